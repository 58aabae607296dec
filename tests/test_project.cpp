// Projection matrices: corners, near/far depths, exact monotonicity, outside stays outside.
// Expected values are the canonical volumes of each convention, written here by hand, or
// numbers derived by hand in the comments; never taken from the code under test.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "shadowproof/core/error.h"
#include "shadowproof/constructions/project.h"
#include "support/exact_helpers.h"

using namespace shadowproof;
using shadowproof::testing::q;
using shadowproof::testing::error_text;

namespace {

// NDC depth of the near and far planes, by convention (the definition, restated by hand).
struct hand_range {
  depth_convention c;
  int near_ndc, far_ndc;
};
const hand_range hand_ranges[] = {{depth_convention::gl, -1, 1},
                                  {depth_convention::d3d, 0, 1},
                                  {depth_convention::reverse_z, 1, 0}};

// Exact for rationals; for float and double, within a few units in the last place.
template <class T>
bool same(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, rational>) {
    return a == b;
  } else {
    const T scale = std::max({T(1), std::fabs(a), std::fabs(b)});
    return std::fabs(a - b) <= 8 * std::numeric_limits<T>::epsilon() * scale;
  }
}

template <class T>
std::array<T, 3> ndc(const mat4<T>& M, const T& x, const T& y, const T& z) {
  const vec4<T> v = M * make_point(x, y, z);
  REQUIRE(v[3] != T(0));
  return {T(v[0] / v[3]), T(v[1] / v[3]), T(v[2] / v[3])};
}

template <class T>
void check_ndc(const mat4<T>& M, const T& x, const T& y, const T& z, int ex, int ey, int ez) {
  const auto p = ndc(M, x, y, z);
  INFO("eye point (" << x << ", " << y << ", " << z << ")");
  CHECK(same(p[0], T(ex)));
  CHECK(same(p[1], T(ey)));
  CHECK(same(p[2], T(ez)));
}

// Monotonicity, proved exactly. Along the view axis z_ndc(z) = (a z + b)/(c z + d) with
// (a, b, c, d) = (M22, M23, M32, M33), provided x and y do not enter the depth (M20 = M21 =
// M30 = M31 = 0). For any z1 ≠ z2 away from the pole,
//   z_ndc(z2) − z_ndc(z1) = (a d − b c)(z2 − z1) / ((c z1 + d)(c z2 + d)),
// and c z + d keeps one sign on an interval without its root, so the difference quotient has the
// constant sign of a d − b c there: strictly monotonic iff a d − b c ≠ 0. The test checks the
// hypotheses (no x, y dependence; the root of c z + d outside [z_lo, z_hi]), the sign of
// a d − b c against the direction the convention demands (near → far), and the identity itself
// on points evaluated through the full matrix.
void check_strictly_monotonic(const mat4<rational>& M, const rational& z_lo, const rational& z_hi,
                              int expected_sign) {
  REQUIRE(M(2, 0) == 0);
  REQUIRE(M(2, 1) == 0);
  REQUIRE(M(3, 0) == 0);
  REQUIRE(M(3, 1) == 0);
  const rational a = M(2, 2), b = M(2, 3), c = M(3, 2), d = M(3, 3);
  // c z + d has the same non-zero sign at both ends, hence no root in between (it is affine).
  const rational e_lo = c * z_lo + d, e_hi = c * z_hi + d;
  REQUIRE(e_lo != 0);
  REQUIRE(sgn(e_lo) == sgn(e_hi));
  const rational det = a * d - b * c;
  CHECK(sgn(det) == expected_sign);
  const rational xs[] = {z_lo, (3 * z_lo + z_hi) / 4, (z_lo + z_hi) / 2, z_hi};
  for (const rational& z1 : xs)
    for (const rational& z2 : xs) {
      if (z1 == z2) continue;
      const rational d1 = ndc<rational>(M, q(3), q(-2), z1)[2], d2 = ndc<rational>(M, q(-5), q(7), z2)[2];
      CHECK(rational(d2 - d1) == rational(det * (z2 - z1) / ((c * z1 + d) * (c * z2 + d))));
    }
}

