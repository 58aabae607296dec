# shadowproof explain: the derivations with numbers. Expected values are derived by hand:
# P = (0,1,0,0), L = (2,5,1,1) gives P·L = 5 and M = 5I - L Pᵀ; the mirror y = 1 has row
# (0, -1, 0, 2); N(α, β) for n = 1, f = 3 has α = -2, β = -3.

shadowproof_cli_case(NAME "explain shadow derives the README example step by step"
  ARGS explain shadow --plane 0,1,0,0 --light 2,5,1,1 EXPECT_CODE 0
  STDOUT_REGEX "P·L = 0·2 \\+ 1·5 \\+ 0·1 \\+ 0·1 = 5.*M = \\(P·L\\) I − L Pᵀ:.*Result: shadow matrix.*\\[ 5 -2  0  0 \\].*\\[ 0  0  0  0 \\].*\\[ 0 -1  5  0 \\].*\\[ 0 -1  0  5 \\]")
shadowproof_cli_case(NAME "explain shadow follows a point to its shadow"
  ARGS explain shadow --plane 0,1,0,0 --light 2,5,1,1 --point 1,2,3 EXPECT_CODE 0
  STDOUT_REGEX "k = −\\(P·V\\)/\\(P·L\\) = −\\(2\\)/\\(5\\) = -2/5.*affine image \\(x/w, y/w, z/w\\) = \\(1/3, 0, 13/3\\)")
shadowproof_cli_case(NAME "explain shadow reads every number syntax"
  ARGS explain shadow --plane "0,f32:1,0,0x0p0" --light "1/2,2.5e0,0x1p0,1" EXPECT_CODE 0
  STDOUT_REGEX "L = \\(1/2, 5/2, 1, 1\\)")
shadowproof_cli_case(NAME "explain reflect ends in the matrix reflect prints"
  ARGS explain reflect --plane 0,1,0,-1 EXPECT_CODE 0
  STDOUT_REGEX "M M = I \\(holds\\).*det M = -1.*Result: reflection matrix.*\\[ 1  0  0  0 \\].*\\[ 0 -1  0  2 \\]")
shadowproof_cli_case(NAME "explain perspective solves alpha and beta"
  ARGS explain perspective --near 1 --far 3 EXPECT_CODE 0
  STDOUT_REGEX "det = \\(-1\\)·1 − 1·\\(-3\\) = 2.*= -2\n.*= -3\n.*depth -1 \\(holds\\).*depth 1 \\(holds\\).*\\[ 1  0  0  0 \\].*\\[ 0  0 -2 -3 \\].*\\[ 0  0 -1  0 \\]")
shadowproof_cli_case(NAME "explain perspective with a window derives the frustum"
  ARGS explain perspective --near 1 --far 3 --left -1 --right 1 --bottom -1 --top 1 --convention d3d EXPECT_CODE 0
  STDOUT_REGEX "z_near = 0, z_far = 1.*A = \\(1·0 − 3·1\\)/\\(2\\) = -3/2.*B = 1·0 \\+ 1·\\(-3/2\\) = -3/2.*near corner.*\\(holds\\).*far corner.*\\(holds\\)")
shadowproof_cli_case(NAME "explain normal-matrix ends in the inverse transpose"
  ARGS explain normal-matrix --matrix 2,0,0,5,0,1,0,0,0,0,1,0,0,0,0,1 EXPECT_CODE 0
  STDOUT_REGEX "det M = .* = 2\n.*Mᵀ G = I \\(holds\\).*Result: normal matrix.*\\[ 1/2    0    0    0 \\].*\\[-5/2    0    0    1 \\]")

# Bad input: exit 2, a message naming the culprit, nothing on stdout.
shadowproof_cli_case(NAME "explain shadow rejects a malformed plane"
  ARGS explain shadow --plane 0,1,x,0 --light 2,5,1,1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.number\\.malformed\\]")
shadowproof_cli_case(NAME "explain shadow rejects a zero light"
  ARGS explain shadow --plane 0,1,0,0 --light 0,0,0,0 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.geometry\\.zero_light\\]")
shadowproof_cli_case(NAME "explain reflect rejects a zero normal"
  ARGS explain reflect --plane 0,0,0,1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.geometry\\.zero_normal\\]")
shadowproof_cli_case(NAME "explain perspective rejects near = far"
  ARGS explain perspective --near 2 --far 2 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.project\\.degenerate_volume\\]")
shadowproof_cli_case(NAME "explain perspective names the missing window flags"
  ARGS explain perspective --near 1 --far 3 --left -1 --right 1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "missing --bottom, --top")
shadowproof_cli_case(NAME "explain normal-matrix rejects a singular matrix"
  ARGS explain normal-matrix --matrix 1,0,0,0,0,1,0,0,0,0,0,0,0,0,0,1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.matrix\\.singular\\]")
shadowproof_cli_case(NAME "explain without a topic is a usage error"
  ARGS explain EXPECT_CODE 2 STDOUT_EMPTY)
shadowproof_cli_case(NAME "explain --help lists the topics"
  ARGS explain --help EXPECT_CODE 0 STDOUT_REGEX "shadow.*reflect.*perspective.*normal-matrix")
