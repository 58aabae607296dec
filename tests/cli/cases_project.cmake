# shadowproof project / normal-matrix / depth-precision. Expected matrices are derived by hand
# from the published formulas (numbers in the comments), never copied from a run.

# perspective c = cot(fovy/2) = 2, aspect 3/2, n = 1, f = 3: x scale c/aspect = 4/3, y scale 2;
# gl depth row (-(f+n)/(f-n), -2fn/(f-n)) = (-2, -3).
shadowproof_cli_case(NAME "project perspective gl: depth row (-2, -3)"
  ARGS project perspective --cot-half-fovy 2 --aspect 3/2 --near 1 --far 3
  EXPECT_CODE 0
  STDOUT_REGEX "\\[ *4/3 +0 +0 +0 \\]\n +\\[ *0 +2 +0 +0 \\]\n +\\[ *0 +0 +-2 +-3 \\]\n +\\[ *0 +0 +-1 +0 \\]")
# d3d: (-f/(f-n), -fn/(f-n)) = (-3/2, -3/2).
shadowproof_cli_case(NAME "project perspective d3d: depth row (-3/2, -3/2)"
  ARGS project perspective --cot-half-fovy 2 --aspect 3/2 --near 1 --far 3 --convention d3d
  EXPECT_CODE 0 STDOUT_REGEX "\\[ *0 +0 +-3/2 +-3/2 \\]")
# reverse-z: (n/(f-n), fn/(f-n)) = (1/2, 3/2).
shadowproof_cli_case(NAME "project perspective reverse-z: depth row (1/2, 3/2)"
  ARGS project perspective --cot-half-fovy 2 --aspect 3/2 --near 1 --far 3 --convention reverse-z
  EXPECT_CODE 0 STDOUT_REGEX "\\[ *0 +0 +1/2 +3/2 \\]")
# reverse-z with the far plane at infinity: (0, n) = (0, 1); the view direction reaches depth 0.
shadowproof_cli_case(NAME "project perspective reverse-z infinite far: depth row (0, 1)"
  ARGS project perspective --cot-half-fovy 2 --aspect 3/2 --near 1 --infinite-far --convention reverse-z
  EXPECT_CODE 0 STDOUT_REGEX "\\[ *0 +0 +0 +1 \\]\n +\\[ *0 +0 +-1 +0 \\]")
# gl infinite far: (-1, -2n) = (-1, -2).
shadowproof_cli_case(NAME "project perspective gl infinite far: depth row (-1, -2)"
  ARGS project perspective --cot-half-fovy 1 --aspect 1 --near 1 --infinite-far
  EXPECT_CODE 0 STDOUT_REGEX "\\[ *0 +0 +-1 +-2 \\]")
# The near-plane centre goes to NDC depth -1 (gl), the far-plane corner (3*4/3... ) to (1, 1, 1):
# far window at distance 3 is x in [-9/4, 9/4], y in [-3/2, 3/2].
shadowproof_cli_case(NAME "project perspective maps near centre and far corner exactly"
  ARGS project perspective --cot-half-fovy 2 --aspect 3/2 --near 1 --far 3 --point 0,0,-1 --point 9/4,3/2,-3
  EXPECT_CODE 0
  STDOUT_REGEX "point \\(0, 0, -1\\):\n  image  \\(0, 0, -1, 1\\)\n  ndc    \\(0, 0, -1\\)\n  inside.*point \\(9/4, 3/2, -3\\):\n  image  \\(3, 3, 3, 3\\)\n  ndc    \\(1, 1, 1\\)\n  inside")
# A point behind the eye is outside although its x, y NDC are in range: w < 0.
shadowproof_cli_case(NAME "project perspective: behind the eye is outside"
  ARGS project perspective --cot-half-fovy 1 --aspect 1 --near 1 --far 10 --point 0,0,1
  EXPECT_CODE 0 STDOUT_REGEX "outside the canonical view volume")
# JSON: exact strings, ndc null for w = 0 (the point (1, 0, 0) lies in the eye plane).
shadowproof_cli_case(NAME "project --json prints matrix strings and a null ndc for w = 0"
  ARGS project perspective --cot-half-fovy 2 --aspect 3/2 --near 1 --far 3 --point 1,0,0 --json
  EXPECT_CODE 0
  STDOUT_REGEX "\"matrix\": \\[\n +\\[\n +\"4/3\",.*\"image\": \\[\n +\"4/3\",\n +\"0\",\n +\"-3\",\n +\"0\"\n +\\],.*\"ndc\": null")

