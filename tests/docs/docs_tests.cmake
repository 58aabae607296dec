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

# Links: every relative link of the pages names an existing file, and an existing heading when it
# has an #anchor. The checker itself must report a page with broken links.
add_executable(shadowproof_page_links ${CMAKE_CURRENT_LIST_DIR}/page_links.cpp)
shadowproof_warnings(shadowproof_page_links)
file(GLOB shadowproof_linked_pages CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md ${PROJECT_SOURCE_DIR}/docs/upstream/*.md
     ${PROJECT_SOURCE_DIR}/src/*/README.md ${PROJECT_SOURCE_DIR}/include/shadowproof/README.md)
add_test(NAME "docs: every link of the pages points to an existing page and heading"
  COMMAND shadowproof_page_links ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CONTRIBUTING.md
          ${PROJECT_SOURCE_DIR}/conformance/README.md ${shadowproof_linked_pages})
add_test(NAME "docs: the link checker reports a missing page and a missing heading"
  COMMAND shadowproof_page_links ${CMAKE_CURRENT_LIST_DIR}/data/broken_links.md)
set_tests_properties("docs: every link of the pages points to an existing page and heading" PROPERTIES LABELS docs)
set_tests_properties("docs: the link checker reports a missing page and a missing heading" PROPERTIES LABELS docs
  PASS_REGULAR_EXPRESSION "broken_links.md:4: no such file: no-such-page.md\n.*broken_links.md:4: no such heading: #no-such-heading\n2 broken link\\(s\\)")
