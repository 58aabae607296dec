# Tested documentation (label `docs`): every ```console block of README.md and docs/*.md is run
# and its output compared (tests/docs/console_blocks.cpp); every ```cpp block is a complete
# translation unit compiled as part of the build, so a page that stops compiling fails the build.
add_executable(shadowproof_console_blocks ${CMAKE_CURRENT_LIST_DIR}/console_blocks.cpp)
shadowproof_warnings(shadowproof_console_blocks)

file(GLOB shadowproof_doc_pages CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md)
list(PREPEND shadowproof_doc_pages ${PROJECT_SOURCE_DIR}/README.md)
set(shadowproof_snippets "")
foreach(page ${shadowproof_doc_pages})
  file(RELATIVE_PATH rel ${PROJECT_SOURCE_DIR} ${page})
  string(MAKE_C_IDENTIFIER "${rel}" slug)
  file(READ ${page} text)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${page})
  # Console blocks: one test per page that has any.
  if(text MATCHES "```console\n")
    add_test(NAME "docs: ${rel} shows what the commands print"
      COMMAND shadowproof_console_blocks ${page} ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR}
              ${CMAKE_CURRENT_BINARY_DIR}/docs-scratch/${slug})
    set_tests_properties("docs: ${rel} shows what the commands print" PROPERTIES LABELS docs TIMEOUT 600)
  endif()
  # C++ blocks: extracted at configure time into the build tree.
  set(index 0)
  while(text MATCHES "```cpp\n")
    string(FIND "${text}" "```cpp\n" start)
    math(EXPR start "${start} + 7")
    string(SUBSTRING "${text}" ${start} -1 text)
    string(FIND "${text}" "```" stop)
    string(SUBSTRING "${text}" 0 ${stop} code)
    math(EXPR stop "${stop} + 3")
    string(SUBSTRING "${text}" ${stop} -1 text)
    math(EXPR index "${index} + 1")
    set(snippet ${CMAKE_CURRENT_BINARY_DIR}/docs-snippets/${slug}_${index}.cpp)
    file(CONFIGURE OUTPUT ${snippet} CONTENT "// ${rel}, C++ block ${index}\n${code}" @ONLY)
    list(APPEND shadowproof_snippets ${snippet})
  endwhile()
endforeach()
if(shadowproof_snippets)
  add_library(shadowproof_doc_snippets OBJECT ${shadowproof_snippets})
  target_link_libraries(shadowproof_doc_snippets PRIVATE shadowproof shadowproof_impls)
  if(TARGET Catch2::Catch2)
    target_link_libraries(shadowproof_doc_snippets PRIVATE Catch2::Catch2)
  endif()
endif()