// Outside maps outside, inside maps inside, checked generically: P0 = the mean of the 8 corners
// lies inside the (convex) volume; for every corner and every face centre F, the point
// P0 + (1 + ε)(F − P0) is beyond the volume (past a boundary point on a ray from inside) and
// P0 + (1 − ε)(F − P0) is inside. Corner index bits: 1 = right, 2 = top, 4 = far.
void check_inside_outside(const mat4<rational>& M, const std::array<vec4<rational>, 8>& corners,
                          const std::function<bool(const vec4<rational>&)>& inside) {
  const rational eps = q(1, 1000);
  vec4<rational> P0;
  for (const auto& C : corners) P0 = P0 + rational(1, 8) * C;
  CHECK(inside(M * P0));
  std::vector<vec4<rational>> boundary(corners.begin(), corners.end());
  for (int bit = 1; bit <= 4; bit <<= 1)
    for (int value = 0; value <= 1; ++value) {
      vec4<rational> F;
      for (int i = 0; i < 8; ++i)
        if (((i & bit) != 0) == (value == 1)) F = F + rational(1, 4) * corners[i];
      boundary.push_back(F);
    }
  for (const auto& B : boundary) {
    CHECK(inside(M * B));  // the volume is closed
    CHECK_FALSE(inside(M * (P0 + rational(1 + eps) * (B - P0))));
    CHECK(inside(M * (P0 + rational(1 - eps) * (B - P0))));
  }
}

std::function<bool(const vec4<rational>&)> clip_test(depth_convention c) {
  return [c](const vec4<rational>& v) { return in_clip_volume(v, c); };
}

// Corners of the frustum with near window [l, r] × [b, t] at distance n and far plane at f.
std::array<vec4<rational>, 8> frustum_corners(const rational& l, const rational& r, const rational& b,
                                              const rational& t, const rational& n, const rational& f) {
  std::array<vec4<rational>, 8> c;
  for (int i = 0; i < 8; ++i) {
    const rational s = (i & 4) ? rational(f / n) : rational(1);
    c[i] = make_point<rational>(s * ((i & 1) ? r : l), s * ((i & 2) ? t : b), -s * n);
  }
  return c;
}

// Direction of z_ndc as z_eye grows, by hand: moving from the far plane (smaller z_eye) to the
// near plane (larger z_eye) goes from far_ndc to near_ndc.
int expected_depth_sign(const hand_range& r) { return r.near_ndc > r.far_ndc ? 1 : -1; }

}  // namespace

// ===========================================================================================
// Conventions

TEST_CASE("depth conventions print and parse their CLI names", "[project]") {
  CHECK(to_string(depth_convention::gl) == "gl");
  CHECK(to_string(depth_convention::d3d) == "d3d");
  CHECK(to_string(depth_convention::reverse_z) == "reverse-z");
  for (const auto& r : hand_ranges) CHECK(parse_depth_convention(to_string(r.c)) == r.c);
  CHECK(error_text([] { parse_depth_convention("vulkan"); }) ==
        "[shadowproof.project.convention] unknown depth convention 'vulkan': expected gl, d3d or reverse-z");
}

// ===========================================================================================
// Orthographic

// The box [−2, 6] × [−1, 3] × [−5, −1]: every entry is dyadic (1/4, 1/2, ...), so the float
// instances are exact too.
TEMPLATE_TEST_CASE("orthographic maps the 8 box corners onto the canonical corners", "[project]", rational,
                   double, float) {
  using T = TestType;
  const T l = -2, r = 6, b = -1, t = 3, n = 1, f = 5;
  for (const auto& hr : hand_ranges) {
    INFO("convention " << to_string(hr.c));
    const mat4<T> M = orthographic(l, r, b, t, n, f, hr.c);
    for (int i = 0; i < 8; ++i) {
      const bool right = i & 1, top = i & 2, far = i & 4;
      check_ndc<T>(M, right ? r : l, top ? t : b, far ? T(-f) : T(-n), right ? 1 : -1, top ? 1 : -1,
                   far ? hr.far_ndc : hr.near_ndc);
    }
  }
}

