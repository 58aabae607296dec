# --jobs: the grading commands give the same report on any number of threads.
if(TARGET shadowproof_impls)
  add_test(NAME "jobs: check, grade and fuzz print the same bytes with --jobs 1, 2 and 3"
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -DWORK=${CMAKE_CURRENT_BINARY_DIR}/same_jobs
            -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/same_jobs.cmake)
  set_tests_properties("jobs: check, grade and fuzz print the same bytes with --jobs 1, 2 and 3"
    PROPERTIES LABELS "hardening;cli" TIMEOUT 300 COST 30)
endif()
shadowproof_cli_case(NAME "check --jobs 0 is refused"
  ARGS check --impl all --jobs 0 EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "--jobs: Value 0 not in range 1 to 256")
shadowproof_cli_case(NAME "fuzz --jobs above the cap is refused"
  ARGS fuzz --impl seed003-ray-f32 --cases 10 --jobs 257 EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "--jobs: Value 257 not in range 1 to 256")
