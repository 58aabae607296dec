# shadowproof check / cases / grade / exact: the grader run through the real executable. Expected
# values and verdicts come from the hand-derived fixtures in tests/data/verify (see its README).
set(verify_data ${PROJECT_SOURCE_DIR}/tests/data/verify)

# --- check ------------------------------------------------------------------------------------
if(TARGET shadowproof_impls)
  shadowproof_cli_case(NAME "check --list names the seed formulas one per line"
    ARGS check --list EXPECT_CODE 0
    STDOUT_REGEX "(^|\n)seed000-general-f32\n.*(^|\n)seed001-shader-f32\n")
  shadowproof_cli_case(NAME "check prints one verdict row per implementation"
    ARGS check --impl seed000-closed-form-f32 --cases 40 EXPECT_CODE 0
    STDOUT_REGEX "\nseed000-closed-form-f32 +(exact|faithful|stable|range) +[0-9-]+ +[0-9-]+ +[0-9-]+ +[0-9-]+ +[0-9-]+ +[0-9-]+ +[0-9-]+ +[0-9-]+\n")
  # An exactly parallel light gives exact zeros that the closed form reproduces exactly.
  shadowproof_cli_case(NAME "check: seed 000's closed form is exact on exactly parallel lights"
    ARGS check --impl seed000-closed-form-f32 --cases 30 --class degenerate --json EXPECT_CODE 0
    STDOUT_REGEX "\"max_ulps\": 0,.*\"verdict\": \"exact\"")
  shadowproof_cli_case(NAME "check --json carries the oracle counters and every case's verdict"
    ARGS check --impl reflect-divide-f64 --cases 9 --json EXPECT_CODE 0
    STDOUT_REGEX "\"decided_by_intervals\": [0-9]+,\n *\"fell_back_to_rationals\": [0-9]+.*\"case_verdicts\": \\[\n *\"(exact|faithful|stable)\",")
  shadowproof_cli_case(NAME "check --svg writes the plot"
    ARGS check --impl seed000-general-f32 --cases 30 --svg ${CMAKE_CURRENT_BINARY_DIR}/verify_plot.svg EXPECT_CODE 0
    STDOUT_REGEX "Plot written to .*verify_plot.svg")
  shadowproof_cli_case(NAME "check --list and --op select nothing else"
    ARGS check --impl all --op normal-matrix --cases 8 EXPECT_CODE 0
    STDOUT_REGEX "normal-inverse-transpose-f32")
  shadowproof_cli_case(NAME "check: the correctly rounded reference is exact and passes --fail-on faithful"
    ARGS check --impl correctly-rounded-shadow-point-f32 --cases 80 --fail-on faithful EXPECT_CODE 0
    STDOUT_REGEX "correctly-rounded-shadow-point-f32 +exact +80 .*PASS: --fail-on faithful")
  shadowproof_cli_case(NAME "check --fail-on rejects an unknown verdict"
    ARGS check --impl all --fail-on bad EXPECT_CODE 2 STDOUT_EMPTY
    STDERR_REGEX "\\[shadowproof.verify.unknown_verdict\\] unknown --fail-on 'bad'; expected one of exact, faithful")
  if("irrlicht" IN_LIST SHADOWPROOF_ENGINES)
    # Irrlicht drops the plane's D·w from P·L: point lights over y = h ≠ 0 are wrong, and the
    # thresholds fail the run.
    shadowproof_cli_case(NAME "check --max-ulps fails Irrlicht's point-light shadow matrix"
      ARGS check --impl irrlicht-shadow-unit-normal-f32 --cases 60 --max-ulps 4 EXPECT_CODE 1
      STDOUT_REGEX "FAIL: --max-ulps 4 exceeded")
    shadowproof_cli_case(NAME "check --fail-on wrong fails Irrlicht's shadow matrix"
      ARGS check --impl irrlicht-shadow-f32 --cases 40 --class regular --fail-on wrong EXPECT_CODE 1
      STDOUT_REGEX "irrlicht-shadow-f32 +wrong .*FAIL: --fail-on wrong: some case is at or past it")
    shadowproof_cli_case(NAME "check --max-ulps passes Irrlicht's orthographic builder at 1 ulp within the range"
      ARGS check --impl irrlicht-ortho-rh-f32 --cases 60 --class regular --max-ulps 1 EXPECT_CODE 0
      STDOUT_REGEX "PASS: --max-ulps 1 held")
  endif()
  # Every line of the full report within 100 columns, the wide one included.
  foreach(wide "" "--wide")
    add_test(NAME "cli: check ${wide} reports fit in 100 columns"
      COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> "-DARGS=check\;--impl\;all\;--cases\;16\;${wide}"
      -DWIDTH=100 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/check_width.cmake)
    set_tests_properties("cli: check ${wide} reports fit in 100 columns" PROPERTIES LABELS cli)
  endforeach()
  # Every reproducer a report prints runs and exits 0: flat volumes, singular matrices and
  # degenerate shadows included (one example per verdict with --wide).
  add_test(NAME "cli: every reproducer check prints runs"
    COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> "-DARGS=check\;--impl\;all\;--cases\;16\;--wide"
    -DMIN=40 -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/run_reproducers.cmake)
  set_tests_properties("cli: every reproducer check prints runs" PROPERTIES LABELS cli COST 30)