TEST_CASE("orthographic with non-dyadic bounds maps corners exactly and depth monotonically", "[project]") {
  const rational l = q(-1, 3), r = q(2, 7), b = q(-5, 9), t = q(1, 11), n = q(1, 10), f = q(1000);
  for (const auto& hr : hand_ranges) {
    INFO("convention " << to_string(hr.c));
    const mat4<rational> M = orthographic(l, r, b, t, n, f, hr.c);
    for (int i = 0; i < 8; ++i) {
      const bool right = i & 1, top = i & 2, far = i & 4;
      check_ndc<rational>(M, right ? r : l, top ? t : b, far ? rational(-f) : rational(-n), right ? 1 : -1,
                          top ? 1 : -1, far ? hr.far_ndc : hr.near_ndc);
    }
    check_strictly_monotonic(M, -f, -n, expected_depth_sign(hr));
    std::array<vec4<rational>, 8> corners;
    for (int i = 0; i < 8; ++i)
      corners[i] = make_point<rational>((i & 1) ? r : l, (i & 2) ? t : b, (i & 4) ? rational(-f) : rational(-n));
    check_inside_outside(M, corners, clip_test(hr.c));
  }
}

TEST_CASE("orthographic: points just outside each face map outside, inside points inside", "[project]") {
  const rational l = -2, r = 6, b = -1, t = 3, n = 1, f = 5, eps = q(1, 1000);
  for (const auto& hr : hand_ranges) {
    INFO("convention " << to_string(hr.c));
    const mat4<rational> M = orthographic(l, r, b, t, n, f, hr.c);
    CHECK(in_clip_volume(M * make_point<rational>(2, 1, -3), hr.c));  // centre
    CHECK(in_clip_volume(M * make_point<rational>(r, t, -f), hr.c));  // a corner: closed volume
    const vec4<rational> outside[] = {make_point<rational>(l - eps, 1, -3), make_point<rational>(r + eps, 1, -3),
                                      make_point<rational>(2, b - eps, -3), make_point<rational>(2, t + eps, -3),
                                      make_point<rational>(2, 1, -n + eps), make_point<rational>(2, 1, -f - eps)};
    for (const auto& X : outside) CHECK_FALSE(in_clip_volume(M * X, hr.c));
    // Depth beyond near/far lands beyond the near/far NDC value, on the far side of it.
    const rational before_near = ndc<rational>(M, 2, 1, -n + eps)[2];
    const rational beyond_far = ndc<rational>(M, 2, 1, -f - eps)[2];
    CHECK(sgn(rational(before_near - hr.near_ndc)) == sgn(rational(hr.near_ndc - hr.far_ndc)));
    CHECK(sgn(rational(beyond_far - hr.far_ndc)) == sgn(rational(hr.far_ndc - hr.near_ndc)));
  }
}

TEST_CASE("seed 002's S·T equals the gl orthographic matrix", "[project]") {
  const rational l = q(-1, 3), r = q(2, 7), b = q(-5, 9), t = q(1, 11), n = q(1, 10), f = q(7, 2);
  CHECK(orthographic_normalization_seed002(l, r, b, t, n, f) == orthographic(l, r, b, t, n, f, depth_convention::gl));
}

TEST_CASE("seed 002 erratum (column vectors): the printed S·T, with +(f+n)/(f-n) in row 3, misses the near plane", "[project][erratum]") {
  // Box [−1, 1]² × [−3, −1] (n = 1, f = 3): (f+n)/(f−n) = 2, −2/(f−n) = −1.
  const rational n = 1, f = 3;
  const mat4<rational> printed = make_mat4<rational>({1, 0, 0, 0,  //
                                                      0, 1, 0, 0,  //
                                                      0, 0, -1, 2,  //
                                                      0, 0, 0, 1});
  const mat4<rational> ST = orthographic_normalization_seed002<rational>(-1, 1, -1, 1, n, f);
  // The near-plane centre (0, 0, −1): the printed matrix gives z = (−1)(−1) + 2 = 3, outside
  // [−1, 1]; S·T = S(1, 1, −1) T(0, 0, 2) gives −((−1) + 2) = −1, the near plane.
  CHECK(ndc<rational>(printed, 0, 0, -1)[2] == 3);
  CHECK(ndc<rational>(ST, 0, 0, -1)[2] == -1);
  CHECK(ST(2, 3) == -2);
  CHECK(printed != ST);
}

