# Cameras with irrational entries, conventions declared in case lines, and the conformance
# table's sample run. Expected values are derived by hand (tests/data/conformance/README.md).
set(conformance_data ${PROJECT_SOURCE_DIR}/tests/data/conformance)

# --- shadowproof camera -------------------------------------------------------------------------
# cot(45°) = 1 exactly; left-handed d3d with the far plane at infinity: (2,2) = +1, (2,3) = −n.
shadowproof_cli_case(NAME "camera: 90 degrees is exactly cot 45° = 1"
  ARGS camera perspective --fovy 90 --degrees --aspect 2 --near 1 --infinite-far --convention d3d --handedness left
  EXPECT_CODE 0
  STDOUT_REGEX "\\(0,0\\) 1/2\n.*\\(1,1\\) 1\n.*\\(2,2\\) 1\n  \\(2,3\\) -1\n.*\\(3,2\\) 1\n")
# The float nearest π/2 is 4.37e-8 above it: cot of half of it is 1 − 4.37e-8, below the float
# midpoint 1 − 2^-25, so it rounds to 1 − 2^-24 = 0x1.fffffep-1.
shadowproof_cli_case(NAME "camera: cot of half the float nearest pi/2 rounds below 1"
  ARGS camera perspective --fovy 0x1.921fb6p+0 --aspect 1 --near 1 --far 3
  EXPECT_CODE 0
  STDOUT_REGEX "\\(1,1\\) cot\\(fovy/2\\) = 0\\.99999995628861[0-9]*\\.\\.\\.  f32 0x1\\.fffffep-1")
# eye (1, 0, 1) looking at the origin: x = (1, 0, −1)/√2, z = (1, 0, 1)/√2, translation −√2.
shadowproof_cli_case(NAME "camera: look-at entries are q/sqrt(s), rounded as IEEE sqrt rounds them"
  ARGS camera look-at --eye 1,0,1 --target 0,0,0 --up 0,1,0
  EXPECT_CODE 0
  STDOUT_REGEX "\\(0,0\\) 1/sqrt\\(2\\) = 0\\.70710678118654752440[0-9]*\\.\\.\\.  f32 0x1\\.6a09e6p-1  f64 0x1\\.6a09e667f3bcdp-1\n.*\\(1,1\\) 1\n.*\\(2,3\\) -2/sqrt\\(2\\) = -1\\.41421356237309504880")
shadowproof_cli_case(NAME "camera: a look-at with up along the view direction is rejected"
  ARGS camera look-at --eye 1,0,1 --target 0,0,0 --up 2,0,2
  EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.camera.degenerate_view\\] --up is parallel to the view direction \\(or zero\\)")
shadowproof_cli_case(NAME "camera: a field of view of half a turn or more is rejected"
  ARGS camera perspective --fovy 180 --degrees --aspect 1 --near 1 --far 2
  EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.project.focal_not_positive\\] --fovy 180 degrees is not inside \\(0, 180\\)")
shadowproof_cli_case(NAME "project: --handedness left negates column 2"
  ARGS project ortho --left -1 --right 1 --bottom -1 --top 1 --near 1 --far 3 --handedness left
  EXPECT_CODE 0
  STDOUT_REGEX "left-handed \\(looking down \\+z\\)\n.*\\[ *0 +0 +1 +-2 \\]")
shadowproof_cli_case(NAME "project: an unknown handedness is rejected"
  ARGS project ortho --left -1 --right 1 --bottom -1 --top 1 --near 1 --far 3 --handedness up
  EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.project.handedness\\] unknown handedness 'up': expected right or left")

