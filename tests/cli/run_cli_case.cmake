# Runs one CLI case and checks its exit code and output.
# -DEXE=... -DARGS="a;b;c" -DEXPECT_CODE=N [-DSTDOUT_REGEX=...] [-DSTDERR_REGEX=...]
# [-DSTDOUT_EMPTY=ON] [-DWORKING_DIRECTORY=...]
if(NOT DEFINED WORKING_DIRECTORY)
  set(WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endif()
foreach(var ARGS STDOUT_REGEX STDERR_REGEX)
  if(DEFINED ${var})
    string(REPLACE "<lsq>" "[" ${var} "${${var}}")
    string(REPLACE "<rsq>" "]" ${var} "${${var}}")
  endif()
endforeach()
string(REPLACE "\\;" ";" ARGS "${ARGS}")
execute_process(COMMAND ${EXE} ${ARGS}
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
  WORKING_DIRECTORY ${WORKING_DIRECTORY} TIMEOUT 120)
if(NOT "${code}" STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECT_CODE}\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(DEFINED STDOUT_REGEX AND NOT out MATCHES "${STDOUT_REGEX}")
  message(FATAL_ERROR "stdout does not match '${STDOUT_REGEX}'\nstdout:\n${out}\nstderr:\n${err}")
endif()
if(DEFINED STDERR_REGEX AND NOT err MATCHES "${STDERR_REGEX}")
  message(FATAL_ERROR "stderr does not match '${STDERR_REGEX}'\nstderr:\n${err}")
endif()
if(STDOUT_EMPTY AND NOT out STREQUAL "")
  message(FATAL_ERROR "stdout should be empty on error, got:\n${out}")
endif()