// ===========================================================================================
// Oblique

TEST_CASE("H(θ, φ) sends the projector direction (cot θ, cot φ, 1) to the z axis and fixes z = 0",
          "[project]") {
  const rational ct = q(1, 2), cp = q(-3, 4);
  const mat4<rational> H = oblique_shear(ct, cp);
  CHECK(H * make_vec4<rational>(ct, cp, 1, 0) == make_vec4<rational>(0, 0, 1, 0));
  CHECK(H * make_point<rational>(q(5, 3), -2, 0) == make_point<rational>(q(5, 3), -2, 0));
  CHECK(determinant(H) == 1);
  // The unnormalised projection collapses each projector onto one point of z = 0:
  // X = (1, 2, 4) ↦ (1 − 4·1/2, 2 + 4·3/4, 0) = (−1, 5, 0), and X + 6 d has the same image.
  const mat4<rational> P = oblique_parallel_projection(ct, cp);
  const vec4<rational> X = make_point<rational>(1, 2, 4);
  CHECK(P * X == make_point<rational>(-1, 5, 0));
  CHECK(P * (X + rational(6) * make_vec4<rational>(ct, cp, 1, 0)) == make_point<rational>(-1, 5, 0));
}

TEST_CASE("oblique maps the sheared box's corners onto the canonical corners", "[project]") {
  const rational l = -2, r = 6, b = -1, t = 3, n = q(1, 2), f = 5, ct = q(2, 3), cp = q(-1, 5);
  for (const auto& hr : hand_ranges) {
    INFO("convention " << to_string(hr.c));
    const mat4<rational> M = oblique(l, r, b, t, n, f, ct, cp, hr.c);
    for (int i = 0; i < 8; ++i) {
      const bool right = i & 1, top = i & 2, far = i & 4;
      const rational z = far ? rational(-f) : rational(-n);
      // The volume's corner over box corner (x, y, z) is (x + z cot θ, y + z cot φ, z).
      const rational x = (right ? r : l) + z * ct, y = (top ? t : b) + z * cp;
      check_ndc<rational>(M, x, y, z, right ? 1 : -1, top ? 1 : -1, far ? hr.far_ndc : hr.near_ndc);
    }
    check_strictly_monotonic(M, -f, -n, expected_depth_sign(hr));
    std::array<vec4<rational>, 8> corners;
    for (int i = 0; i < 8; ++i) {
      const rational z = (i & 4) ? rational(-f) : rational(-n);
      corners[i] = make_point<rational>(((i & 1) ? r : l) + z * ct, ((i & 2) ? t : b) + z * cp, z);
    }
    check_inside_outside(M, corners, clip_test(hr.c));
    // The unsheared box corner (r, 1, −f) is outside: H moves its x to r − (−5)(2/3) = r + 10/3,
    // past the right face.
    CHECK_FALSE(in_clip_volume(M * make_point<rational>(r, 1, -f), hr.c));
  }
}

TEST_CASE("seed 002's normalised oblique M_orth·S·T·H maps the sheared box onto the square at z = 0",
          "[project]") {
  const rational l = -2, r = 6, b = -1, t = 3, n = q(1, 2), f = 5, ct = q(2, 3), cp = q(-1, 5);
  const mat4<rational> P = oblique_normalized_projection_seed002(l, r, b, t, n, f, ct, cp);
  for (int i = 0; i < 8; ++i) {
    const bool right = i & 1, top = i & 2, far = i & 4;
    const rational z = far ? rational(-f) : rational(-n);
    check_ndc<rational>(P, (right ? r : l) + z * ct, (top ? t : b) + z * cp, z, right ? 1 : -1, top ? 1 : -1, 0);
  }
}

// ===========================================================================================
// Perspective