endif()
shadowproof_cli_case(NAME "check rejects an unknown implementation"
  ARGS check --impl no-such-impl EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.verify.unknown_impl\\] no implementation named 'no-such-impl' \\(see --list\\)")
shadowproof_cli_case(NAME "check rejects an unknown name in a list of implementations"
  ARGS check --impl glm-ortho-f32,no-such-impl EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.verify.unknown_impl\\] no implementation named 'no-such-impl' \\(see --list\\)")
add_test(NAME "cli: check --impl A,B grades each as alone, in the built-in order, once"
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/check_impl_list.cmake)
set_tests_properties("cli: check --impl A,B grades each as alone, in the built-in order, once" PROPERTIES LABELS cli)
shadowproof_cli_case(NAME "check's table cuts a long name in the middle, so the f32 and f64 rows differ"
  ARGS check --impl correctly-rounded-perspective-fov-infinite-f32,correctly-rounded-perspective-fov-infinite-f64 --cases 2
  EXPECT_CODE 0
  STDOUT_REGEX "\ncorrectly-rounded-perspecti\\.\\.infinite-f32 exact +2 [^\n]*\ncorrectly-rounded-perspecti\\.\\.infinite-f64 exact +2 ")
shadowproof_cli_case(NAME "check rejects an unknown operation"
  ARGS check --impl all --op twist EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.verify.unknown_op\\] unknown --op 'twist'")

# --- cases ------------------------------------------------------------------------------------
shadowproof_cli_case(NAME "cases writes the protocol's JSON lines"
  ARGS cases --op shadow-matrix --type f32 --count 2 --seed 7 EXPECT_CODE 0
  STDOUT_REGEX "^{\"id\": 0, \"op\": \"shadow-matrix\", \"type\": \"f32\", \"class\": \"regular\", \"closeness\": -?[0-9]+\\.[0-9][0-9], \"plane\": \\[\"-?0x[^\"]+\", \"[^\"]+\", \"[^\"]+\", \"[^\"]+\"\\], \"light\": \\[[^]]+\\], \"exact\": {\"plane\": \\[[^]]+\\], \"light\": \\[[^]]+\\]}, \"numbers\": {\"plane\": \\[-?[0-9][^]\"]*\\], \"light\": \\[[^]\"]+\\]}}\n{\"id\": 1, [^\n]*\"class\": \"near-degenerate\"[^\n]*\n$")
shadowproof_cli_case(NAME "cases marks exactly degenerate cases with closeness -inf"
  ARGS cases --op shadow-matrix --type f64 --count 1 --class degenerate EXPECT_CODE 0
  STDOUT_REGEX "\"class\": \"degenerate\", \"closeness\": \"-inf\"")
shadowproof_cli_case(NAME "cases names the point input of shadow-point"
  ARGS cases --op shadow-point --type f64 --count 1 EXPECT_CODE 0
  STDOUT_REGEX "\"point\": \\[")
shadowproof_cli_case(NAME "cases --point-lights gives every light w = 1"
  ARGS cases --op shadow-point --type f32 --count 8 --point-lights EXPECT_CODE 0
  STDOUT_REGEX "^({[^\n]*\"light\": \\[\"[^\"]+\", \"[^\"]+\", \"[^\"]+\", \"0x1p\\+0\"\\][^\n]*\n)+$")
add_test(NAME "cli: cases --symmetric gives l = -r and b = -t"
  COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:shadowproof_cli> -P ${CMAKE_CURRENT_SOURCE_DIR}/cli/check_symmetric.cmake)
set_tests_properties("cli: cases --symmetric gives l = -r and b = -t" PROPERTIES LABELS cli)
shadowproof_cli_case(NAME "cases --class range scales the inputs out of the type's range"
  ARGS cases --op reflection-matrix --type f32 --count 1 --class range EXPECT_CODE 0
  STDOUT_REGEX "\"class\": \"range\".*p[+-](6[4-9]|7[0-9])\"")
