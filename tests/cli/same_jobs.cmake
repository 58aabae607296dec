# Runs check, grade and fuzz with --jobs 1, 2 and 3 and compares the bytes: the threads share
# the work, never the result. The one figure that is a measurement, check's throughput
# ("… cases/s"), is replaced by a mark before the text reports are compared; the JSON
# documents carry no timing and are compared as printed. -DEXE=... -DWORK=dir
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# grade needs outputs: the point's own coordinates as the "shadow" of each case. A wrong
# answer on purpose, so the grades differ from case to case (ulps, bits, worst cases).
execute_process(COMMAND ${EXE} cases --op shadow-point --type f32 --count 1500 --seed 5
                OUTPUT_FILE ${WORK}/cases.jsonl RESULT_VARIABLE code)
if(code)
  message(FATAL_ERROR "shadowproof cases failed with ${code}")
endif()
file(STRINGS ${WORK}/cases.jsonl lines)
set(outputs "")
foreach(line IN LISTS lines)
  if(NOT line MATCHES "\"id\": ([0-9]+),.*\"point\": \\[([^]]*)\\]")
    message(FATAL_ERROR "unexpected case line: ${line}")
  endif()
  string(APPEND outputs "{\"id\": ${CMAKE_MATCH_1}, \"output\": [${CMAKE_MATCH_2}]}\n")
endforeach()
file(WRITE ${WORK}/outputs.jsonl "${outputs}")

# Words are separated by '|' here (a ';' would flatten the list of commands). Each command
# grades more cases per implementation than one thread's slice (256 for check and grade, 64 for
# fuzz), so every --jobs count really splits the work; with 4,096 cases per implementation,
# check's threads take whole implementations, costliest first (--jobs 2).
set(commands
  "check|--impl|all|--op|shadow-point|--cases|600|--seed|7"
  "check|--impl|all|--op|shadow-point|--cases|600|--seed|7|--json"
  "check|--impl|all|--op|ortho|--cases|4096|--seed|7"
  "grade|${WORK}/cases.jsonl|${WORK}/outputs.jsonl"
  "grade|${WORK}/cases.jsonl|${WORK}/outputs.jsonl|--json"
  "fuzz|--impl|seed003-ray-f32|--cases|3000|--seed|7"
  "fuzz|--impl|seed003-ray-f32|--cases|3000|--seed|7|--json")
set(k 0)
foreach(words IN LISTS commands)
  string(REPLACE "|" ";" cmd "${words}")
  string(REPLACE "|" " " shown "${words}")
  foreach(jobs 1 2 3)
    execute_process(COMMAND ${EXE} ${cmd} --jobs ${jobs} OUTPUT_VARIABLE out ERROR_QUIET RESULT_VARIABLE code)
    if(NOT code MATCHES "^[01]$")
      message(FATAL_ERROR "'${shown} --jobs ${jobs}' failed with ${code}")
    endif()
    string(REGEX REPLACE "[0-9.e+]+ ([kMG] )?cases/s" "<throughput>" out "${out}")
    file(WRITE ${WORK}/${k}-${jobs}.out "${out}")
    file(SHA256 ${WORK}/${k}-${jobs}.out hash_${jobs})
  endforeach()
  file(SIZE ${WORK}/${k}-1.out size)
  if(size LESS 200)
    message(FATAL_ERROR "'${shown}' printed almost nothing: the comparison would prove nothing")
  endif()
  foreach(jobs 2 3)
    if(NOT hash_${jobs} STREQUAL hash_1)
      message(FATAL_ERROR "'${shown}' printed different bytes with --jobs ${jobs} than with --jobs 1 "
                          "(${WORK}/${k}-${jobs}.out vs ${WORK}/${k}-1.out)")
    endif()
  endforeach()
  math(EXPR k "${k} + 1")
endforeach()