TEST_CASE("seed 002's N(α, β) normalises the 45° frustum", "[project]") {
  // n = 1, f = 3: α = (1+3)/(1−3) = −2, β = 2·3/(1−3) = −3.
  const mat4<rational> N = perspective_normalization<rational>(1, 3);
  CHECK(N == make_mat4<rational>({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0}));
  // Corners of |x|, |y| ≤ −z, z ∈ [−3, −1] go to (±1, ±1, ∓1) with near → −1, far → 1.
  for (int i = 0; i < 8; ++i) {
    const bool right = i & 1, top = i & 2, far = i & 4;
    const rational s = far ? 3 : 1;
    check_ndc<rational>(N, right ? s : rational(-s), top ? s : rational(-s), -s, right ? 1 : -1, top ? 1 : -1,
                        far ? 1 : -1);
  }
  check_strictly_monotonic(N, -3, -1, -1);
  check_inside_outside(N, frustum_corners(-1, 1, -1, 1, 1, 3), clip_test(depth_convention::gl));
}

TEMPLATE_TEST_CASE("frustum maps the 8 frustum corners onto the canonical corners", "[project]", rational, double,
                   float) {
  using T = TestType;
  // Near window [−1, 3] × [−2, 2] at n = 2, far plane f = 6: the far window is 3 times larger.
  const T l = -1, r = 3, b = -2, t = 2, n = 2, f = 6;
  for (const auto& hr : hand_ranges) {
    INFO("convention " << to_string(hr.c));
    const mat4<T> M = frustum(l, r, b, t, n, f, hr.c);
    for (int i = 0; i < 8; ++i) {
      const bool right = i & 1, top = i & 2, far = i & 4;
      const T s = far ? T(3) : T(1);
      check_ndc<T>(M, s * (right ? r : l), s * (top ? t : b), far ? T(-f) : T(-n), right ? 1 : -1, top ? 1 : -1,
                   far ? hr.far_ndc : hr.near_ndc);
    }
  }
}

TEMPLATE_TEST_CASE("perspective maps the 8 frustum corners onto the canonical corners", "[project]", rational,
                   double, float) {
  using T = TestType;
  // c = 2, aspect = 2, n = 1, f = 3: near window top = n/c = 1/2, right = top·aspect = 1; the
  // far window is 3 times larger. Dyadic throughout, so float and double stay close to exact.
  const T c = 2, aspect = 2, n = 1, f = 3, top = T(1) / T(2), right = 1;
  for (const auto& hr : hand_ranges) {
    INFO("convention " << to_string(hr.c));
    const mat4<T> M = perspective(c, aspect, n, f, hr.c);
    for (int i = 0; i < 8; ++i) {
      const bool rt = i & 1, tp = i & 2, far = i & 4;
      const T s = far ? T(3) : T(1);
      check_ndc<T>(M, s * (rt ? right : T(-right)), s * (tp ? top : T(-top)), far ? T(-f) : T(-n), rt ? 1 : -1,
                   tp ? 1 : -1, far ? hr.far_ndc : hr.near_ndc);
    }
  }
}

TEST_CASE("frustum and perspective with awkward rationals: corners exact, depth strictly monotonic",
          "[project]") {
  const rational n = q(1, 10), f = q(1000, 3), c = q(12, 5), aspect = q(16, 9);
  const rational top = n / c, right = top * aspect;  // near-plane window of gluPerspective
  for (const auto& hr : hand_ranges) {
    INFO("convention " << to_string(hr.c));
    const mat4<rational> P = perspective(c, aspect, n, f, hr.c);
    const mat4<rational> F = frustum(q(-1, 7), q(5, 3), q(-2, 9), q(1, 4), n, f, hr.c);
    for (int i = 0; i < 8; ++i) {
      const bool rt = i & 1, tp = i & 2, far = i & 4;
      const rational s = far ? rational(f / n) : rational(1);
      const int ex = rt ? 1 : -1, ey = tp ? 1 : -1, ez = far ? hr.far_ndc : hr.near_ndc;
      check_ndc<rational>(P, s * (rt ? right : rational(-right)), s * (tp ? top : rational(-top)), -s * n, ex, ey,
                          ez);
      check_ndc<rational>(F, s * (rt ? q(5, 3) : q(-1, 7)), s * (tp ? q(1, 4) : q(-2, 9)), -s * n, ex, ey, ez);
    }
    check_strictly_monotonic(P, -f, -n, expected_depth_sign(hr));
    check_strictly_monotonic(F, -f, -n, expected_depth_sign(hr));
    check_inside_outside(P, frustum_corners(-right, right, -top, top, n, f), clip_test(hr.c));
    check_inside_outside(F, frustum_corners(q(-1, 7), q(5, 3), q(-2, 9), q(1, 4), n, f), clip_test(hr.c));
  }
}

