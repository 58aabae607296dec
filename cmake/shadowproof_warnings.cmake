# Warnings are PRIVATE options of our own targets, never global flags.
function(shadowproof_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wno-maybe-uninitialized)
endfunction()
