# The HTML report, as a browser reads it: headless Chromium loads the page written by check,
# grade or fuzz and dumps the DOM it built; the test looks for what a reader looks for (each
# implementation with its verdict, one scatter plot each, the reproducer commands, the declared
# conventions) and for the absence of anything fetched from elsewhere. Then it renders a PNG.
# -DEXE=... -DWORK=dir -DKIND=check|grade|fuzz -DDATA=tests/data/verify
# Skipped (ctest SKIP_REGULAR_EXPRESSION) when no Chromium is installed.
find_program(CHROMIUM NAMES chromium chromium-browser google-chrome-stable google-chrome)
if(NOT CHROMIUM)
  message("SKIPPED: no headless Chromium (Debian: apt-get install chromium); the HTML report is not rendered")
  return()
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/profile)
set(page ${WORK}/report.html)
if(KIND STREQUAL "check")
  set(args check --impl all --op shadow-point --cases 240 --seed 1 --html ${page})
  # Every shadow-point implementation must have its section.
  execute_process(COMMAND ${EXE} check --list OUTPUT_VARIABLE names)
  string(REGEX MATCHALL "[^\n]+" names "${names}")
  set(expected_names "")
  foreach(n IN LISTS names)
    if(n MATCHES "(seed001-shader|seed003-ray|homogeneous-image)")
      list(APPEND expected_names ${n})
    endif()
  endforeach()
  set(expected "shadowproof check" "Conventions declared" "Worst cases" "shadowproof shadow")
elseif(KIND STREQUAL "grade")
  set(args grade ${DATA}/shard_cases.jsonl ${DATA}/shard_outputs.jsonl --html ${page})
  set(expected_names shard_outputs)
  set(expected "shadowproof grade" "Conventions declared" "Worst cases" "row-major")
else()
  set(args fuzz --impl seed001-shader-f32 --cases 300 --seed 1 --html ${page})
  set(expected_names seed001-shader-f32)
  set(expected "shadowproof fuzz" "nonfinite" "light_parallel" "shrunk:" "Conventions declared")
endif()
execute_process(COMMAND ${EXE} ${args} RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(code GREATER 1 OR NOT EXISTS ${page})
  message(FATAL_ERROR "${args} failed with ${code}: ${err}")
endif()

# Self-contained: nothing for the browser to fetch.
file(READ ${page} html)
foreach(fetch "<script" "<link" "<img" "<iframe" "@import" "url(" " src=" "href=\"http" "href='http")
  string(FIND "${html}" "${fetch}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "the page refers to an external resource ('${fetch}' at ${at})")
  endif()
endforeach()

set(flags --headless --no-sandbox --disable-gpu --disable-background-networking --disable-component-update
          --disable-sync --no-first-run --disable-extensions --user-data-dir=${WORK}/profile)
execute_process(COMMAND ${CHROMIUM} ${flags} --dump-dom file://${page}
                OUTPUT_VARIABLE dom ERROR_VARIABLE chromium_err RESULT_VARIABLE code TIMEOUT 120)
if(NOT code EQUAL 0 OR NOT dom MATCHES "</html>")
  message(FATAL_ERROR "Chromium could not load the page (${code}): ${chromium_err}")
endif()
file(WRITE ${WORK}/dom.html "${dom}")

foreach(name IN LISTS expected_names)
  if(NOT dom MATCHES "<h2>[^<]*${name}")
    message(FATAL_ERROR "no section for ${name} in the rendered page")
  endif()
endforeach()
foreach(text IN LISTS expected)
  string(FIND "${dom}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the rendered page does not show '${text}'")
  endif()
endforeach()
# One parsed SVG plot per section, with points in it; a verdict badge per section.
string(REGEX MATCHALL "<section" sections "${dom}")
string(REGEX MATCHALL "<svg " plots "${dom}")
string(REGEX MATCHALL "<h2>[^<]*<span class=\"badge [a-z]+\">[a-z]+</span>" badges "${dom}")
list(LENGTH sections n_sections)
list(LENGTH plots n_plots)
list(LENGTH badges n_badges)
list(LENGTH expected_names n_names)
if(n_sections LESS n_names OR NOT n_plots EQUAL n_sections OR NOT n_badges EQUAL n_sections)
  message(FATAL_ERROR "${n_sections} sections, ${n_plots} plots, ${n_badges} verdicts (expected one of each per "
                      "implementation, at least ${n_names})")
endif()
if(NOT dom MATCHES "<circle ")
  message(FATAL_ERROR "the plots have no points")
endif()
# Reproducers sit in copyable blocks.
if(NOT dom MATCHES "<pre class=\"repro\">shadowproof [a-z-]+ ")
  message(FATAL_ERROR "no reproducer command in the page")
endif()

execute_process(COMMAND ${CHROMIUM} ${flags} --hide-scrollbars --window-size=1200,1800
                        --screenshot=${WORK}/report.png file://${page}
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET TIMEOUT 120)
file(SIZE ${WORK}/report.png png_size)
if(NOT code EQUAL 0 OR png_size LESS 20000)
  message(FATAL_ERROR "no screenshot (${code}, ${png_size} bytes)")
endif()
message(STATUS "${n_sections} sections rendered; screenshot ${WORK}/report.png")
