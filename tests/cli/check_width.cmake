# Runs a report command and checks that no line of its output is wider than WIDTH columns.
# -DEXE=<shadowproof> -DARGS="check;--impl;all;..." -DWIDTH=100
string(REPLACE "\\;" ";" ARGS "${ARGS}")
execute_process(COMMAND ${EXE} ${ARGS} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
if(code GREATER 1)
  message(FATAL_ERROR "report failed (${code}): ${err}")
endif()
# One column per character: ';', '[', ']' and '\' would confuse CMake's list splitting.
string(REGEX REPLACE "[][;\\]" "x" out "${out}")
string(REPLACE "\n" ";" lines "${out}")
set(n 0)
foreach(line IN LISTS lines)
  math(EXPR n "${n} + 1")
  string(LENGTH "${line}" length)  # bytes: the reports are ASCII
  if(length GREATER WIDTH)
    message(FATAL_ERROR "line ${n} has ${length} columns (at most ${WIDTH}):\n${line}")
  endif()
endforeach()
message(STATUS "${n} lines, none wider than ${WIDTH}")
