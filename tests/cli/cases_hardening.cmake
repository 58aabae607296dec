# Output discipline: killed runs keep the previous report, the same seed gives the same bytes.
foreach(kind check fuzz)
  add_test(NAME "hardening: a ${kind} run killed midway leaves the previous report intact"
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -DKIND=${kind}
            -DWORK=${CMAKE_CURRENT_BINARY_DIR}/kill_midway_${kind} -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/kill_midway.cmake)
  set_tests_properties("hardening: a ${kind} run killed midway leaves the previous report intact"
    PROPERTIES LABELS "hardening;cli" TIMEOUT 60)
endforeach()

add_test(NAME "hardening: the same seed gives byte-identical output"
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -DWORK=${CMAKE_CURRENT_BINARY_DIR}/same_seed
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/same_seed.cmake)
set_tests_properties("hardening: the same seed gives byte-identical output" PROPERTIES LABELS "hardening;cli" TIMEOUT 120 COST 25)
