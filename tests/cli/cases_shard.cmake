# --shard and merge: sharded runs merge to the unsharded report exactly (shard_merge.cmake), a
# bad shard specification and shards that do not make one run are refused with exit 2.
add_test(NAME "cli: shards of check, grade and fuzz merge to the unsharded report byte for byte"
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -DWORK=${CMAKE_CURRENT_BINARY_DIR}/shard_merge
          -DDATA=${CMAKE_CURRENT_SOURCE_DIR}/data/verify -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/shard_merge.cmake)
set_tests_properties("cli: shards of check, grade and fuzz merge to the unsharded report byte for byte"
  PROPERTIES LABELS cli TIMEOUT 600 COST 40)

foreach(spec "3/3" "1/0" "a/4" "2" "1/2/3" "0/1048577" " 1/2")
  shadowproof_cli_case(NAME "check refuses --shard '${spec}'"
    ARGS check --impl seed003-ray-f32 --cases 10 --shard ${spec} EXPECT_CODE 2
    STDERR_REGEX "shadowproof[.]shard[.]spec[]] bad --shard '${spec}': ")
endforeach()
shadowproof_cli_case(NAME "grade refuses a bad --shard"
  ARGS grade cases.jsonl outputs.jsonl --shard 4/4 EXPECT_CODE 2
  STDERR_REGEX "shard[.]spec[]] bad --shard '4/4': the shard index i runs from 0 to N-1 = 3")
shadowproof_cli_case(NAME "fuzz refuses a bad --shard"
  ARGS fuzz --impl seed003-ray-f32 --cases 10 --shard 0/0 EXPECT_CODE 2
  STDERR_REGEX "shard[.]spec[]] bad --shard '0/0': the shard count N must be at least 1")
shadowproof_cli_case(NAME "merge needs shard reports, not other JSON"
  ARGS merge ${CMAKE_CURRENT_SOURCE_DIR}/data/verify/shard_cases.jsonl EXPECT_CODE 2
  STDERR_REGEX "merge[.]input[]] .*shard_cases.jsonl is not a JSON report")
shadowproof_cli_case(NAME "merge refuses a file that does not exist"
  ARGS merge no-such-shard.json EXPECT_CODE 2
  STDERR_REGEX "merge[.]input[]] cannot read the shard report 'no-such-shard.json'")

# Missing, duplicated and foreign shards, on reports written by real runs.
add_test(NAME "cli: merge refuses missing, duplicated and foreign shards"
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -DWORK=${CMAKE_CURRENT_BINARY_DIR}/shard_errors
          -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/shard_errors.cmake)
set_tests_properties("cli: merge refuses missing, duplicated and foreign shards" PROPERTIES LABELS cli)

# The HTML report of each command, loaded by headless Chromium (skipped without one).
foreach(kind check grade fuzz)
  add_test(NAME "cli: ${kind} --html writes a self-contained page Chromium renders"
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -DWORK=${CMAKE_CURRENT_BINARY_DIR}/html_${kind}
            -DKIND=${kind} -DDATA=${CMAKE_CURRENT_SOURCE_DIR}/data/verify -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/html_report.cmake)
  set_tests_properties("cli: ${kind} --html writes a self-contained page Chromium renders" PROPERTIES
    LABELS cli TIMEOUT 300 SKIP_REGULAR_EXPRESSION "SKIPPED: no headless Chromium")
endforeach()