# ortho box [-2, 6] x [-1, 3] x [-5, -1] (n = 1, f = 5), gl: 2/(r-l) = 1/4, -(r+l)/(r-l) = -1/2,
# 2/(t-b) = 1/2, -(t+b)/(t-b) = -1/2, -2/(f-n) = -1/2, -(f+n)/(f-n) = -3/2.
shadowproof_cli_case(NAME "project ortho gl: the box matrix"
  ARGS project ortho --left -2 --right 6 --bottom -1 --top 3 --near 1 --far 5
  EXPECT_CODE 0
  STDOUT_REGEX "\\[ *1/4 +0 +0 +-1/2 \\]\n +\\[ *0 +1/2 +0 +-1/2 \\]\n +\\[ *0 +0 +-1/2 +-3/2 \\]\n +\\[ *0 +0 +0 +1 \\]")
# d3d: -1/(f-n) = -1/4, -n/(f-n) = -1/4.
shadowproof_cli_case(NAME "project ortho d3d: depth row (-1/4, -1/4)"
  ARGS project ortho --left -2 --right 6 --bottom -1 --top 3 --near 1 --far 5 --convention d3d
  EXPECT_CODE 0 STDOUT_REGEX "\\[ *0 +0 +-1/4 +-1/4 \\]")
# oblique = ortho * H with cot θ = 1/2, cot φ = 0: row 0 = (1/4, 0, (1/4)(-1/2), -1/2).
shadowproof_cli_case(NAME "project oblique: ortho times the shear"
  ARGS project oblique --left -2 --right 6 --bottom -1 --top 3 --near 1 --far 5 --cot-theta 1/2 --cot-phi 0
  EXPECT_CODE 0 STDOUT_REGEX "\\[ *1/4 +0 +-1/8 +-1/2 \\]")
# frustum l = -1, r = 3, b = -2, t = 2, n = 2, f = 6, gl: 2n/(r-l) = 1, (r+l)/(r-l) = 1/2,
# 2n/(t-b) = 1, depth row (-(f+n)/(f-n), -2fn/(f-n)) = (-2, -6).
shadowproof_cli_case(NAME "project frustum gl: the off-centre frustum matrix"
  ARGS project frustum --left -1 --right 3 --bottom -2 --top 2 --near 2 --far 6
  EXPECT_CODE 0
  STDOUT_REGEX "\\[ *1 +0 +1/2 +0 \\]\n +\\[ *0 +1 +0 +0 \\]\n +\\[ *0 +0 +-2 +-6 \\]\n +\\[ *0 +0 +-1 +0 \\]")
# GAMES101 n = -1, f = -5, c = 1, aspect 1: persp row 2 = (0, 0, n+f, -nf) = (0, 0, -6, -5);
# ortho z scale 2/(n-f) = 1/2, z shift -(n+f)/2 = 3: row 2 = (1/2)(-6) + (1/2)(3)(1) = -3/2 and
# (1/2)(-5) = -5/2; x, y: (1/top)·n = -1. The near centre (0, 0, -1) goes to NDC depth +1.
shadowproof_cli_case(NAME "project games101: the composed matrix, near to +1"
  ARGS project games101 --near -1 --far -5 --cot-half-fovy 1 --aspect 1 --point 0,0,-1
  EXPECT_CODE 0
  STDOUT_REGEX "\\[ *-1 +0 +0 +0 \\]\n +\\[ *0 +-1 +0 +0 \\]\n +\\[ *0 +0 +-3/2 +-5/2 \\]\n +\\[ *0 +0 +1 +0 \\].*ndc    \\(0, 0, 1\\)")

# Errors: exit 2, nothing on stdout, the culprit named on stderr.
shadowproof_cli_case(NAME "project: near = far is an error"
  ARGS project ortho --left -1 --right 1 --bottom -1 --top 1 --near 2 --far 2
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "project.degenerate_volume. near = far = 2")
shadowproof_cli_case(NAME "project: left = right is an error"
  ARGS project frustum --left 1 --right 1 --bottom -1 --top 1 --near 1 --far 2
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "project.degenerate_volume. left = right = 1")
shadowproof_cli_case(NAME "project: frustum near <= 0 is an error"
  ARGS project frustum --left -1 --right 1 --bottom -1 --top 1 --near 0 --far 2
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "project.near_not_positive. near = 0 must be > 0")
shadowproof_cli_case(NAME "project: games101 wants negative planes"
  ARGS project games101 --near 1 --far -5 --cot-half-fovy 1 --aspect 1
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "project.games101_sign. near = 1 must be < 0")
shadowproof_cli_case(NAME "project: a malformed number names its flag"
  ARGS project perspective --cot-half-fovy 1 --aspect 1 --near 1 --far 1x
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "number.malformed. --far: cannot read \"1x\"")
shadowproof_cli_case(NAME "project: a missing flag is named"
  ARGS project perspective --cot-half-fovy 1 --aspect 1 --near 1
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "cli.missing_option. perspective needs --far")
shadowproof_cli_case(NAME "project: a flag of another projection is refused"
  ARGS project perspective --cot-half-fovy 1 --aspect 1 --near 1 --far 5 --left 2
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "cli.unused_option. --left does not apply to perspective")
shadowproof_cli_case(NAME "project: unknown convention"
  ARGS project perspective --cot-half-fovy 1 --aspect 1 --near 1 --far 5 --convention vulkan
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "project.convention. unknown depth convention 'vulkan'")