TEST_CASE("perspective in each convention has the textbook depth rows", "[project]") {
  // n = 1, f = 3, by hand from the published formulas:
  //   gl (glFrustum): −(f+n)/(f−n) = −2, −2fn/(f−n) = −3
  //   d3d (Vulkan right-handed, depth [0, 1]): −f/(f−n) = −3/2, −fn/(f−n) = −3/2
  //   reverse-z: n/(f−n) = 1/2, fn/(f−n) = 3/2
  //   infinite far: gl (−1, −2n) = (−1, −2); d3d (−1, −n) = (−1, −1); reverse-z (0, n) = (0, 1)
  struct row { depth_convention c; bool inf; rational a, b; };
  const row rows[] = {{depth_convention::gl, false, -2, -3},
                      {depth_convention::d3d, false, q(-3, 2), q(-3, 2)},
                      {depth_convention::reverse_z, false, q(1, 2), q(3, 2)},
                      {depth_convention::gl, true, -1, -2},
                      {depth_convention::d3d, true, -1, -1},
                      {depth_convention::reverse_z, true, 0, 1}};
  for (const auto& x : rows) {
    INFO(to_string(x.c) << (x.inf ? " infinite far" : ""));
    const mat4<rational> M = perspective<rational>(2, q(3, 2), 1, 3, x.c, x.inf);
    CHECK(M == make_mat4<rational>({q(4, 3), 0, 0, 0, 0, 2, 0, 0, 0, 0, x.a, x.b, 0, 0, -1, 0}));
  }
}

TEST_CASE("infinite far: near corners exact, the view direction reaches the far depth, depth monotonic",
          "[project]") {
  const rational n = q(1, 10), c = q(3, 2), aspect = q(4, 3);
  const rational top = n / c, right = top * aspect;
  for (const auto& hr : hand_ranges) {
    INFO("convention " << to_string(hr.c));
    const mat4<rational> M = perspective(c, aspect, n, rational(0), hr.c, true);
    for (int i = 0; i < 4; ++i)
      check_ndc<rational>(M, i & 1 ? right : rational(-right), i & 2 ? top : rational(-top), -n, i & 1 ? 1 : -1,
                          i & 2 ? 1 : -1, hr.near_ndc);
    // Points at infinity along the edges of the frustum: (±right/n, ±top/n, −1, 0).
    for (int i = 0; i < 4; ++i) {
      const vec4<rational> edge = make_vec4<rational>(i & 1 ? rational(right / n) : rational(-right / n),
                                                     i & 2 ? rational(top / n) : rational(-top / n), -1, 0);
      const auto p = ndc_of(M * edge);
      REQUIRE(p);
      CHECK((*p)[0] == (i & 1 ? 1 : -1));
      CHECK((*p)[1] == (i & 2 ? 1 : -1));
      CHECK((*p)[2] == hr.far_ndc);
    }
    // Strictly monotonic on the whole ray [−10¹², −n]; a point 10¹² away is still inside, short
    // of the far depth.
    check_strictly_monotonic(M, rational(-1000000000000), -n, expected_depth_sign(hr));
    const vec4<rational> distant = M * make_point<rational>(0, 0, -1000000000000);
    CHECK(in_clip_volume(distant, hr.c));
    CHECK((*ndc_of(distant))[2] != hr.far_ndc);
  }
}

