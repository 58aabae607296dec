# Warnings are PRIVATE options of our own targets, never global flags.
function(shadowproof_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
    # GCC 12 reports false positives inside CGAL and gmpxx expression templates.
    $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
endfunction()
