# shadowproof check / cases / grade: the grader run through the real executable. Expected
# values come from the hand-derived fixtures in tests/data/verify (see its README).
set(verify_data ${PROJECT_SOURCE_DIR}/tests/data/verify)

# --- check ------------------------------------------------------------------------------------
if(TARGET shadowproof_impls)
  shadowproof_cli_case(NAME "check --list names the seed formulas one per line"
    ARGS check --list EXPECT_CODE 0
    STDOUT_REGEX "(^|\n)seed000-general-f32\n.*(^|\n)seed001-shader-f32\n")
  shadowproof_cli_case(NAME "check prints one row per input class"
    ARGS check --impl seed000-closed-form-f32 --cases 30 EXPECT_CODE 0
    STDOUT_REGEX "seed000-closed-form-f32 +shadow-matrix +regular +10 .*near-degenerate +10 .*degenerate +10 ")
  # An exactly parallel light gives exact zeros that the closed form reproduces exactly.
  shadowproof_cli_case(NAME "check: seed 000's closed form is exact on exactly parallel lights"
    ARGS check --impl seed000-closed-form-f32 --cases 30 --json EXPECT_CODE 0
    STDOUT_REGEX "\"class\": \"degenerate\",[^[]*\"max_ulps\": 0,")
  shadowproof_cli_case(NAME "check --json carries the oracle counters"
    ARGS check --impl reflect-divide-f64 --cases 9 --json EXPECT_CODE 0
    STDOUT_REGEX "\"decided_by_intervals\": [0-9]+,\n *\"fell_back_to_rationals\": [0-9]+")
  shadowproof_cli_case(NAME "check --svg writes the plot"
    ARGS check --impl seed000-general-f32 --cases 30 --svg ${CMAKE_CURRENT_BINARY_DIR}/verify_plot.svg EXPECT_CODE 0
    STDOUT_REGEX "Plot written to .*verify_plot.svg")
  shadowproof_cli_case(NAME "check --list and --op select nothing else"
    ARGS check --impl all --op normal-matrix --cases 6 EXPECT_CODE 0
    STDOUT_REGEX "normal-inverse-transpose-f32")
  if("irrlicht" IN_LIST SHADOWPROOF_ENGINES)
    # Irrlicht drops the plane's D·w from P·L: point lights over y = h ≠ 0 are wrong by far more
    # than 4 ulps, so the threshold fails the run.
    shadowproof_cli_case(NAME "check --max-ulps fails Irrlicht's point-light shadow matrix"
      ARGS check --impl irrlicht-shadow-unit-normal-f32 --cases 60 --max-ulps 4 EXPECT_CODE 1
      STDOUT_REGEX "FAIL: threshold --max-ulps 4 exceeded")
    shadowproof_cli_case(NAME "check --max-ulps passes Irrlicht's orthographic builder at 1 ulp"
      ARGS check --impl irrlicht-ortho-rh-f32 --cases 60 --max-ulps 1 EXPECT_CODE 0
      STDOUT_REGEX "PASS: threshold --max-ulps 1 held")
  endif()
endif()
shadowproof_cli_case(NAME "check rejects an unknown implementation"
  ARGS check --impl no-such-impl EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.verify.unknown_impl\\] no implementation named 'no-such-impl' \\(see --list\\)")
shadowproof_cli_case(NAME "check rejects an unknown operation"
  ARGS check --impl all --op twist EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.verify.unknown_op\\] unknown --op 'twist'")

# --- cases ------------------------------------------------------------------------------------
shadowproof_cli_case(NAME "cases writes the protocol's JSON lines"
  ARGS cases --op shadow-matrix --type f32 --count 2 --seed 7 EXPECT_CODE 0
  STDOUT_REGEX "^{\"id\": 0, \"op\": \"shadow-matrix\", \"type\": \"f32\", \"class\": \"regular\", \"plane\": \\[\"-?0x[^\"]+\", \"[^\"]+\", \"[^\"]+\", \"[^\"]+\"\\], \"light\": \\[[^]]+\\], \"exact\": {\"plane\": \\[[^]]+\\], \"light\": \\[[^]]+\\]}, \"numbers\": {\"plane\": \\[-?[0-9][^]\"]*\\], \"light\": \\[[^]\"]+\\]}}\n{\"id\": 1, [^\n]*\n$")
shadowproof_cli_case(NAME "cases names the point input of shadow-point"
  ARGS cases --op shadow-point --type f64 --count 1 EXPECT_CODE 0
  STDOUT_REGEX "\"point\": \\[")