TEST_CASE("perspective: points outside the frustum, or behind the eye, map outside", "[project]") {
  const rational n = 1, f = 10, c = 1, aspect = 2, eps = q(1, 1000);
  // Near window [−2, 2] × [−1, 1] at distance 1; at distance 5: [−10, 10] × [−5, 5].
  for (const auto& hr : hand_ranges) {
    INFO("convention " << to_string(hr.c));
    const mat4<rational> M = perspective(c, aspect, n, f, hr.c);
    CHECK(in_clip_volume(M * make_point<rational>(0, 0, -5), hr.c));
    CHECK(in_clip_volume(M * make_point<rational>(10, -5, -5), hr.c));
    const vec4<rational> outside[] = {
        make_point<rational>(10 + eps, 0, -5), make_point<rational>(-10 - eps, 0, -5),
        make_point<rational>(0, 5 + eps, -5),  make_point<rational>(0, -5 - eps, -5),
        make_point<rational>(0, 0, -1 + eps),  make_point<rational>(0, 0, -10 - eps),
        make_point<rational>(0, 0, 5),  // behind the eye
        make_point<rational>(0, 0, 0)};
    for (const auto& X : outside) CHECK_FALSE(in_clip_volume(M * X, hr.c));
  }
  // Behind the eye the division alone folds points back: (1, 0, 2) has x_clip = 1/2 and
  // w = −2, so x_ndc = −1/4 ∈ [−1, 1]; only the sign of w tells it is behind the eye.
  const mat4<rational> G = perspective(c, aspect, n, f, depth_convention::gl);
  const vec4<rational> behind = G * make_point<rational>(1, 0, 2);
  CHECK((*ndc_of(behind))[0] == q(-1, 4));
  CHECK(behind[3] == -2);
}

TEST_CASE("perspective_normalization is the gl frustum of the 45° frustum", "[project]") {
  const rational n = q(2, 5), f = q(7, 3);
  CHECK(perspective_normalization(n, f) == frustum<rational>(-n, n, -n, n, n, f, depth_convention::gl));
}

// ===========================================================================================
// GAMES101

TEST_CASE("GAMES101 persp->ortho fixes the near plane and the far centre, keeps z = f", "[project]") {
  const rational n = q(-1, 2), f = -7;
  const mat4<rational> M = games101_persp_to_ortho(n, f);
  // Row 3 = (0, 0, n + f, −n f) = (0, 0, −15/2, −7/2).
  CHECK(M == make_mat4<rational>({n, 0, 0, 0, 0, n, 0, 0, 0, 0, q(-15, 2), q(-7, 2), 0, 0, 1, 0}));
  CHECK(proportional(M * make_point<rational>(3, -4, n), make_point<rational>(3, -4, n)));
  CHECK(proportional(M * make_point<rational>(0, 0, f), make_point<rational>(0, 0, f)));
  // A far-plane point off the axis is squeezed towards the axis by n/f but stays at z = f.
  CHECK(ndc<rational>(M, 14, 7, f) == std::array<rational, 3>{1, q(1, 2), f});
}

TEST_CASE("seed 004 erratum (column vectors): the printed persp->ortho third row (0, 0, nf, -nf) is wrong", "[project][erratum]") {
  // n = −1, f = −2, so nf = 2 and n + f = −3. The near-plane centre (0, 0, −1, 1):
  //   printed row: 2·(−1) − 2 = −4, w = −1 → z = 4, not n = −1;
  //   correct row: (−3)(−1) − 2 = 1,  w = −1 → z = −1 = n.
  const rational n = -1, f = -2;
  CHECK(ndc<rational>(games101_persp_to_ortho_as_printed(n, f), 0, 0, n)[2] == 4);
  CHECK(ndc<rational>(games101_persp_to_ortho(n, f), 0, 0, n)[2] == -1);
  // Far centre (0, 0, −2): printed 2·(−2) − 2 = −6, w = −2 → 3, not f = −2.
  CHECK(ndc<rational>(games101_persp_to_ortho_as_printed(n, f), 0, 0, f)[2] == 3);
  CHECK(ndc<rational>(games101_persp_to_ortho(n, f), 0, 0, f)[2] == -2);
}

