# Installs shadowproof from the build tree into a fresh prefix, builds this example against it
# (find_package(shadowproof 0.2 REQUIRED COMPONENTS testing)), runs its Catch2 and GoogleTest
# programs, which must pass, then runs their planted-defect tests, which must fail with the
# message that names the entry, the exact value, the ulps and the reproducer.
# -DSOURCE_DIR=<repo> -DBINARY_DIR=<build> -DWORK_DIR=<dir> [-DCONSUMER_FLAGS=<sanitizer flags>]
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${prefix} RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
# Built without optimisation: under the sanitizers, an optimised Catch2 main with the exact
# oracle's templates takes minutes to compile, and what is tested is the package, not speed.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/unit_tests -B ${WORK_DIR}/build
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=
  "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_FLAGS}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "configuring the example failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "building the example failed:\n${out}\n${err}")
endif()

# The engine's own tests pass.
foreach(program engine_catch2_tests engine_gtest_tests)
  execute_process(COMMAND ${WORK_DIR}/build/${program} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc)
    message(FATAL_ERROR "${program} failed (${rc}):\n${out}\n${err}")
  endif()
endforeach()

# The planted defect fails in both frameworks, and the failure says where and by how much:
# on the floor y = 1 under the lamp (2, 5, 1), P·L = 4 and M(3,3) = 4 − 1·(−1) = 5; the defect
# gives 4, 2^21 floats below 5 (a float step is 2^-21 in [4, 8)).
set(entry_line "  (3,3): got 4 (0x1p+2), exact 5, correctly rounded 5 (0x1.4p+2): 2097152 ulps")
set(reproducer_line "  exact answer: shadowproof shadow --plane 0x0p+0,0x1p+0,0x0p+0,-0x1p+0 --light 0x1p+1,0x1.4p+2,0x1p+0,0x1p+0")
function(expect_planted_failure program)
  execute_process(COMMAND ${WORK_DIR}/build/${program} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc)
    message(FATAL_ERROR "${program}'s planted-defect tests passed; they must fail:\n${out}")
  endif()
  foreach(expected "${entry_line}" "${reproducer_line}" "shadow-matrix (f32): " " of 300 cases fail (ulps>"
                   "worst case, shrunk from ")
    string(FIND "${out}" "${expected}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${program}'s planted-defect output lacks '${expected}':\n${out}\n${err}")
    endif()
  endforeach()
  message(STATUS "${program} on the planted defect:\n${out}")
endfunction()
expect_planted_failure(engine_catch2_tests "[planted]")
expect_planted_failure(engine_gtest_tests --gtest_also_run_disabled_tests "--gtest_filter=*DISABLED_*")
