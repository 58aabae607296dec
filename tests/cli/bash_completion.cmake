# Sources the completion script in bash and completes a few command lines; expected words come
# from the command table (README): `sha<TAB>` is shadow, `explain <TAB>` lists its topics.
# -DSCRIPT=<src/cli/shadowproof.bash>
find_program(BASH bash REQUIRED)
function(complete line expected)
  # COMP_WORDS are the words of `line` plus the word being completed (the last one, maybe "").
  execute_process(COMMAND ${BASH} -c "source '${SCRIPT}'; COMP_WORDS=(${line}); COMP_CWORD=$((\${#COMP_WORDS[@]} - 1)); _shadowproof; echo \"\${COMPREPLY[*]}\""
    OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  string(STRIP "${out}" out)
  if(rc OR NOT out STREQUAL expected)
    message(FATAL_ERROR "completing '${line}' gave '${out}' (exit ${rc}), expected '${expected}'")
  endif()
endfunction()
complete("shadowproof sha" "shadow")
complete("shadowproof explain ''" "--help -h change-of-basis games101 normal-matrix oblique ortho perspective reflect reflect-frames shadow")
complete("shadowproof explain shadow --p" "--plane --point")
complete("shadowproof --max-bits 64 ref" "reflect")
complete("shadowproof --vers" "--version")
complete("shadowproof shadow --plane 0,1,0,0 --li" "--light")
