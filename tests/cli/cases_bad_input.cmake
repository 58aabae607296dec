# One ctest per file in tests/data/bad_input/ that has a `cli:` line (see its README).
file(GLOB SHADOWPROOF_BAD_INPUT_CASES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/data/bad_input/*.txt)
foreach(case_file ${SHADOWPROOF_BAD_INPUT_CASES})
  file(STRINGS ${case_file} cli_line REGEX "^cli: ")
  if(NOT cli_line)
    continue()
  endif()
  get_filename_component(case_name ${case_file} NAME_WE)
  add_test(NAME "bad input (cli): ${case_name}"
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -DCASE=${case_file}
            -DDATA=${PROJECT_SOURCE_DIR}/tests/data/bad_input -DTMP=${CMAKE_CURRENT_BINARY_DIR}/bad_input_tmp/${case_name}
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/run_bad_input.cmake)
  set_tests_properties("bad input (cli): ${case_name}" PROPERTIES LABELS "bad_input;cli" TIMEOUT 60)
endforeach()