# normal-matrix of S(2, 1, 1): G = diag(1/2, 1, 1, 1); the normal (1, 1, 0) goes to (1/2, 1, 0).
shadowproof_cli_case(NAME "normal-matrix of a non-uniform scale"
  ARGS normal-matrix --matrix 2,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1 --normal 1,1,0
  EXPECT_CODE 0
  STDOUT_REGEX "det M = 2\n.*\\[ *1/2 +0 +0 +0 \\].*normal \\(1, 1, 0\\) -> \\(1/2, 1, 0\\)")
# Shear x += y: G = (M^-1)^T = [1 0 0 0; -1 1 0 0; 0 0 1 0; 0 0 0 1].
shadowproof_cli_case(NAME "normal-matrix --json of a shear"
  ARGS normal-matrix --matrix 1,1,0,0,0,1,0,0,0,0,1,0,0,0,0,1 --json
  EXPECT_CODE 0
  STDOUT_REGEX "\"matrix\": \\[\n +\\[\n +\"1\",\n +\"0\",\n +\"0\",\n +\"0\"\n +\\],\n +\\[\n +\"-1\",\n +\"1\",")
shadowproof_cli_case(NAME "normal-matrix: a singular matrix is an error"
  ARGS normal-matrix --matrix 1,0,0,0,0,1,0,0,0,0,0,0,0,0,0,1
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "matrix.singular. the matrix is singular")
shadowproof_cli_case(NAME "normal-matrix: wrong number of entries"
  ARGS normal-matrix --matrix 1,0,0
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "number.list_length. --matrix expects 16")

# depth-precision, by hand: orthographic d3d with n = 0, f = 2^24 - 1 = 16777215 makes the
# 24-bit code k exactly eye distance k, so [1, 10] holds 10 codes, 1 apart.
shadowproof_cli_case(NAME "depth-precision unorm24 of a linear depth: 10 codes"
  ARGS depth-precision ortho --left -1 --right 1 --bottom -1 --top 1 --near 0 --far 16777215
       --convention d3d --from 1 --to 10 --format unorm24 --at 3 --json
  EXPECT_CODE 0 STDOUT_REGEX "\"distinct_values\": 10,.*\"spacing\": \"1\"")
# f32 with z_ndc = s on [1/2, 1]: the floats 1/2 + k 2^-24, k = 0 .. 2^23: 8388609 values.
shadowproof_cli_case(NAME "depth-precision f32 of a linear depth: 2^23 + 1 floats"
  ARGS depth-precision ortho --left -1 --right 1 --bottom -1 --top 1 --near 0 --far 1
       --convention d3d --from 1/2 --to 1 --format f32 --json
  EXPECT_CODE 0 STDOUT_REGEX "\"distinct_values\": 8388609")
shadowproof_cli_case(NAME "depth-precision table compares gl, d3d and reverse-z"
  ARGS depth-precision perspective --cot-half-fovy 1 --aspect 1 --near 0.1 --far 1000 --from 1 --to 1000
       --format f32
  EXPECT_CODE 0 STDOUT_REGEX "gl +[0-9]+\n +d3d +[0-9]+\n +reverse-z +[0-9]+\n")
shadowproof_cli_case(NAME "depth-precision writes an SVG plot"
  ARGS depth-precision --cot-half-fovy 1 --aspect 1 --near 0.1 --far 1000 --from 1 --to 1000
       --format f32 --svg depth_precision_plot.svg
  EXPECT_CODE 0 STDOUT_REGEX "plot written to depth_precision_plot.svg")
shadowproof_cli_case(NAME "depth-precision: interval beyond the far plane is an error"
  ARGS depth-precision --cot-half-fovy 1 --aspect 1 --near 1 --far 10 --from 5 --to 20 --format f32
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "depth_precision.outside_volume. interval end: distance 20")
shadowproof_cli_case(NAME "depth-precision: from >= to is an error"
  ARGS depth-precision --cot-half-fovy 1 --aspect 1 --near 1 --far 10 --from 5 --to 5 --format f32
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "depth_precision.interval. the eye-distance interval .5, 5.")
shadowproof_cli_case(NAME "depth-precision: unknown format"
  ARGS depth-precision --cot-half-fovy 1 --aspect 1 --near 1 --far 10 --from 2 --to 3 --format f16
  EXPECT_CODE 2 STDOUT_EMPTY STDERR_REGEX "depth_precision.format. unknown depth format 'f16'")
