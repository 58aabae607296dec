# The shadow, reflect and demo subcommands, and bad input through the CLI.
# Expected text is derived by hand: P = (0,1,0,0), L = (2,5,1,1) gives M = 5I - L Pᵀ.

shadowproof_cli_case(NAME "shadow prints the hand-derived matrix and image"
  ARGS shadow --plane 0,1,0,0 --light 2,5,1,1 --point 1,2,3 EXPECT_CODE 0
  STDOUT_REGEX "P·L = 5.*\\[ 5 -2  0  0 \\].*\\[ 0  0  0  0 \\].*\\[ 0 -1  5  0 \\].*\\[ 0 -1  0  5 \\].*class  shadow.*affine \\(1/3, 0, 13/3\\)")
shadowproof_cli_case(NAME "shadow --json has the documented shape with exact strings"
  ARGS shadow --plane 0,1,0,0 --light 2,5,1,1 --point 1,2,3 --point 0,7,0 --json EXPECT_CODE 0
  STDOUT_REGEX "\"matrix\": \\[[^]]*\"5\",[^]]*\"-2\".*\"affine\": \\[[^]]*\"1/3\",[^]]*\"0\",[^]]*\"13/3\".*\"class\": \"shadow\".*\"class\": \"beyond_light\"")
shadowproof_cli_case(NAME "shadow reads every number syntax"
  ARGS shadow --plane "0,f32:1,0,0x0p0" --light "1/2,2.5e0,0x1p0,1" --point "0,1,0" EXPECT_CODE 0
  STDOUT_REGEX "light L = \\(1/2, 5/2, 1, 1\\)")
shadowproof_cli_case(NAME "a directional light parallel to the plane is a result, not an error"
  ARGS shadow --plane 0,1,0,0 --light 1,0,0,0 --point 0,2,0 --point 3,0,3 EXPECT_CODE 0
  STDOUT_REGEX "class  light_parallel.*image  \\(-2, 0, 0, 0\\).*affine none \\(w = 0\\).*class  line_in_plane")
shadowproof_cli_case(NAME "a point at the light's height has an image at infinity"
  ARGS shadow --plane 0,1,0,0 --light 2,5,1,1 --point -1,5,0 --json EXPECT_CODE 0
  STDOUT_REGEX "\"affine\": null.*\"class\": \"at_infinity\"")
shadowproof_cli_case(NAME "reflect about y = 1 maps the origin to (0, 2, 0)"
  ARGS reflect --plane 0,1,0,-1 --point 0,0,0 EXPECT_CODE 0
  STDOUT_REGEX "\\[ 1  0  0  0 \\].*\\[ 0 -1  0  2 \\].*affine \\(0, 2, 0\\)")
shadowproof_cli_case(NAME "reflect --json prints exact strings"
  ARGS reflect --plane 1,2,2,-3 --json EXPECT_CODE 0 STDOUT_REGEX "\"7/9\".*\"-4/9\".*\"2/3\"")
shadowproof_cli_case(NAME "demo runs and its exact checks pass"
  ARGS demo EXPECT_CODE 0 STDOUT_REGEX "exact check: 25 of 25 non-zero images.*-> OK.*M² = I -> OK, det M = -1")

foreach(cmd shadow reflect demo)
  shadowproof_cli_case(NAME "${cmd} --help explains the command" ARGS ${cmd} --help EXPECT_CODE 0 STDOUT_REGEX "Usage:")
endforeach()
shadowproof_cli_case(NAME "--help lists the subcommands" ARGS --help EXPECT_CODE 0 STDOUT_REGEX "shadow.*reflect|reflect.*shadow")

# Bad input: a clear message on stderr, nothing on stdout, exit code 2.
shadowproof_cli_case(NAME "a malformed number names the offending text"
  ARGS shadow --plane 0,1,0,zero --light 1,1,1,1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof.number.malformed\\] cannot read \"zero\" as a number")
shadowproof_cli_case(NAME "a zero plane normal is rejected"
  ARGS shadow --plane 0,0,0,1 --light 1,1,1,1 EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "geometry.zero_normal")
shadowproof_cli_case(NAME "a zero light is rejected"
  ARGS shadow --plane 0,1,0,0 --light 0,0,0,0 EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "geometry.zero_light")
shadowproof_cli_case(NAME "f32:nan is rejected"
  ARGS shadow --plane 0,1,0,0 --light f32:nan,1,1,1 EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "number.not_finite.*f32:nan")
shadowproof_cli_case(NAME "f64:inf is rejected"
  ARGS reflect --plane f64:inf,1,0,0 EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "number.not_finite")
shadowproof_cli_case(NAME "f32 overflow to infinity is rejected"
  ARGS reflect --plane f32:1e39,1,0,0 EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "overflows the float format")
shadowproof_cli_case(NAME "an over-long number is rejected with the limit and the flag"
  ARGS shadow --plane 0,1,0,1e999999 --light 1,1,1,1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "number.too_large.*4096 bits.*--max-bits")
shadowproof_cli_case(NAME "--max-bits lowers the limit"
  ARGS --max-bits 8 shadow --plane 0,1,0,256 --light 1,1,1,1 EXPECT_CODE 2 STDERR_REGEX "limit is 8 bits")
shadowproof_cli_case(NAME "a zero denominator is rejected"
  ARGS shadow --plane 0,1,0,1/0 --light 1,1,1,1 EXPECT_CODE 2 STDERR_REGEX "number.zero_denominator")
shadowproof_cli_case(NAME "a plane with three numbers is rejected"
  ARGS shadow --plane 0,1,0 --light 1,1,1,1 EXPECT_CODE 2 STDERR_REGEX "--plane expects 4 comma-separated numbers, got 3")
shadowproof_cli_case(NAME "a point with two numbers is rejected"
  ARGS shadow --plane 0,1,0,0 --light 1,1,1,1 --point 1,2 EXPECT_CODE 2 STDERR_REGEX "--point expects 3")
shadowproof_cli_case(NAME "a missing required option is a usage error"
  ARGS shadow --light 1,1,1,1 EXPECT_CODE 2 STDERR_REGEX "--plane is required")
shadowproof_cli_case(NAME "an unknown subcommand is a usage error" ARGS shade EXPECT_CODE 2 STDERR_REGEX "shade")
shadowproof_cli_case(NAME "no subcommand is a usage error" ARGS "" EXPECT_CODE 2)
