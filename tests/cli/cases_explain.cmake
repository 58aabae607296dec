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
  ARGS explain --help EXPECT_CODE 0
  STDOUT_REGEX "shadow.*reflect.*reflect-frames.*perspective.*ortho.*oblique.*games101.*normal-matrix.*change-of-basis")

# Point classes, named with their geometric meaning. Light (0, 4, 0) over y = 0: s = 4, and
# λ* = s/(s − t) is 2 for t = 2 (a real shadow), 2/3 for t = −2 (false), −2 for t = 6 (anti-shadow).
shadowproof_cli_case(NAME "explain shadow names each point's class and what it means"
  ARGS explain shadow --plane 0,1,0,0 --light 0,4,0,1 --point 2,2,0 --point -1,-2,2 --point 1,6,-2 --point 2,4,-1 EXPECT_CODE 0
  STDOUT_REGEX "class shadow: a real shadow.*= 2 > 1.*class behind_receiver: a false shadow.*= 2/3, between 0 and 1.*class beyond_light: an anti-shadow.*= -2 < 0.*class at_infinity: at infinity")

# Every topic draws its case with --svg; an unwritable picture is an error before anything is printed.
shadowproof_cli_case(NAME "explain shadow --svg draws the case"
  ARGS explain shadow --plane 0,1,0,0 --light 2,5,1,1 --point 1,2,3 --svg explain_shadow.svg EXPECT_CODE 0
  STDOUT_REGEX "affine image \\(x/w, y/w, z/w\\) = \\(1/3, 0, 13/3\\)")
shadowproof_cli_case(NAME "explain --svg to an unwritable path is an error"
  ARGS explain reflect --plane 0,1,0,-1 --svg no_such_directory/figure.svg EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.io\\.cannot_write\\]")

# Seed 003's reflection by frames with the rotation of q = (2, -1, -1, 0): N = (1, 2, 2)/3, and
# with d = 3 the point (1, 2, 3) goes to (1,2,3) − 2(11/3 + 3)(1,2,2)/3 = (−31/9, −62/9, −53/9).
shadowproof_cli_case(NAME "explain reflect-frames follows a point through every factor"
  ARGS explain reflect-frames --quaternion 2,-1,-1,0 --d 3 --point 1,2,3 --svg explain_frames.svg EXPECT_CODE 0
  STDOUT_REGEX "N = \\(1/3, 2/3, 2/3\\).*equals the closed form of the mirror \\(holds\\).*M_rowᵀ = M \\(holds\\).*T\\(−dN\\) · that = \\(-31/9, -62/9, -53/9, 1\\) = X'")
shadowproof_cli_case(NAME "explain reflect-frames rejects the zero quaternion"
  ARGS explain reflect-frames --quaternion 0,0,0,0 --d 1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.geometry\\.zero_quaternion\\]")

# The normalisation N(α, β) needs both planes in front of the eye.
shadowproof_cli_case(NAME "explain perspective rejects near = 0"
  ARGS explain perspective --near 0 --far 3 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.project\\.near_not_positive\\] near = 0 must be > 0")
shadowproof_cli_case(NAME "explain perspective rejects a negative near"
  ARGS explain perspective --near -1 --far 3 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.project\\.near_not_positive\\] near = -1 must be > 0")
shadowproof_cli_case(NAME "explain perspective rejects far = 0"
  ARGS explain perspective --near 1 --far 0 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.project\\.far_not_positive\\]")
shadowproof_cli_case(NAME "explain perspective --svg draws the frustum and the cube"
  ARGS explain perspective --near 1 --far 4 --left -1 --right 1 --bottom -1 --top 1 --convention reverse-z --point 1,1,-2 --svg explain_frustum.svg EXPECT_CODE 0
  STDOUT_REGEX "z_near = 1, z_far = 0.*The points:")

# Orthographic: box [-2, 2] x [-1, 1] x [-5, -1], gl: A = (−1 − 1)/4 = −1/2, B = −1 + A·1 = −3/2.
shadowproof_cli_case(NAME "explain ortho derives the depth row"
  ARGS explain ortho --left -2 --right 2 --bottom -1 --top 1 --near 1 --far 5 --svg explain_ortho.svg EXPECT_CODE 0
  STDOUT_REGEX "A = \\(\\(-1\\) − 1\\)/\\(4\\) = -1/2.*B = \\(-1\\) \\+ \\(-1/2\\)·1 = -3/2.*near corner.*\\(holds\\).*far corner.*\\(holds\\).*Result: orthographic matrix")
