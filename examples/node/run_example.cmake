# End-to-end run of the node example: shadowproof cases -> node -> shadowproof grade.
# -DSHADOWPROOF=<exe> -DNODE=<node> -DSCRIPT=<shadow_matrix.js> -DWORK_DIR=<dir> -DTYPE=f32|f64
file(MAKE_DIRECTORY ${WORK_DIR})
set(cases ${WORK_DIR}/cases_${TYPE}.jsonl)
set(outputs ${WORK_DIR}/outputs_${TYPE}.jsonl)
execute_process(COMMAND ${SHADOWPROOF} cases --op shadow-matrix --type ${TYPE} --count 300 --seed 5
  OUTPUT_FILE ${cases} RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "shadowproof cases failed (${code})")
endif()
execute_process(COMMAND ${NODE} ${SCRIPT} ${cases} OUTPUT_FILE ${outputs} RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "node failed (${code}): ${err}")
endif()
execute_process(COMMAND ${SHADOWPROOF} grade ${cases} ${outputs} --json
  OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "shadowproof grade failed (${code}): ${err}")
endif()
# Every case graded (a missing one would have failed the grade), a verdict for each; regular
# cases are within a few ulps (the JS formula is the float formula; only rounding differs).
foreach(pattern "\"cases\": 300," "\"case_verdicts\": \\[" "\"verdict\": \"(exact|faithful|stable|unstable|range)\"")
  if(NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "grade output lacks ${pattern}:\n${out}")
  endif()
endforeach()
string(REGEX MATCH "\"regular\": {[^}]*\"max_ulps\": ([0-9]+)," regular "${out}")
if(NOT regular OR CMAKE_MATCH_1 GREATER 4096)
  message(FATAL_ERROR "regular cases should be within 4096 ulps:\n${out}")
endif()
message(STATUS "node example graded: regular max ulps ${CMAKE_MATCH_1}")