TEST_CASE("GAMES101 projection maps the frustum corners to the cube, near → +1, far → -1", "[project]") {
  const rational n = q(-1, 10), f = -50, c = q(5, 2), aspect = q(16, 9);
  const rational top = -n / c, right = top * aspect;  // near window half-sizes, by hand
  const mat4<rational> M = games101_projection(n, f, c, aspect);
  for (int i = 0; i < 8; ++i) {
    const bool rt = i & 1, tp = i & 2, far = i & 4;
    const rational s = far ? rational(f / n) : rational(1);
    check_ndc<rational>(M, s * (rt ? right : rational(-right)), s * (tp ? top : rational(-top)), far ? f : n,
                        rt ? 1 : -1, tp ? 1 : -1, far ? -1 : 1);
  }
  // z_ndc increases with z_eye (near, the larger z, goes to +1).
  check_strictly_monotonic(M, f, n, 1);
  // In front of the eye GAMES101 has w = z_eye < 0: inside means w < 0 and NDC in [−1, 1]³.
  const auto games101_inside = [](const vec4<rational>& v) {
    if (!(v[3] < 0)) return false;
    for (int i = 0; i < 3; ++i)
      if (v[i] / v[3] < -1 || v[i] / v[3] > 1) return false;
    return true;
  };
  check_inside_outside(M, frustum_corners(-right, right, -top, top, rational(-n), rational(-f)), games101_inside);
  // Same projective map as the gl perspective with the NDC depth negated.
  CHECK(proportional(M, scaling<rational>(1, 1, -1) * perspective(c, aspect, rational(-n), rational(-f),
                                                                    depth_convention::gl)));
}

// ===========================================================================================
// Bad input

TEST_CASE("degenerate volumes and misplaced planes are errors naming the culprit", "[project]") {
  const auto gl = depth_convention::gl;
  CHECK(error_text([&] { orthographic<rational>(1, 1, 0, 1, 1, 2, gl); }) ==
        "[shadowproof.project.degenerate_volume] left = right = 1: the view volume has zero width, no "
        "projection maps it onto a cube");
  CHECK(error_text([&] { orthographic<rational>(0, 1, q(1, 3), q(1, 3), 1, 2, gl); }) ==
        "[shadowproof.project.degenerate_volume] bottom = top = 1/3: the view volume has zero height, no "
        "projection maps it onto a cube");
  CHECK(error_text([&] { frustum<rational>(-1, 1, -1, 1, 2, 2, gl); }) ==
        "[shadowproof.project.degenerate_volume] near = far = 2: the view volume has zero depth, no "
        "projection maps it onto a cube");
  CHECK(error_text([&] { perspective_normalization<rational>(3, 3); }) ==
        "[shadowproof.project.degenerate_volume] near = far = 3: the view volume has zero depth, no "
        "projection maps it onto a cube");
  CHECK(error_text([&] { frustum<rational>(-1, 1, -1, 1, 0, 2, gl); }) ==
        "[shadowproof.project.near_not_positive] near = 0 must be > 0: the near plane of a perspective "
        "projection lies in front of the eye");
  CHECK(error_text([&] { perspective<rational>(1, 1, 1, -5, gl); }) ==
        "[shadowproof.project.far_not_positive] far = -5 must be > 0: the far plane of a perspective "
        "projection lies in front of the eye");
  CHECK(error_text([&] { perspective<rational>(0, 1, 1, 5, gl); }) ==
        "[shadowproof.project.focal_not_positive] cot(fovy/2) = 0 must be > 0: the field of view must lie "
        "in (0°, 180°)");
  CHECK(error_text([&] { games101_projection<rational>(1, -5, 1, 1); }) ==
        "[shadowproof.project.games101_sign] near = 1 must be < 0: GAMES101 looks down −z and takes the z "
        "coordinates of the planes, not their distances");
  // An infinite far plane ignores f, so f = 0 is no error there.
  CHECK(error_text([&] { perspective<rational>(1, 1, 1, 0, gl, true); }) == "no error");
}