shadowproof_cli_case(NAME "explain ortho rejects a flat box"
  ARGS explain ortho --left 1 --right 1 --bottom -1 --top 1 --near 1 --far 5 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.project\\.degenerate_volume\\]")

# Oblique, both signs: cot θ = 1, cot φ = 0 and the point (0, 0, 1) go to x = +1 (plus, seed 002's
# x_p = x + z cot θ) or x = −1 (minus, Angel's and the library's).
shadowproof_cli_case(NAME "explain oblique with +cot follows seed 002's first slide"
  ARGS explain oblique --cot-theta 1 --cot-phi 0 --cot-sign plus --point 0,0,1 --svg explain_oblique.svg EXPECT_CODE 0
  STDOUT_REGEX "tan θ = z/\\(x_p − x\\).*projector = \\(1, 0, -1, 0\\).*H projector = \\(0, 0, -1, 0\\) \\(holds\\).*M \\(0, 0, 1, 1\\) = \\(1, 0, 0, 1\\)")
shadowproof_cli_case(NAME "explain oblique with -cot follows the library"
  ARGS explain oblique --cot-theta 1 --cot-phi 0 --point 0,0,1 EXPECT_CODE 0
  STDOUT_REGEX "projector = \\(1, 0, 1, 0\\).*M \\(0, 0, 1, 1\\) = \\(-1, 0, 0, 1\\)")
shadowproof_cli_case(NAME "explain oblique with a box keeps depth"
  ARGS explain oblique --cot-theta 2/3 --cot-phi -1/5 --left -2 --right 6 --bottom -1 --top 3 --near 1/2 --far 5 --convention d3d EXPECT_CODE 0
  STDOUT_REGEX "near corner over \\(l, b, −n\\).*\\(holds\\).*far corner over \\(r, t, −f\\).*\\(holds\\)")
shadowproof_cli_case(NAME "explain oblique rejects an unknown sign"
  ARGS explain oblique --cot-theta 1 --cot-phi 0 --cot-sign sideways EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.explain\\.cot_sign\\] unknown --cot-sign 'sideways'")
shadowproof_cli_case(NAME "explain oblique names a missing box flag"
  ARGS explain oblique --cot-theta 1 --cot-phi 0 --left -1 --right 1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.cli\\.missing_option\\].*missing --bottom, --top")

# GAMES101: n = −1, f = −4: A = n + f = −5, B = −nf = −4; c = 1 gives top = 1.
shadowproof_cli_case(NAME "explain games101 squeezes, centres and scales"
  ARGS explain games101 --near -1 --far -4 --cot-half-fovy 1 --aspect 4/3 --svg explain_games101.svg EXPECT_CODE 0
  STDOUT_REGEX "A = -5, B = -4.*top = 1, right = 4/3.*near corner.*\\(holds\\).*far corner.*\\(holds\\)")
shadowproof_cli_case(NAME "explain games101 rejects a positive near"
  ARGS explain games101 --near 1 --far -4 --cot-half-fovy 1 --aspect 1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.project\\.games101_sign\\]")
shadowproof_cli_case(NAME "explain games101 names a missing flag"
  ARGS explain games101 --near -1 --far -4 --aspect 1 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.cli\\.missing_option\\] explain games101 needs --cot-half-fovy")

# Change of basis: the child point (1, 1, 0) of the frame with axes (0,1,0), (-1,0,0), (0,0,1) at
# (2, 1, 0) is (2,1,0) + (0,1,0) + (-1,0,0) = (1, 2, 0).
shadowproof_cli_case(NAME "explain change-of-basis maps a child point to the parent"
  ARGS explain change-of-basis --x-axis 0,1,0 --y-axis -1,0,0 --z-axis 0,0,1 --origin 2,1,0 --point 1,1,0 --svg explain_basis.svg EXPECT_CODE 0
  STDOUT_REGEX "equals the inverse \\(holds\\).*M_c→p \\(a, b, c, 1\\) = \\(1, 2, 0, 1\\)")
shadowproof_cli_case(NAME "explain change-of-basis rejects dependent axes"
  ARGS explain change-of-basis --x-axis 1,0,0 --y-axis 2,0,0 --z-axis 0,0,1 --origin 0,0,0 EXPECT_CODE 2 STDOUT_EMPTY
  STDERR_REGEX "\\[shadowproof\\.matrix\\.singular\\]")
shadowproof_cli_case(NAME "explain normal-matrix follows a normal"
  ARGS explain normal-matrix --matrix 2,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1 --normal 1,1,0 --svg explain_normal.svg EXPECT_CODE 0
  STDOUT_REGEX "G n = \\(1/2, 1, 0\\).*M n = \\(2, 1, 0\\)")
