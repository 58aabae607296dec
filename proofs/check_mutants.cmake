# Runs the proofs built against the headers with switchable changed formulas (mutants.cmake):
# with no change switched on every proof must pass (the copy is the library), and with each change
# switched on alone, its derivation must fail at the step named for it.
# -DRUNNER=<shadowproof_proofs_mutant> -DEXPECTED="index:slug:step;..."
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=SHADOWPROOF_MUTANT ${RUNNER} check
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "the proofs fail against the copy of the headers with no change switched on:\n${out}${err}")
endif()
set(problems "")
foreach(entry ${EXPECTED})
  string(REGEX MATCH "^([0-9]+):([^:]+):(.*)$" matched "${entry}")
  set(index ${CMAKE_MATCH_1})
  set(slug ${CMAKE_MATCH_2})
  set(step "${CMAKE_MATCH_3}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E env SHADOWPROOF_MUTANT=${index} ${RUNNER} check ${slug}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REGEX MATCHALL "  FAIL [^\n]*" failures "${out}")
  string(FIND "${failures}" "${step}" at)
  if(NOT code EQUAL 1 OR at EQUAL -1)
    string(APPEND problems "change ${index} (${slug}): exit ${code}, the step '${step}' did not fail:\n${out}${err}\n")
  endif()
endforeach()
if(NOT problems STREQUAL "")
  message(FATAL_ERROR "a changed formula was not caught by its proof:\n${problems}")
endif()
list(LENGTH EXPECTED count)
message(STATUS "${count} changed formulas, each caught by its proof on its own")
