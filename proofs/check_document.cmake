# Regenerates docs/derivations.md into the build tree and compares it with the committed copy.
# -DRUNNER=<shadowproof_proofs> -DCOMMITTED=<source copy> -DFRESH=<build copy>
get_filename_component(fresh_dir ${FRESH} DIRECTORY)
file(MAKE_DIRECTORY ${fresh_dir})
execute_process(COMMAND ${RUNNER} markdown ${FRESH} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "writing the document failed (exit ${code}):\n${out}${err}")
endif()
if(NOT EXISTS ${COMMITTED})
  message(FATAL_ERROR "${COMMITTED} is missing; run: cmake --build <build dir> --target update_derivations_doc")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${COMMITTED} ${FRESH} RESULT_VARIABLE differ)
if(NOT differ EQUAL 0)
  message(FATAL_ERROR "docs/derivations.md is out of date with proofs/ (fresh copy: ${FRESH}); "
                      "run: cmake --build <build dir> --target update_derivations_doc")
endif()