shadowproof_cli_case(NAME "cases rejects directional-only together with point-lights-only"
  ARGS cases --op shadow-point --directional --point-lights EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.verify.requirements\\] --directional and --point-lights exclude each other")
shadowproof_cli_case(NAME "cases rejects an unknown type"
  ARGS cases --op shadow-matrix --type f16 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.verify.unknown_type\\] unknown --type 'f16'; expected f32 or f64")

# --- grade: verdicts of hand-derived outputs --------------------------------------------------
shadowproof_cli_case(NAME "grade: the exact matrix is exact"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_exact.jsonl --json EXPECT_CODE 0
  STDOUT_REGEX "\"cases\": 1,.*\"max_bits\": 0.0,.*\"max_ulps\": 0,.*\"verdict\": \"exact\"")
shadowproof_cli_case(NAME "grade: the float after 2 is faithful, caught by --fail-on faithful"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_one_ulp.jsonl --fail-on faithful EXPECT_CODE 1
  STDOUT_REGEX "is faithful\\..*FAIL: --fail-on faithful: some case is at or past it")
shadowproof_cli_case(NAME "grade: a faithful output passes --fail-on stable"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_one_ulp.jsonl --fail-on stable EXPECT_CODE 0
  STDOUT_REGEX "PASS: --fail-on stable: every case is better")
shadowproof_cli_case(NAME "grade: the float after 2 is 1 ulp and 1 bit"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_one_ulp.jsonl --json EXPECT_CODE 0
  STDOUT_REGEX "\"expected\": \"0x1p\\+1\",.*\"got\": \"0x1.000002p\\+1\",.*\"max_bits\": 1.0,.*\"max_ulps\": 1,")
shadowproof_cli_case(NAME "grade: transposed storage declared column-major is exact"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_transposed.jsonl --layout column-major --json
  EXPECT_CODE 0 STDOUT_REGEX "\"max_ulps\": 0,.*\"verdict\": \"exact\"")
shadowproof_cli_case(NAME "grade: transposed storage undeclared is wrong"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_transposed.jsonl --fail-on wrong EXPECT_CODE 1
  STDOUT_REGEX "is wrong\\..*\\(0,1\\): got 0x0p\\+0, exact -0x1p\\+0.*backward error 3.33e-01 \\(5.59e\\+06 u\\) > sqrt\\(u\\).*FAIL: --fail-on wrong")
shadowproof_cli_case(NAME "grade: transposed storage undeclared fails --max-ulps"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_transposed.jsonl --max-ulps 0 EXPECT_CODE 1
  STDOUT_REGEX "FAIL: --max-ulps 0 exceeded")
shadowproof_cli_case(NAME "grade: a NaN where the matrix has a value is nonfinite and fails --max-ulps"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_nan.jsonl --max-ulps 100 EXPECT_CODE 1
  STDOUT_REGEX "is nonfinite\\..*\\(1,3\\): got nan, exact 0x1p\\+1.*FAIL: --max-ulps 100 exceeded, or NaN/Inf")
shadowproof_cli_case(NAME "grade: a dropped d w is wrong"
  ARGS grade ${verify_data}/point_light_case.jsonl ${verify_data}/point_light_dropped.jsonl --json EXPECT_CODE 0
  STDOUT_REGEX "\"backward_error_u\": 2396745[0-9.e+]*,.*\"name\": \"\\(0,0\\)\",.*\"verdict\": \"wrong\"")
shadowproof_cli_case(NAME "grade: the point-light matrix itself is exact"
  ARGS grade ${verify_data}/point_light_case.jsonl ${verify_data}/point_light_exact.jsonl --fail-on faithful EXPECT_CODE 0
  STDOUT_REGEX "is exact\\.")
shadowproof_cli_case(NAME "grade --homogeneous: 3M is exact"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_times_3.jsonl --homogeneous --fail-on faithful
  EXPECT_CODE 0 STDOUT_REGEX "is exact\\.")
shadowproof_cli_case(NAME "grade --homogeneous: -M is exact"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_negated.jsonl --homogeneous --fail-on faithful
  EXPECT_CODE 0 STDOUT_REGEX "is exact\\.")
shadowproof_cli_case(NAME "grade: 3M undeclared is wrong"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_times_3.jsonl EXPECT_CODE 0
  STDOUT_REGEX "is wrong\\.")
shadowproof_cli_case(NAME "grade --homogeneous prints the scale and its pivot"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_times_3_one_off.jsonl --homogeneous EXPECT_CODE 0
  STDOUT_REGEX "is wrong\\..*\\(0,3\\): got 0x1p\\+2, exact 0x1.8p\\+1.*lambda 3.00e\\+00 from the pivot \\(2,1\\)")
