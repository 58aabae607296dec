# Fails when `shadowproof help --KIND` differs from the committed file (rebuild the target
# update_cli_reference to rewrite it). -DEXE=... -DKIND=man|bash-completion -DCOMMITTED=<file>
execute_process(COMMAND ${EXE} help --${KIND} OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "shadowproof help --${KIND} failed (${rc})")
endif()
file(READ ${COMMITTED} committed)
if(NOT generated STREQUAL committed)
  message(FATAL_ERROR "${COMMITTED} is out of date with the command-line definitions: "
                      "cmake --build <build> --target update_cli_reference")
endif()
