# SHADOWPROOF_SANITIZE="address;undefined" instruments every target of this project (the whole
# test suite runs under it in the asan-ubsan preset). UBSan findings abort: a report is a failure.
if(SHADOWPROOF_SANITIZE)
  list(JOIN SHADOWPROOF_SANITIZE "," shadowproof_sanitizers)
  add_compile_options(-fsanitize=${shadowproof_sanitizers} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${shadowproof_sanitizers} -fno-sanitize-recover=all)
endif()