# --- check on the camera operations ------------------------------------------------------------
if(TARGET shadowproof_impls)
  # The correctly rounded references are exact on every case; the camera code overflows
  # (nonfinite where the exact entry is finite) on the range class: range.
  shadowproof_cli_case(NAME "check grades every camera implementation with a verdict"
    ARGS check --impl all --op perspective-fov --cases 9
    EXPECT_CODE 0
    STDOUT_REGEX "correctly-rounded-perspective-fov-f32 +exact +9 +- +- +- +- +- +- +-\n.*textbook-perspective-fov-f32 +range ")
  foreach(op perspective-fov-infinite look-at target-to ortho-size perspective-size)
    shadowproof_cli_case(NAME "check runs the ${op} implementations"
      ARGS check --impl all --op ${op} --cases 6 EXPECT_CODE 0
      STDOUT_REGEX "correctly-rounded-[a-z0-9.-]+ +exact +6 +- +- +- +- +- +- +-\n")
  endforeach()
endif()

# --- conventions in case lines ------------------------------------------------------------------
shadowproof_cli_case(NAME "cases --convention writes the conventions and the inputs in them"
  ARGS cases --op shadow-matrix --type f32 --count 1 --convention plane=n.x=d --convention layout=column-major
  EXPECT_CODE 0
  STDOUT_REGEX "\"conventions\": {\"layout\": \"column-major\", \"plane\": \"n.x=d\"}.*\"numbers\": {\"plane\": \\[")
shadowproof_cli_case(NAME "grade: one file mixes layouts, depths, handedness, plane forms, mat4 layouts and degrees"
  ARGS grade ${conformance_data}/mixed_cases.jsonl ${conformance_data}/mixed_exact.jsonl --json
  EXPECT_CODE 0
  STDOUT_REGEX "\"garbage\": 0,.*\"max_ulps\": 0,.*\"nonfinite\": 0,")
shadowproof_cli_case(NAME "grade: the reproducer carries the case's own conventions"
  ARGS grade ${conformance_data}/mixed_cases.jsonl ${conformance_data}/mixed_one_ulp.jsonl --json
  EXPECT_CODE 0
  STDOUT_REGEX "\"verdict\": \"faithful\".*\"reproduce\": \"shadowproof camera perspective --fovy 0x1.68p\\+6 --degrees --aspect 0x1p\\+1")
shadowproof_cli_case(NAME "cases rejects an unknown convention"
  ARGS cases --op ortho --convention depth=z
  EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.protocol.convention\\] convention \"depth\" cannot be \"z\"; expected one of gl, d3d, reverse-z")
shadowproof_cli_case(NAME "grade refuses to grade an irrational operation up to scale"
  ARGS grade ${conformance_data}/mixed_cases.jsonl ${conformance_data}/mixed_exact.jsonl --homogeneous
  EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.verify.irrational_scale\\] perspective-fov: its exact values are irrational")

# --- the conformance table, a sample of every adapter -------------------------------------------
# Needs the pinned npm libraries and the Vulkan runner (conformance/setup.sh, which
# scripts/test.sh runs); skipped, and said so, when they are not there. It starts about 180
# `shadowproof cases` and `grade` processes: under the sanitizers each one's leak check at exit
# costs ~50 ms, so leaks are not looked for here (the cli tests of cases and grade look for them).
set(SHADOWPROOF_CONFORMANCE_VK_BUILD "${PROJECT_SOURCE_DIR}/build/conformance-vk" CACHE PATH
    "Build tree of conformance/vulkan (the Vulkan runner) for the conformance sample test")
find_program(SHADOWPROOF_NODE node)
if(SHADOWPROOF_NODE)
  add_test(NAME "conformance: every adapter of the table runs and is graded (a sample)"
    COMMAND ${SHADOWPROOF_NODE} ${PROJECT_SOURCE_DIR}/conformance/run.mjs --sample --skip-when-not-set-up
            --shadowproof $<TARGET_FILE:shadowproof_cli> --vk-build ${SHADOWPROOF_CONFORMANCE_VK_BUILD})
  set_tests_properties("conformance: every adapter of the table runs and is graded (a sample)" PROPERTIES
    LABELS conformance SKIP_RETURN_CODE 77 TIMEOUT 900 COST 90
    ENVIRONMENT "VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json;ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:detect_stack_use_after_return=0")
endif()