shadowproof_cli_case(NAME "grade --name labels the rows"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/ground_exact.jsonl --name my-shader EXPECT_CODE 0
  STDOUT_REGEX "my-shader is exact\\..*\nmy-shader regular +exact +1 ")
shadowproof_cli_case(NAME "grade: an image on the wrong side is misclassified and wrong"
  ARGS grade ${verify_data}/point_case.jsonl ${verify_data}/point_flipped.jsonl --json EXPECT_CODE 0
  STDOUT_REGEX "\"misclassified\": 1,.*\"verdict\": \"wrong\"")
shadowproof_cli_case(NAME "grade: NaN for a singular matrix is a correct rejection"
  ARGS grade ${verify_data}/singular_case.jsonl ${verify_data}/singular_nan.jsonl --fail-on faithful EXPECT_CODE 0
  STDOUT_REGEX "is exact\\.")
shadowproof_cli_case(NAME "grade: the identity for a singular matrix is garbage"
  ARGS grade ${verify_data}/singular_case.jsonl ${verify_data}/singular_identity.jsonl EXPECT_CODE 0
  STDOUT_REGEX "is garbage\\..*\\(0,0\\): got 0x1p\\+0, no exact value")
shadowproof_cli_case(NAME "grade --sentinel identity: the identity for a singular matrix is a correct rejection"
  ARGS grade ${verify_data}/singular_case.jsonl ${verify_data}/singular_identity.jsonl --sentinel identity
  --fail-on faithful EXPECT_CODE 0 STDOUT_REGEX "is exact\\.")
shadowproof_cli_case(NAME "grade rejects a sentinel that means nothing for the operation"
  ARGS grade ${verify_data}/point_case.jsonl ${verify_data}/point_flipped.jsonl --sentinel identity EXPECT_CODE 2
  STDOUT_EMPTY STDERR_REGEX "\\[shadowproof.verify.sentinel\\] --sentinel identity means nothing for shadow-point outputs")
shadowproof_cli_case(NAME "grade: NaN for a flat view volume is a correct rejection"
  ARGS grade ${verify_data}/flat_case.jsonl ${verify_data}/flat_nan.jsonl --json EXPECT_CODE 0
  STDOUT_REGEX "\"nonfinite\": 0,.*\"verdict\": \"exact\"")
shadowproof_cli_case(NAME "exact prints a flat view volume's undefined entries"
  ARGS exact --op ortho --type f32 --inputs -1,1,1,1,1,3 EXPECT_CODE 0
  STDOUT_REGEX "\\(0,0\\)  1  ->  0x1p\\+0\n  \\(0,1\\)  0  ->  0x0p\\+0\n.*\\(1,1\\)  undefined .*\\(2,3\\)  -2  ->  -0x1p\\+1")

# --- grade: gating that cannot be fooled -------------------------------------------------------
shadowproof_cli_case(NAME "grade: an outputs file without some case exits 2 naming it"
  ARGS grade ${verify_data}/two_cases.jsonl ${verify_data}/short_outputs.jsonl --max-ulps 0 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.grade.missing_id\\] .*short_outputs.jsonl answers 1 of the 2 cases; no output line for id 1")
shadowproof_cli_case(NAME "grade: an empty outputs file exits 2"
  ARGS grade ${verify_data}/ground_case.jsonl ${verify_data}/empty.jsonl --max-ulps 0 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.grade.empty\\] the outputs file '.*empty.jsonl' has no line: none of the 1 cases was answered")
shadowproof_cli_case(NAME "grade: an empty case file exits 2"
  ARGS grade ${verify_data}/empty.jsonl ${verify_data}/ground_exact.jsonl EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.grade.empty\\] the case file '.*empty.jsonl' has no case")
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
  # Two or three roundings in c/aspect and in A, B: no worse than stable on ordinary inputs.
  shadowproof_cli_case(NAME "check grades the perspective builders no worse than stable on regular cases"
    ARGS check --op perspective --impl all --cases 90 --class regular --fail-on unstable EXPECT_CODE 0
    STDOUT_REGEX "perspective-closed-form-f32 +(exact|faithful|stable) .*perspective-reciprocal-f32 +(exact|faithful|stable) .*PASS")
  shadowproof_cli_case(NAME "cases writes the perspective's camera input group"
    ARGS cases --op perspective --type f32 --count 1 EXPECT_CODE 0
    STDOUT_REGEX "\"op\": \"perspective\", \"type\": \"f32\", \"class\": \"regular\", \"closeness\": [-0-9.]+, \"camera\": \\[\"0x[^\"]+\", \"0x[^\"]+\", \"0x[^\"]+\", \"0x[^\"]+\"\\]")
endif()
