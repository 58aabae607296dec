# --version, help, the man page and the bash completion, all generated from the command-line
# definitions; the committed man page and completion script must equal what the binary prints.

shadowproof_cli_case(NAME "--version prints the project version"
  ARGS --version EXPECT_CODE 0 STDOUT_REGEX "^shadowproof ${PROJECT_VERSION}\n$")
shadowproof_cli_case(NAME "help of a nested command lists its options"
  ARGS help explain shadow EXPECT_CODE 0
  STDOUT_REGEX "^derive the shadow matrix.*Usage: shadowproof explain shadow \\[OPTIONS\\].*--plane TEXT REQUIRED.*--light TEXT REQUIRED.*--point")
shadowproof_cli_case(NAME "help alone is the overview of every command"
  ARGS help EXPECT_CODE 0
  STDOUT_REGEX "Usage: shadowproof \\[OPTIONS\\] SUBCOMMAND.*--version.*Subcommands:.*explain.*shadow")
shadowproof_cli_case(NAME "help --all covers every command"
  ARGS help --all EXPECT_CODE 0
  STDOUT_REGEX "Subcommands:.*Usage: shadowproof explain shadow.*--plane.*Usage: shadowproof help.*--bash-completion.*Usage: shadowproof project.*--convention")
shadowproof_cli_case(NAME "help of an unknown command names the commands there are"
  ARGS help explain shade EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "^shadowproof: \\[shadowproof\\.cli\\.unknown_command\\] no command 'shadowproof explain shade' \\(one of: change-of-basis, games101, normal-matrix, oblique, ortho, perspective, reflect, reflect-frames, shadow\\)\n$")

foreach(kind man bash-completion)
  set(committed ${PROJECT_SOURCE_DIR}/src/cli/shadowproof.1)
  if(kind STREQUAL "bash-completion")
    set(committed ${PROJECT_SOURCE_DIR}/src/cli/shadowproof.bash)
  endif()
  add_test(NAME "cli: help --${kind} equals the committed ${kind} file"
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -DKIND=${kind} -DCOMMITTED=${committed}
      -P ${CMAKE_CURRENT_LIST_DIR}/generated_in_sync.cmake)
  set_tests_properties("cli: help --${kind} equals the committed ${kind} file" PROPERTIES LABELS cli)
endforeach()
add_test(NAME "cli: bash completes commands, subcommands and options"
  COMMAND ${CMAKE_COMMAND} -DSCRIPT=${PROJECT_SOURCE_DIR}/src/cli/shadowproof.bash
    -P ${CMAKE_CURRENT_LIST_DIR}/bash_completion.cmake)
set_tests_properties("cli: bash completes commands, subcommands and options" PROPERTIES LABELS cli)

# Rewrites the committed files from the binary (after changing an option or a description).
add_custom_target(update_cli_reference
  COMMAND $<TARGET_FILE:shadowproof_cli> help --man > ${PROJECT_SOURCE_DIR}/src/cli/shadowproof.1
  COMMAND $<TARGET_FILE:shadowproof_cli> help --bash-completion > ${PROJECT_SOURCE_DIR}/src/cli/shadowproof.bash
  DEPENDS shadowproof_cli VERBATIM)
shadowproof_cli_case(NAME "a malformed option points at its subcommand's help"
  ARGS check --cases x EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "^shadowproof: Could not convert: --cases = x\n\\(run 'shadowproof check --help' for usage\\)\n$")
shadowproof_cli_case(NAME "a missing option of a nested subcommand points at that subcommand's help"
  ARGS explain shadow EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\(run 'shadowproof explain shadow --help' for usage\\)\n$")
