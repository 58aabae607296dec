# SHADOWPROOF_SANITIZE="address;undefined" instruments every target of this project (the whole
# test suite runs under it in the asan-ubsan preset). UBSan findings abort: a report is a failure.
if(SHADOWPROOF_SANITIZE)
  list(JOIN SHADOWPROOF_SANITIZE "," shadowproof_sanitizers)
  add_compile_options(-fsanitize=${shadowproof_sanitizers} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${shadowproof_sanitizers} -fno-sanitize-recover=all)
  # Executables link at a fixed address: an instrumented position-independent CLI carries about
  # two million relative relocations that the loader applies at every start (0.2 s of CPU and
  # 45 MB of touched pages per process), and the test suite starts the CLI and the test programs
  # over a thousand times. The instrumentation is the same either way.
  add_link_options($<$<STREQUAL:$<TARGET_PROPERTY:TYPE>,EXECUTABLE>:-no-pie>)
  # gold links an instrumented executable in less than half the CPU time of the default linker
  # (1.6 s against 3.6 s for the CLI), over thirty times per build.
  include(CheckLinkerFlag)
  check_linker_flag(CXX -fuse-ld=gold SHADOWPROOF_LINKER_HAS_GOLD)
  if(SHADOWPROOF_LINKER_HAS_GOLD)
    add_link_options(-fuse-ld=gold)
  endif()
endif()
