# Runs each seeded command twice (and once with another seed) and compares the bytes.
# -DEXE=... -DWORK=dir
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
# Words are separated by '|' here (a ';' would flatten the list of commands).
set(commands
  "cases|--op|shadow-point|--type|f32|--count|300|--seed|7"
  "check|--impl|all|--cases|40|--seed|7|--json"
  "fuzz|--impl|seed003-ray-f32|--cases|1000|--seed|7|--json")
set(k 0)
foreach(words IN LISTS commands)
  string(REPLACE "|" ";" cmd "${words}")
  string(REPLACE "|" " " shown "${words}")
  set(outputs "")
  foreach(run a b)
    execute_process(COMMAND ${EXE} ${cmd} OUTPUT_FILE ${WORK}/${k}-${run}.out ERROR_QUIET RESULT_VARIABLE code)
    if(code GREATER 1)
      message(FATAL_ERROR "'${shown}' failed with ${code}")
    endif()
  endforeach()
  file(SHA256 ${WORK}/${k}-a.out a)
  file(SHA256 ${WORK}/${k}-b.out b)
  file(SIZE ${WORK}/${k}-a.out size)
  if(NOT a STREQUAL b OR size EQUAL 0)
    message(FATAL_ERROR "'${shown}' printed different bytes for the same seed (or nothing)")
  endif()
  # A different seed must change the output, or the comparison above proves nothing.
  string(REGEX REPLACE ";7$|;7;" ";8;" other "${cmd};")
  execute_process(COMMAND ${EXE} ${other} OUTPUT_FILE ${WORK}/${k}-c.out ERROR_QUIET)
  file(SHA256 ${WORK}/${k}-c.out c)
  if(c STREQUAL a)
    message(FATAL_ERROR "'${shown}' printed the same bytes for seeds 7 and 8")
  endif()
  math(EXPR k "${k} + 1")
endforeach()
