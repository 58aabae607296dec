# Sharded runs merged give the unsharded report byte for byte, text and JSON, whatever the
# order of the shard files and whatever the shard count (a shard may be empty).
# -DEXE=... -DWORK=dir -DDATA=tests/data/verify
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
# Words are separated by '|' (a ';' would flatten the list of runs).
set(runs
  "check|--impl|seed003-ray-f32|--cases|300|--seed|5"
  "check|--impl|all|--op|shadow-matrix|--cases|60|--seed|2|--max-ulps|4"
  "grade|${DATA}/shard_cases.jsonl|${DATA}/shard_outputs.jsonl"
  "fuzz|--impl|seed001-shader-f32|--cases|400|--seed|1")
# For each run, the shard counts and the order the files are given to merge (a permutation):
# 1 shard, 3 shards, and 7 shards where a shard may hold a single case.
set(splits_0 "1:0" "3:2,0,1" "7:6,3,0,5,1,4,2")
set(splits_1 "3:2,0,1")
set(splits_2 "1:0" "3:2,0,1" "7:6,3,0,5,1,4,2")
set(splits_3 "3:1,2,0" "7:6,3,0,5,1,4,2")
set(k 0)
foreach(words IN LISTS runs)
  string(REPLACE "|" ";" cmd "${words}")
  string(REPLACE "|" " " shown "${words}")
  execute_process(COMMAND ${EXE} ${cmd} OUTPUT_FILE ${WORK}/${k}-whole.txt ERROR_VARIABLE err RESULT_VARIABLE whole_code)
  execute_process(COMMAND ${EXE} ${cmd} --json OUTPUT_FILE ${WORK}/${k}-whole.json ERROR_QUIET)
  if(whole_code GREATER 1)
    message(FATAL_ERROR "'${shown}' failed with ${whole_code}: ${err}")
  endif()
  # check's rate in cases per second is a measurement of the live run, which a merge of shards
  # does not have: the summary line is compared without it.
  file(READ ${WORK}/${k}-whole.txt whole_text)
  string(REGEX REPLACE "; graded at [^\n]* cases/s\\." "." whole_text "${whole_text}")
  file(WRITE ${WORK}/${k}-whole.txt "${whole_text}")
  file(SIZE ${WORK}/${k}-whole.txt size)
  if(size EQUAL 0)
    message(FATAL_ERROR "'${shown}' printed nothing")
  endif()
  foreach(split IN LISTS splits_${k})
    string(REPLACE ":" ";" parts "${split}")
    list(GET parts 0 n)
    list(GET parts 1 order)
    string(REPLACE "," ";" order "${order}")
    set(files "")
    foreach(i IN LISTS order)
      set(file ${WORK}/${k}-shard-${i}-of-${n}.json)
      execute_process(COMMAND ${EXE} ${cmd} --shard ${i}/${n} --json OUTPUT_FILE ${file} ERROR_VARIABLE err
                      RESULT_VARIABLE code)
      if(code GREATER 1)
        message(FATAL_ERROR "'${shown} --shard ${i}/${n} --json' failed with ${code}: ${err}")
      endif()
      list(APPEND files ${file})
    endforeach()
    foreach(form txt json)
      set(flag "")
      if(form STREQUAL "json")
        set(flag --json)
      endif()
      execute_process(COMMAND ${EXE} merge ${flag} ${files} OUTPUT_FILE ${WORK}/${k}-merged-${n}.${form}
                      ERROR_VARIABLE err RESULT_VARIABLE code)
      if(NOT code EQUAL whole_code)
        message(FATAL_ERROR "merge of '${shown}' in ${n} shards exited with ${code}, the whole run with ${whole_code}: ${err}")
      endif()
      file(SHA256 ${WORK}/${k}-whole.${form} a)
      file(SHA256 ${WORK}/${k}-merged-${n}.${form} b)
      if(NOT a STREQUAL b)
        message(FATAL_ERROR "merge of '${shown}' in ${n} shards (${form}) differs from the unsharded run: "
                            "compare ${WORK}/${k}-whole.${form} and ${WORK}/${k}-merged-${n}.${form}")
      endif()
    endforeach()
  endforeach()
  message(STATUS "'${shown}': shards ${splits_${k}} merge to the unsharded report")
  math(EXPR k "${k} + 1")
endforeach()