shadowproof_cli_case(NAME "cases rejects an unknown type"
  ARGS cases --op shadow-matrix --type f16 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.verify.unknown_type\\] unknown --type 'f16'; expected f32 or f64")

# --- grade ------------------------------------------------------------------------------------
shadowproof_cli_case(NAME "grade: the exact matrix is 0 ulps"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_exact.jsonl --json EXPECT_CODE 0
  STDOUT_REGEX "\"cases\": 1,.*\"max_bits\": 0.0,.*\"max_ulps\": 0,")
shadowproof_cli_case(NAME "grade: the float after 2 is 1 ulp and 1 bit"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_one_ulp.jsonl --json EXPECT_CODE 0
  STDOUT_REGEX "\"max_bits\": 1.0,.*\"max_ulps\": 1,.*\"expected\": \"0x1p\\+1\",.*\"got\": \"0x1.000002p\\+1\"")
shadowproof_cli_case(NAME "grade: transposed storage declared column-major is exact"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_transposed.jsonl --layout column-major --json
  EXPECT_CODE 0 STDOUT_REGEX "\"max_ulps\": 0,")
shadowproof_cli_case(NAME "grade: transposed storage undeclared fails the threshold"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_transposed.jsonl --max-ulps 0
  EXPECT_CODE 1 STDOUT_REGEX "FAIL: threshold --max-ulps 0 exceeded")
shadowproof_cli_case(NAME "grade: an image on the wrong side is misclassified"
  ARGS grade ${verify_data}/point_case.jsonl ${verify_data}/point_flipped.jsonl --json EXPECT_CODE 0
  STDOUT_REGEX "\"misclassified\": 1,")
shadowproof_cli_case(NAME "grade rejects an output line of the wrong length"
  ARGS grade ${verify_data}/point_case.jsonl ${verify_data}/ground_exact.jsonl EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.protocol.output\\] line 1: \"output\" must be an array of 3 numbers")
shadowproof_cli_case(NAME "grade rejects a case input that is not a float"
  ARGS grade ${verify_data}/not_representable_case.jsonl ${verify_data}/ground_exact.jsonl EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.protocol.case\\] line 1: \"plane\"\\[0\\] = \"0.1\" is not a finite number exactly representable in f32")
shadowproof_cli_case(NAME "grade rejects a missing file"
  ARGS grade ${verify_data}/no_such_file.jsonl ${verify_data}/ground_exact.jsonl EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.grade.file\\] cannot read the cases file")

# --- the node example, end to end (cases -> node -> grade) -------------------------------------
find_program(SHADOWPROOF_NODE NAMES node nodejs)
foreach(type f32 f64)
  set(name "cli: node example grades a JavaScript shadow matrix (${type})")
  if(SHADOWPROOF_NODE)
    add_test(NAME "${name}" COMMAND ${CMAKE_COMMAND} -DSHADOWPROOF=$<TARGET_FILE:shadowproof_cli>
      -DNODE=${SHADOWPROOF_NODE} -DSCRIPT=${PROJECT_SOURCE_DIR}/examples/node/shadow_matrix.js
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/node_example -DTYPE=${type}
      -P ${PROJECT_SOURCE_DIR}/examples/node/run_example.cmake)
  else()
    add_test(NAME "${name}" COMMAND ${CMAKE_COMMAND} -E echo "node not found: skipped")
    set_tests_properties("${name}" PROPERTIES SKIP_REGULAR_EXPRESSION "node not found")
  endif()
  set_tests_properties("${name}" PROPERTIES LABELS cli)
endforeach()

# --- an operation added through the table: perspective from cot(fovy/2) -----------------------
if(TARGET shadowproof_impls)
  # Two roundings at most in c/aspect and in A, B: within 2 ulps on regular cases.
  shadowproof_cli_case(NAME "check grades the perspective builders within 2 ulps on regular cases"
    ARGS check --op perspective --impl all --cases 90 EXPECT_CODE 0
    STDOUT_REGEX "perspective-closed-form-f32 +perspective +regular +30 +[0-2] .*perspective-reciprocal-f32 +perspective +regular +30 +[0-2] ")
  shadowproof_cli_case(NAME "cases writes the perspective's camera input group"
    ARGS cases --op perspective --type f32 --count 1 EXPECT_CODE 0
    STDOUT_REGEX "\"op\": \"perspective\", \"type\": \"f32\", \"class\": \"regular\", \"camera\": \\[\"0x[^\"]+\", \"0x[^\"]+\", \"0x[^\"]+\", \"0x[^\"]+\"\\]")
endif()
