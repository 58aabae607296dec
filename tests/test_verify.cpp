// The grader: metrics on hand-made cases (expected values derived by hand), convention mapping,
// the case protocol, and the filtered oracle agreeing exactly with the all-rational one.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "shadowproof/core/error.h"
#include "shadowproof/constructions/look_at.h"
#include "shadowproof/constructions/normal_matrix.h"
#include "shadowproof/constructions/project.h"
#include "shadowproof/constructions/reflect.h"
#include "shadowproof/constructions/shadow.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/protocol.h"

using namespace shadowproof;

namespace {

test_case make_case(operation op, scalar_type type, std::vector<double> inputs) {
  test_case c;
  c.op = op;
  c.type = type;
  c.inputs = std::move(inputs);
  return c;
}

// Receiver y = 1, i.e. P = (0, 1, 0, −1); directional light L = (1, 2, 3, 0), P·L = 2.
// By hand, M = 2 I − L Pᵀ with L Pᵀ = [0 1 0 −1; 0 2 0 −2; 0 3 0 −3; 0 0 0 0]:
const std::vector<double> ground_inputs{0, 1, 0, -1, 1, 2, 3, 0};
const std::vector<double> ground_matrix{2, -1, 0, 1,  //
                                        0, 0, 0, 2,   //
                                        0, -3, 2, 3,  //
                                        0, 0, 0, 2};

std::vector<double> transposed(const std::vector<double>& m) {
  std::vector<double> t(16);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) t[c * 4 + r] = m[r * 4 + c];
  return t;
}

}  // namespace

TEST_CASE("an output off by exactly one ulp grades as 1 ulp and 1 bit", "[verify]") {
  const test_case c = make_case(operation::shadow_matrix, scalar_type::f32, ground_inputs);
  std::vector<double> out = ground_matrix;
  out[0] = static_cast<double>(std::nextafter(2.0f, 3.0f));  // 2 + 2^-22
  const case_grade g = grade_case(c, conventions{}, out.data());
  CHECK(g.max_ulps == 1);
  CHECK(g.max_bits == 1.0);
  CHECK(g.worst_output == 0);
  CHECK(g.outputs[0].reference == 2.0);
  CHECK(g.outputs[0].relative == std::ldexp(1.0, -23));
  for (std::size_t i = 1; i < 16; ++i) CHECK(g.outputs[i].ulps == 0);
  CHECK(g.nonfinite == 0);
}

TEST_CASE("an exact tie between two floats rounds to even in both oracles", "[verify]") {
  // P = (0, 1, 2^-12, 0), L = (1, 1, 2^-12, 0): P·L = 1 + 2^-24, exactly halfway between the
  // floats 1 and 1 + 2^-23, and entry (0,0) = P·L − L₀P₀ = 1 + 2^-24. Ties go to even: 1.
  const double t = std::ldexp(1.0, -12);
  const test_case c = make_case(operation::shadow_matrix, scalar_type::f32, {0, 1, t, 0, 1, 1, t, 0});
  std::vector<double> out(16, 0.0);
  out[0] = 1.0;
  for (oracle_mode mode : {oracle_mode::filtered, oracle_mode::naive}) {
    const case_grade g = grade_case(c, conventions{}, out.data(), mode);
    CHECK(g.outputs[0].reference == 1.0);
    CHECK(g.outputs[0].ulps == 0);
  }
  out[0] = 1.0 + std::ldexp(1.0, -23);
  CHECK(grade_case(c, conventions{}, out.data()).outputs[0].ulps == 1);
}

TEST_CASE("the exact matrix itself grades as correctly rounded", "[verify]") {
  const test_case c = make_case(operation::shadow_matrix, scalar_type::f64, ground_inputs);
  const case_grade g = grade_case(c, conventions{}, ground_matrix.data());
  CHECK(g.max_ulps == 0);
  CHECK(g.max_bits == 0.0);
}

TEST_CASE("a NaN where the exact value is finite counts as non-finite, not as ulps", "[verify]") {
  const test_case c = make_case(operation::shadow_matrix, scalar_type::f32, ground_inputs);
  std::vector<double> out = ground_matrix;
  out[7] = std::numeric_limits<double>::quiet_NaN();
  out[11] = std::numeric_limits<double>::infinity();
  const case_grade g = grade_case(c, conventions{}, out.data());
  CHECK(g.nonfinite == 2);
  CHECK(g.outputs[7].nonfinite);
  CHECK_FALSE(g.outputs[7].counted());
  CHECK(g.max_ulps == 0);
  CHECK(g.worst_output == 7);
}

TEST_CASE("transposed storage is a convention: exact when declared, wrong when not", "[verify]") {
  const test_case c = make_case(operation::shadow_matrix, scalar_type::f32, ground_inputs);
  const std::vector<double> out = transposed(ground_matrix);
  conventions column_major;
  column_major.storage = storage_order::column_major;
  CHECK(grade_case(c, column_major, out.data()).max_ulps == 0);
  // Row vectors stored row-major are the same memory as column vectors stored column-major.
  conventions row_vectors;
  row_vectors.vectors = vector_side::row;
  CHECK(grade_case(c, row_vectors, out.data()).max_ulps == 0);
  // Undeclared, the transposition is a real error: entry (0,1) is 0 where −1 is exact.
  const case_grade wrong = grade_case(c, conventions{}, out.data());
  CHECK(wrong.max_ulps > 0);
  CHECK(wrong.outputs[1].reference == -1.0);
  CHECK(wrong.outputs[1].got == 0.0);
}

TEST_CASE("a light given along its rays is a convention: −M grades as exact when declared", "[verify]") {
  const test_case c = make_case(operation::shadow_matrix, scalar_type::f64, ground_inputs);
  std::vector<double> out = ground_matrix;
  for (double& x : out) x = -x;  // M(P, −L) = −(P·L) I + L Pᵀ = −M
  conventions along;
  along.light = light_sign::along_rays;
  CHECK(grade_case(c, along, out.data()).max_ulps == 0);
  CHECK(grade_case(c, conventions{}, out.data()).max_ulps > 0);
}

TEST_CASE("a homogeneous result is graded up to its scale, fixed by the largest exact entry", "[verify]") {
  const test_case c = make_case(operation::shadow_matrix, scalar_type::f32, ground_inputs);
  std::vector<double> out = ground_matrix;
  for (double& x : out) x *= -0.75;  // exact in float
  conventions homogeneous;
  homogeneous.homogeneous = true;
  const case_grade g = grade_case(c, homogeneous, out.data());
  CHECK(g.max_ulps == 0);
  // |−3| at (2,1) is the largest exact entry (row-major index 9).
  REQUIRE(g.scale_pivot);
  CHECK(*g.scale_pivot == 9);
  CHECK(grade_case(c, conventions{}, out.data()).max_ulps > 0);
  // A scale does not hide a real error in another entry.
  out[3] = std::nextafter(static_cast<float>(out[3]), 10.0f);
  CHECK(grade_case(c, homogeneous, out.data()).max_ulps == 1);
}

TEST_CASE("an image on the wrong side of the receiver is a flipped class", "[verify]") {
  // Receiver y = 0, light towards +y, V = (1, 2, 3): s = P·L = 1, t = P·V = 2, a real shadow
  // at s V − t L = (1, 0, 3).
  const test_case c = make_case(operation::shadow_point, scalar_type::f32, {0, 1, 0, 0, 0, 1, 0, 0, 1, 2, 3});
  const std::vector<double> right{1, 0, 3};
  const case_grade good = grade_case(c, conventions{}, right.data());
  REQUIRE(good.exact_class);
  CHECK(*good.exact_class == point_class::shadow);
  CHECK(*good.got_class == image_class::shadow);
  CHECK_FALSE(good.misclassified);
  CHECK(good.max_ulps == 0);
  CHECK(*good.plane_value == 0.0);
  // (1, 4, 3) lies beyond V, away from the light: the image of a point behind the receiver.
  const std::vector<double> flipped{1, 4, 3};
  const case_grade bad = grade_case(c, conventions{}, flipped.data());
  CHECK(bad.misclassified);
  CHECK(*bad.got_class == image_class::behind_receiver);
  CHECK(*bad.plane_value == 4.0);
}

TEST_CASE("a finite image where none exists is garbage; infinity there is fine", "[verify]") {
  // Light parallel to the receiver y = 0 and V off it: s = 0, t = 1, no image.
  const test_case c = make_case(operation::shadow_point, scalar_type::f64, {0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0});
  const std::vector<double> finite{1e30, 0, 0};
  const case_grade g = grade_case(c, conventions{}, finite.data());
  CHECK(*g.exact_class == point_class::light_parallel);
  CHECK(g.garbage == 3);
  CHECK_FALSE(g.misclassified);
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> infinite{inf, -inf, std::nan("")};
  const case_grade h = grade_case(c, conventions{}, infinite.data());
  CHECK(h.garbage == 0);
  CHECK(h.nonfinite == 0);
}

TEST_CASE("a point on the receiver is its own shadow even when the light is parallel to it", "[verify]") {
  // Receiver y = 0, directional light (1, 0, 0, 0) parallel to it, V = (3, 0, 5) on it:
  // s = P·L = 0 and t = P·V = 0 (exact class line_in_plane). The line from V towards the light
  // lies in the receiver and meets it at V, so the exact image is V = (3, 0, 5).
  for (scalar_type type : {scalar_type::f32, scalar_type::f64})
    for (oracle_mode mode : {oracle_mode::filtered, oracle_mode::naive}) {
      INFO("type " << to_string(type) << (mode == oracle_mode::naive ? ", naive" : ", filtered"));
      const test_case c = make_case(operation::shadow_point, type, {0, 1, 0, 0, 1, 0, 0, 0, 3, 0, 5});
      const std::vector<double> itself{3, 0, 5};
      const case_grade good = grade_case(c, conventions{}, itself.data(), mode);
      REQUIRE(good.exact_class);
      CHECK(*good.exact_class == point_class::line_in_plane);  // kept for reporting
      CHECK(good.outputs[0].exact_defined);
      CHECK(good.outputs[0].reference == 3.0);
      CHECK(good.outputs[1].reference == 0.0);
      CHECK(good.outputs[2].reference == 5.0);
      CHECK(good.max_ulps == 0);
      CHECK(good.garbage == 0);
      CHECK(*good.got_class == image_class::on_receiver);
      CHECK_FALSE(good.misclassified);
      CHECK(*good.plane_value == 0.0);
      // NaN there (what (P·L) V − (P·V) L = 0 divided by its w = 0 gives) is a failure.
      const double nan = std::numeric_limits<double>::quiet_NaN();
      const std::vector<double> undefined{nan, nan, nan};
      const case_grade bad = grade_case(c, conventions{}, undefined.data(), mode);
      CHECK(bad.nonfinite == 3);
      CHECK(bad.garbage == 0);
      CHECK(*bad.got_class == image_class::nonfinite);
      CHECK(bad.v == verdict::nonfinite);  // V exists and no division is involved
      CHECK_FALSE(bad.misclassified);      // a NaN is on no side: its verdict says it
      // One float step along the receiver is one ulp, not a class change.
      const double next = type == scalar_type::f32 ? double(std::nextafter(5.0f, 6.0f)) : std::nextafter(5.0, 6.0);
      const std::vector<double> off{3, 0, next};
      const case_grade near = grade_case(c, conventions{}, off.data(), mode);
      CHECK(near.max_ulps == 1);
      CHECK(near.worst_output == 2);
      CHECK_FALSE(near.misclassified);
    }
}

TEST_CASE("a flat view volume leaves only the entries dividing by its zero extent undefined", "[verify]") {
  // ortho with b = t = 1: row 1's scale 2/(t−b) and offset −(t+b)/(t−b) do not exist.
  const test_case c = make_case(operation::ortho, scalar_type::f64, {-1, 1, 1, 1, 1, 3});
  // By hand (gl): [1 0 0 0; 0 ? 0 ?; 0 0 −1 −2; 0 0 0 1].
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> out{1, 0, 0, 0, 0, inf, 0, -inf, 0, 0, -1, -2, 0, 0, 0, 1};
  const case_grade g = grade_case(c, conventions{}, out.data());
  CHECK(g.max_ulps == 0);
  CHECK(g.garbage == 0);
  CHECK(g.nonfinite == 0);
  CHECK_FALSE(g.outputs[5].exact_defined);
  CHECK_FALSE(g.outputs[7].exact_defined);
  CHECK(g.outputs[10].exact_defined);
}

TEST_CASE("perspective from cot(fovy/2): the hand-derived matrix is exact, a flat depth range undefines only A and B",
          "[verify]") {
  // c = cot(fovy/2) = 2 (fovy ≈ 53.13°), aspect 2, n = 1, f = 3, gl depth: c/aspect = 1,
  // A = −(f+n)/(f−n) = −2, B = −2fn/(f−n) = −3, by hand.
  const test_case c = make_case(operation::perspective, scalar_type::f32, {2, 2, 1, 3});
  const std::vector<double> by_hand{1, 0, 0, 0, 0, 2, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0};
  const case_grade g = grade_case(c, conventions{}, by_hand.data());
  CHECK(g.max_ulps == 0);
  CHECK(g.nonfinite + g.garbage == 0);
  // d3d depth: A = −f/(f−n) = −3/2, B = −fn/(f−n) = −3/2.
  conventions d3d;
  d3d.depth = depth_convention::d3d;
  std::vector<double> in_d3d = by_hand;
  in_d3d[10] = -1.5;
  in_d3d[11] = -1.5;
  CHECK(grade_case(c, d3d, in_d3d.data()).max_ulps == 0);
  CHECK(grade_case(c, d3d, by_hand.data()).max_ulps > 0);
  // One float step on c/aspect is one ulp.
  std::vector<double> off = by_hand;
  off[0] = std::nextafter(1.0f, 2.0f);
  const case_grade one = grade_case(c, conventions{}, off.data());
  CHECK(one.max_ulps == 1);
  CHECK(one.worst_output == 0);
  // n = f: only row 2's A and B divide by f − n = 0; infinity there is a correct rejection,
  // a finite number is garbage, the other entries are still graded.
  const test_case flat = make_case(operation::perspective, scalar_type::f32, {2, 2, 1, 1});
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> rejected = by_hand;
  rejected[10] = -inf;
  rejected[11] = -inf;
  const case_grade r = grade_case(flat, conventions{}, rejected.data());
  CHECK(r.garbage == 0);
  CHECK(r.nonfinite == 0);
  CHECK(r.max_ulps == 0);
  CHECK_FALSE(r.outputs[10].exact_defined);
  CHECK_FALSE(r.outputs[11].exact_defined);
  CHECK(grade_case(flat, conventions{}, by_hand.data()).garbage == 2);
  // A near plane behind the eye admits no projection at all.
  const test_case behind = make_case(operation::perspective, scalar_type::f32, {2, 2, -1, 3});
  CHECK(grade_case(behind, conventions{}, by_hand.data()).garbage == 16);
}

TEST_CASE("perspective from a field of view: cot of the float nearest pi/2 rounds as derived by hand",
          "[verify][camera]") {
  // fovy = 13176795·2^-23, the float nearest π/2, lies δ = 4.3711390001862…e-8 above π/2, so
  // cot(fovy/2) = cot(π/4 + δ/2) = (1 − tan(δ/2))/(1 + tan(δ/2)) = 1 − δ + δ²/2 − … ≈
  // 1 − 4.37113900e-8. Floats below 1 are 2^-24 = 5.96e-8 apart: 1 − 4.37e-8 is beyond the
  // midpoint 1 − 2.98e-8, so the float is 1 − 2^-24. aspect 1, n = 1, f = 3 (gl): A = −2, B = −3.
  const double fovy = 13176795.0 / 8388608.0;
  const float c32 = 1.0f - std::ldexp(1.0f, -24);
  const test_case c = make_case(operation::perspective_fov, scalar_type::f32, {fovy, 1, 1, 3});
  std::vector<double> by_hand{c32, 0, 0, 0, 0, c32, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0};
  CHECK(grade_case(c, conventions{}, by_hand.data()).max_ulps == 0);
  // 1, the value a careless evaluation of cot(π/4) gives, is one ulp off.
  std::vector<double> one = by_hand;
  one[0] = one[5] = 1;
  CHECK(grade_case(c, conventions{}, one.data()).max_ulps == 1);
  // In double, an independent evaluation with the C library's long double tan: the rounding
  // to double is safe when that value is far from a midpoint between two doubles.
  const long double c_ld = 1.0L / std::tan(static_cast<long double>(fovy) / 2);
  const double c64 = static_cast<double>(c_ld);
  const long double ulp64 = std::ldexp(1.0L, -53);  // doubles in [1/2, 1) are 2^-53 apart
  const long double to_midpoint = std::fabs(std::fabs(c_ld - c64) - ulp64 / 2);
  REQUIRE(to_midpoint > ulp64 / 1000);
  const test_case c_f64 = make_case(operation::perspective_fov, scalar_type::f64, {fovy, 1, 1, 3});
  std::vector<double> in_double = by_hand;
  in_double[0] = in_double[5] = c64;
  CHECK(grade_case(c_f64, conventions{}, in_double.data()).max_ulps == 0);
}

TEST_CASE("perspective from degrees: cot 45° is exactly 1 and cot 30° rounds as sqrt(3) does", "[verify][camera]") {
  conventions degrees;
  degrees.angle = angle_unit::degrees;
  // 90°, aspect 2, n = 1, f = 3: c = 1, c/aspect = 1/2, exactly.
  const test_case right_angle = make_case(operation::perspective_fov, scalar_type::f32, {90, 2, 1, 3});
  const std::vector<double> exact{0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0};
  CHECK(grade_case(right_angle, degrees, exact.data()).max_ulps == 0);
  // 60°: cot 30° = √3, correctly rounded by IEEE sqrt (independent of the oracle).
  for (scalar_type t : {scalar_type::f32, scalar_type::f64}) {
    const double root3 = t == scalar_type::f32 ? static_cast<double>(std::sqrt(3.0f)) : std::sqrt(3.0);
    const test_case sixty = make_case(operation::perspective_fov, t, {60, 1, 1, 3});
    const std::vector<double> m{root3, 0, 0, 0, 0, root3, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0};
    CHECK(grade_case(sixty, degrees, m.data()).max_ulps == 0);
  }
  // The same inputs read as radians are no camera at all: 90 radians is past a half turn.
  CHECK(grade_case(right_angle, conventions{}, exact.data()).garbage == 16);
}

TEST_CASE("a left-handed projection negates column 2; the infinite far plane takes the limit", "[verify][camera]") {
  // 90°, aspect 1, n = 1, far at infinity, d3d depth: A = −z_far = −1, B = n (z_near − z_far) = −1;
  // left-handed: column 2 negated, so A = 1 and the w row reads (0, 0, 1, 0).
  conventions lh;
  lh.angle = angle_unit::degrees;
  lh.depth = depth_convention::d3d;
  lh.hand = handedness::left;
  const test_case c = make_case(operation::perspective_fov_infinite, scalar_type::f32, {90, 1, 1});
  const std::vector<double> by_hand{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -1, 0, 0, 1, 0};
  CHECK(grade_case(c, lh, by_hand.data()).max_ulps == 0);
  conventions rh = lh;
  rh.hand = handedness::right;
  CHECK(grade_case(c, rh, by_hand.data()).max_ulps > 1000);
  // ortho left-handed: box [−1, 1]² × near 1, far 3, gl: (2,2) = −2/(f−n) = −1 → +1.
  const test_case box = make_case(operation::ortho, scalar_type::f32, {-1, 1, -1, 1, 1, 3});
  conventions lh_gl;
  lh_gl.hand = handedness::left;
  const std::vector<double> ortho_lh{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -2, 0, 0, 0, 1};
  CHECK(grade_case(box, lh_gl, ortho_lh.data()).max_ulps == 0);
}

TEST_CASE("look-at and target-to: square roots rounded as IEEE sqrt rounds them, degenerate axes undefined",
          "[verify][camera]") {
  // eye (1, 0, 1), target 0, up (0, 1, 0), right-handed: w = (1, 0, 1), X = up × w = (1, 0, −1),
  // Y = w × X = (0, 2, 0); rows x = (1, 0, −1)/√2, y = (0, 1, 0), z = (1, 0, 1)/√2, and the
  // translations −x·eye = 0, −y·eye = 0, −z·eye = −2/√2 = −√2 (by hand).
  for (scalar_type t : {scalar_type::f32, scalar_type::f64}) {
    const bool f32 = t == scalar_type::f32;
    const double h = f32 ? static_cast<double>(std::sqrt(0.5f)) : std::sqrt(0.5);
    const double r2 = f32 ? static_cast<double>(std::sqrt(2.0f)) : std::sqrt(2.0);
    const test_case c = make_case(operation::look_at, t, {1, 0, 1, 0, 0, 0, 0, 1, 0});
    const std::vector<double> view{h, 0, -h, 0, 0, 1, 0, 0, h, 0, h, -r2, 0, 0, 0, 1};
    CHECK(grade_case(c, conventions{}, view.data()).max_ulps == 0);
    // Left-handed: w = (−1, 0, −1), x = (−1, 0, 1)/√2, z = (−1, 0, −1)/√2, −z·eye = +√2.
    conventions lh;
    lh.hand = handedness::left;
    const std::vector<double> view_lh{-h, 0, h, 0, 0, 1, 0, 0, -h, 0, -h, r2, 0, 0, 0, 1};
    CHECK(grade_case(c, lh, view_lh.data()).max_ulps == 0);
    // The placement: columns x, y, z and the eye.
    const test_case p = make_case(operation::target_to, t, {1, 0, 1, 0, 0, 0, 0, 1, 0});
    const std::vector<double> placement{h, 0, h, 1, 0, 1, 0, 0, -h, 0, h, 1, 0, 0, 0, 1};
    CHECK(grade_case(p, conventions{}, placement.data()).max_ulps == 0);
  }
  // up parallel to the view direction: x and y (rows 0 and 1) do not exist, z does.
  const test_case parallel = make_case(operation::look_at, scalar_type::f32, {1, 0, 1, 0, 0, 0, 2, 0, 2});
  const double h = static_cast<double>(std::sqrt(0.5f)), r2 = static_cast<double>(std::sqrt(2.0f));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> rejected{nan, nan, nan, nan, nan, nan, nan, nan, h, 0, h, -r2, 0, 0, 0, 1};
  const case_grade g = grade_case(parallel, conventions{}, rejected.data());
  CHECK(g.garbage == 0);
  CHECK(g.nonfinite == 0);
  CHECK(g.max_ulps == 0);
  std::vector<double> identity_rows = rejected;  // a library that falls back to the identity
  for (int i = 0; i < 8; ++i) identity_rows[static_cast<std::size_t>(i)] = (i == 0 || i == 5) ? 1 : 0;
  CHECK(grade_case(parallel, conventions{}, identity_rows.data()).garbage == 8);
  // eye = target: no axis at all, only the last row is defined.
  const test_case collapsed = make_case(operation::look_at, scalar_type::f32, {1, 2, 3, 1, 2, 3, 0, 1, 0});
  const std::vector<double> identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  CHECK(grade_case(collapsed, conventions{}, identity.data()).garbage == 12);
}

TEST_CASE("width and height builders: the symmetric volume, a zero width undefines only the x scale",
          "[verify][camera]") {
  // w = 4, h = 2, n = 1, f = 3 (gl): ortho 2/w = 1/2, 2/h = 1, A = −2/(f−n) = −1, B = −(f+n)/(f−n) = −2;
  // perspective 2n/w = 1/2, 2n/h = 1, A = −(f+n)/(f−n) = −2, B = −2fn/(f−n) = −3 (by hand).
  const test_case o = make_case(operation::ortho_size, scalar_type::f32, {4, 2, 1, 3});
  const std::vector<double> ortho{0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, -2, 0, 0, 0, 1};
  CHECK(grade_case(o, conventions{}, ortho.data()).max_ulps == 0);
  const test_case p = make_case(operation::perspective_size, scalar_type::f64, {4, 2, 1, 3});
  const std::vector<double> persp{0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0};
  CHECK(grade_case(p, conventions{}, persp.data()).max_ulps == 0);
  // w = 0: only (0,0) divides by it; the centre offset (0,3) is 0 by construction.
  const test_case flat = make_case(operation::ortho_size, scalar_type::f32, {0, 2, 1, 3});
  std::vector<double> inf_scale = ortho;
  inf_scale[0] = std::numeric_limits<double>::infinity();
  const case_grade g = grade_case(flat, conventions{}, inf_scale.data());
  CHECK(g.garbage == 0);
  CHECK(g.nonfinite == 0);
  CHECK_FALSE(g.outputs[0].exact_defined);
  CHECK(g.outputs[3].exact_defined);
}

TEST_CASE("grading an irrational operation up to scale is refused", "[verify][camera]") {
  conventions homogeneous;
  homogeneous.homogeneous = true;
  const test_case c = make_case(operation::look_at, scalar_type::f32, {1, 0, 1, 0, 0, 0, 0, 1, 0});
  const std::vector<double> out(16, 0.0);
  CHECK_THROWS_WITH(grade_case(c, homogeneous, out.data()),
                    "[shadowproof.verify.irrational_scale] look-at: its exact values are irrational, so it cannot be "
                    "graded up to scale (--homogeneous); grade the matrix as it is");
}

TEST_CASE("declared conventions travel in the case line; inputs are written in them and read back canonically",
          "[verify][protocol]") {
  // A plane written n·x = d: the canonical (0, 1, 0, −1), y = 1, is written (0, 1, 0, 1).
  test_case c = make_case(operation::shadow_matrix, scalar_type::f32, ground_inputs);
  conventions declared;
  declared.plane = plane_form::equals_d;
  declared.storage = storage_order::column_major;
  const std::string line = case_json_line(c, declared);
  CHECK(line.find(R"("conventions": {"layout": "column-major", "plane": "n.x=d"})") != std::string::npos);
  CHECK(line.find(R"("plane": ["0x0p+0", "0x1p+0", "0x0p+0", "0x1p+0"])") != std::string::npos);
  CHECK(line.find(R"("numbers": {"plane": [0, 1, 0, 1], "light": [1, 2, 3, 0]})") != std::string::npos);
  conventions read;  // the caller's defaults, overridden by the line
  const test_case back = parse_case_line(line, 1, read);
  CHECK(back.inputs == c.inputs);
  CHECK(read.plane == plane_form::equals_d);
  CHECK(read.storage == storage_order::column_major);
  // Graded in the line's conventions: the column-major exact matrix is exact.
  CHECK(grade_case(back, read, transposed(ground_matrix).data()).max_ulps == 0);
  // Without a "conventions" object nothing is declared and nothing is written.
  CHECK(case_json_line(c).find("conventions") == std::string::npos);
}

TEST_CASE("JSON numbers in case lines read back as the very same double", "[verify][protocol]") {
  // 0.1f is 13421773·2^-27 = 0.100000001490116119384765625; its shortest round-trip double
  // text is 0.10000000149011612, which any correctly rounding JSON reader turns back into it.
  test_case c = make_case(operation::ortho, scalar_type::f32,
                          {static_cast<double>(0.1f), 1, -1e-30f, 3.5, std::ldexp(1.0, -149), 1e30f});
  const std::string line = case_json_line(c);
  CHECK(line.find(R"("numbers": {"box": [0.10000000149011612, 1, )") != std::string::npos);
  const std::size_t from = line.find('[', line.find(R"("numbers": )"));
  const std::string numbers = line.substr(from, line.find(']', from) + 1 - from);
  // Re-read only the numbers through the output reader's JSON path (a plain JSON parse).
  const output_line o = parse_output_line(R"({"id": 0, "output": )" + numbers + "}", 1, scalar_type::f32, 6);
  CHECK(o.values == c.inputs);
}

TEST_CASE("3x3 layouts: padded and mat4-embedded matrices map to the 9 canonical numbers", "[verify][protocol]") {
  // A = diag(2, 4, 8): (A⁻¹)ᵀ = diag(1/2, 1/4, 1/8), by hand.
  const test_case c = make_case(operation::normal_matrix, scalar_type::f32, {2, 0, 0, 0, 4, 0, 0, 0, 8});
  conventions mat4_io;
  mat4_io.matrix3 = matrix3_layout::mat4;
  mat4_io.matrix3_input = matrix3_layout::mat4;
  const std::string line = case_json_line(c, mat4_io);
  CHECK(line.find(R"("numbers": {"matrix": [2, 0, 0, 0, 0, 4, 0, 0, 0, 0, 8, 0, 0, 0, 0, 1]})") != std::string::npos);
  conventions read;
  const test_case back = parse_case_line(line, 1, read);
  CHECK(back.inputs == c.inputs);
  CHECK(output_count(back, read) == 16);
  const output_line o = parse_output_line(
      R"({"id": 0, "output": [0.5, 0, 0, 0, 0, 0.25, 0, 0, 0, 0, 0.125, 0, 0, 0, 0, 1]})", 1, back, read);
  CHECK(grade_case(back, read, o.values.data()).max_ulps == 0);
  // The embedding's own entries are not free: a 2 in the corner is no mat4 embedding.
  CHECK_THROWS_WITH(parse_output_line(R"({"id": 0, "output": [0.5, 0, 0, 0, 0, 0.25, 0, 0, 0, 0, 0.125, 0, 0, 0, 0, 2]})",
                                      3, back, read),
                    "[shadowproof.protocol.output] line 3: output entry 15 lies outside the 3x3 block of a mat4 "
                    "embedding [A 0; 0 1] and must be exactly 1, not 0x1p+1");
  // Padded: three groups of four, the fourth of each ignored.
  conventions padded;
  padded.matrix3 = matrix3_layout::padded;
  CHECK(output_count(c, padded) == 12);
  const output_line p = parse_output_line(R"({"id": 0, "output": [0.5, 0, 0, 7, 0, 0.25, 0, 7, 0, 0, 0.125, 7]})", 1,
                                          c, padded);
  CHECK(grade_case(c, padded, p.values.data()).max_ulps == 0);
}

TEST_CASE("unknown conventions are rejected with the convention named", "[verify][protocol]") {
  conventions conv;
  CHECK_THROWS_WITH(set_convention(conv, "handedness", "up"),
                    "[shadowproof.protocol.convention] convention \"handedness\" cannot be \"up\"; expected one of "
                    "right, left");
  CHECK_THROWS_WITH(set_convention(conv, "chirality", "left"),
                    Catch::Matchers::StartsWith("[shadowproof.protocol.convention] unknown convention \"chirality\""));
  CHECK_THROWS_WITH(
      parse_case_line(R"({"id": 0, "op": "ortho", "type": "f32", "conventions": {"depth": "z"}, "box": [0, 1, 0, 1, 1, 2]})", 4),
      "[shadowproof.protocol.convention] line 4: convention \"depth\" cannot be \"z\"; expected one of gl, d3d, "
      "reverse-z");
  set_convention(conv, "angle", "degrees");
  set_convention(conv, "symmetric", "true");
  CHECK(conv.angle == angle_unit::degrees);
  CHECK(conv.symmetric_view);
  const auto declared = declared_conventions(conv);
  REQUIRE(declared.size() == 2);
  CHECK(declared[0] == std::make_pair(std::string("angle"), std::string("degrees")));
}

TEST_CASE("the same seed gives the same cases, bit for bit", "[verify]") {
  for (operation op : all_operations()) {
    const auto a = generate_cases(op, scalar_type::f32, 30, 42);
    const auto b = generate_cases(op, scalar_type::f32, 30, 42);
    const auto d = generate_cases(op, scalar_type::f32, 30, 43);
    REQUIRE(a.size() == 30);
    bool differs = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      CHECK(case_json_line(a[i]) == case_json_line(b[i]));
      differs = differs || a[i].inputs != d[i].inputs;
      for (double x : a[i].inputs) CHECK(static_cast<double>(static_cast<float>(x)) == x);
    }
    CHECK(differs);
  }
}

TEST_CASE("degenerate cases are exactly degenerate", "[verify]") {
  for (const auto& c : generate_cases(operation::shadow_matrix, scalar_type::f64, 60, 5, input_class::degenerate)) {
    rational s = 0;
    for (std::size_t i = 0; i < 4; ++i) s += exact_value(c.inputs[i]) * exact_value(c.inputs[4 + i]);
    CHECK(s == 0);
    CHECK(std::isinf(closeness_to_degeneracy(c)));
  }
}

TEST_CASE("a case line reads back to the same inputs", "[verify]") {
  for (operation op : all_operations())
    for (const auto& c : generate_cases(op, scalar_type::f64, 9, 11)) {
      const test_case back = parse_case_line(case_json_line(c), 1);
      CHECK(back.id == c.id);
      CHECK(back.op == c.op);
      CHECK(back.type == c.type);
      CHECK(back.cls == c.cls);
      CHECK(back.inputs == c.inputs);
    }
}

TEST_CASE("exact decimals of binary floats", "[verify]") {
  CHECK(exact_decimal(static_cast<double>(0.1f)) == "0.100000001490116119384765625");
  CHECK(exact_decimal(-2.5) == "-2.5");
  CHECK(exact_decimal(1024.0) == "1024");
  CHECK(exact_decimal(std::ldexp(1.0, -3)) == "0.125");
}

TEST_CASE("malformed protocol lines are rejected with the culprit named", "[verify]") {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message([] { parse_output_line(R"({"id": 3, "output": [0.1, 1, 2]})", 4, scalar_type::f32, 3); }) ==
        "[shadowproof.protocol.output] line 4: \"output\"[0] = 0.1 is not exactly a f32 value (outputs are "
        "never rounded by the grader)");
  CHECK(message([] { parse_output_line(R"({"id": 3, "output": [1, 2]})", 2, scalar_type::f64, 3); }) ==
        "[shadowproof.protocol.output] line 2: \"output\" must be an array of 3 numbers");
  CHECK(message([] {
          parse_case_line(R"({"id": 0, "op": "reflection-matrix", "type": "f32", "plane": [0, 0, 0, 1]})", 7);
        }) == "[shadowproof.protocol.case] line 7: the plane needs a non-zero normal (a, b, c)");
  CHECK(message([] { parse_case_line(R"({"id": 0, "op": "twist", "type": "f32"})", 1); }) ==
        "[shadowproof.protocol.case] line 1: unknown \"op\" \"twist\"");
  const output_line o =
      parse_output_line(R"({"id": 5, "output": ["0x1.8p+0", null, "-inf"]})", 1, scalar_type::f32, 3);
  CHECK(o.id == 5);
  CHECK(o.values[0] == 1.5);
  CHECK(std::isnan(o.values[1]));
  CHECK(o.values[2] == -std::numeric_limits<double>::infinity());
}

// ----------------------------------------------------------------------------------------------
// The filtered oracle must agree exactly with the all-rational one. Outputs come from the
// library's own formulas instantiated in float/double (the naive float implementations).

namespace {

template <class T>
std::vector<double> float_outputs(const test_case& c) {
  const double* in = c.inputs.data();
  auto v = [&](std::size_t i) { return static_cast<T>(in[i]); };
  std::vector<double> out;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  switch (c.op) {
    case operation::shadow_matrix:
    case operation::reflection_matrix: {
      const plane<T> P{make_vec4<T>(v(0), v(1), v(2), v(3))};
      const mat4<T> M = c.op == operation::reflection_matrix
                            ? reflection_matrix(P)
                            : shadow_matrix(P, light<T>{make_vec4<T>(v(4), v(5), v(6), v(7))});
      for (std::size_t i = 0; i < 16; ++i) out.push_back(M(i / 4, i % 4));
      break;
    }
    case operation::shadow_point: {
      const plane<T> P{make_vec4<T>(v(0), v(1), v(2), v(3))};
      const vec4<T> h = shadow_image(P, light<T>{make_vec4<T>(v(4), v(5), v(6), v(7))}, make_point<T>(v(8), v(9), v(10)));
      for (std::size_t i = 0; i < 3; ++i) out.push_back(h[i] / h[3]);
      break;
    }
    case operation::ortho:
    case operation::frustum:
      try {
        const mat4<T> M = c.op == operation::ortho ? orthographic<T>(v(0), v(1), v(2), v(3), v(4), v(5), depth_convention::gl)
                                                   : frustum<T>(v(0), v(1), v(2), v(3), v(4), v(5), depth_convention::gl);
        for (std::size_t i = 0; i < 16; ++i) out.push_back(M(i / 4, i % 4));
      } catch (const error&) {
        out.assign(16, nan);
      }
      break;
    case operation::perspective:
      try {
        const mat4<T> M = perspective<T>(v(0), v(1), v(2), v(3), depth_convention::gl);
        for (std::size_t i = 0; i < 16; ++i) out.push_back(M(i / 4, i % 4));
      } catch (const error&) {
        out.assign(16, nan);
      }
      break;
    case operation::perspective_fov:
    case operation::perspective_fov_infinite: {
      // The textbook evaluation: c = 1/tan(fovy/2), then the same formulas.
      const bool infinite = c.op == operation::perspective_fov_infinite;
      const T focal = T(1) / std::tan(v(0) / T(2));
      try {
        const mat4<T> M = perspective<T>(focal, v(1), v(2), infinite ? T(0) : v(3), depth_convention::gl, infinite);
        for (std::size_t i = 0; i < 16; ++i) out.push_back(M(i / 4, i % 4));
      } catch (const error&) {
        out.assign(16, nan);
      }
      break;
    }
    case operation::ortho_size:
    case operation::perspective_size:
      try {
        const T hw = v(0) / T(2), hh = v(1) / T(2);
        const mat4<T> M = c.op == operation::ortho_size
                              ? orthographic<T>(-hw, hw, -hh, hh, v(2), v(3), depth_convention::gl)
                              : frustum<T>(-hw, hw, -hh, hh, v(2), v(3), depth_convention::gl);
        for (std::size_t i = 0; i < 16; ++i) out.push_back(M(i / 4, i % 4));
      } catch (const error&) {
        out.assign(16, nan);
      }
      break;
    case operation::look_at:
    case operation::target_to: {
      const vec3<T> eye{v(0), v(1), v(2)}, target{v(3), v(4), v(5)}, up{v(6), v(7), v(8)};
      const mat4<T> V = look_at_float(eye, target, up, handedness::right);
      for (std::size_t i = 0; i < 16; ++i) out.push_back(V(i / 4, i % 4));
      break;
    }
    case operation::normal_matrix: {
      mat4<T> A = identity4<T>();
      for (std::size_t i = 0; i < 9; ++i) A(i / 3, i % 3) = v(i);
      try {
        const mat4<T> G = normal_matrix3(A);
        for (std::size_t i = 0; i < 9; ++i) out.push_back(G(i / 3, i % 3));
      } catch (const error&) {
        out.assign(9, nan);
      }
      break;
    }
  }
  return out;
}

void require_same(const case_grade& a, const case_grade& b) {
  REQUIRE(a.outputs.size() == b.outputs.size());
  for (std::size_t i = 0; i < a.outputs.size(); ++i) {
    const auto &x = a.outputs[i], &y = b.outputs[i];
    REQUIRE(x.exact_defined == y.exact_defined);
    REQUIRE(std::memcmp(&x.reference, &y.reference, sizeof(double)) == 0);
    REQUIRE(x.ulps == y.ulps);
    REQUIRE(x.nonfinite == y.nonfinite);
    REQUIRE(x.garbage == y.garbage);
    REQUIRE((x.relative == y.relative || (std::isnan(x.relative) && std::isnan(y.relative))));
  }
  REQUIRE(a.max_ulps == b.max_ulps);
  REQUIRE(a.worst_output == b.worst_output);
  REQUIRE(a.exact_class == b.exact_class);
  REQUIRE(a.got_class == b.got_class);
  REQUIRE(a.misclassified == b.misclassified);
  REQUIRE(a.plane_value == b.plane_value);
  REQUIRE(a.scale_pivot == b.scale_pivot);
  REQUIRE(a.scale == b.scale);
  REQUIRE(a.reference_class == b.reference_class);
  REQUIRE(a.rejected == b.rejected);
  // The verdicts, which the filtered oracle decides over intervals where it can.
  for (std::size_t i = 0; i < a.outputs.size(); ++i) REQUIRE(a.outputs[i].v == b.outputs[i].v);
  REQUIRE(a.v == b.v);
}

}  // namespace

TEST_CASE("the filtered oracle agrees exactly with the all-rational oracle", "[verify][oracle]") {
  const conventions canonical{};
  conventions homogeneous;
  homogeneous.homogeneous = true;
  conventions clamped;
  clamped.clamps_behind_receiver = true;
  clamped.directional_only = true;
  oracle_counters counters, irrational_counters;
  std::size_t graded = 0;
  // Operations whose exact values are irrational: never graded up to scale.
  auto irrational = [](operation op) {
    return op == operation::perspective_fov || op == operation::perspective_fov_infinite ||
           op == operation::look_at || op == operation::target_to;
  };
  std::size_t skipped = 0;
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64})
      for (const conventions* conv : {&canonical, static_cast<const conventions*>(&homogeneous),
                                      static_cast<const conventions*>(&clamped)}) {
        if (conv == &clamped && op != operation::shadow_point) continue;
        if (conv == &homogeneous && irrational(op)) {
          skipped += 150;
          continue;
        }
        const auto cases = generate_cases(op, type, 150, 2024 + static_cast<int>(op), std::nullopt, *conv);
        std::mt19937_64 rng(7);
        for (const auto& c : cases) {
          std::vector<double> out = type == scalar_type::f32 ? float_outputs<float>(c) : float_outputs<double>(c);
          // Also grade outputs a few ulps off the float result, and exact copies of inputs.
          if (rng() % 4 == 0)
            for (double& x : out)
              if (std::isfinite(x)) x = type == scalar_type::f32 ? std::nextafter(static_cast<float>(x), 1e30f) : std::nextafter(x, 1e300);
          const case_grade fast =
              grade_case(c, *conv, out.data(), oracle_mode::filtered, irrational(op) ? &irrational_counters : &counters);
          const case_grade slow = grade_case(c, *conv, out.data(), oracle_mode::naive);
          INFO("op " << to_string(op) << ", type " << to_string(type) << ", case " << case_json_line(c));
          require_same(fast, slow);
          ++graded;
        }
      }
  CHECK(graded + skipped == all_operations().size() * 2 * 2 * 150 + 2 * 150);
  // The irrational camera builders too: square roots and cotangents enclosed by intervals.
  CHECK(irrational_counters.decided_by_intervals > 4 * irrational_counters.fell_back_to_rationals);
  // The comparison is only meaningful if intervals decide most cases on their own.
  CHECK(counters.decided_by_intervals > 4 * counters.fell_back_to_rationals);
}

namespace {

// Conventions the dedicated kernels read, per operation, for the grade-level agreement tests.
std::vector<conventions> kernel_conventions(operation op) {
  conventions along_rays;
  along_rays.light = light_sign::along_rays;
  conventions column_major;
  column_major.storage = storage_order::column_major;
  conventions clamped;
  clamped.clamps_behind_receiver = true;
  clamped.directional_only = true;
  switch (op) {
    case operation::shadow_matrix: return {conventions{}, along_rays, column_major};
    case operation::shadow_point: return {conventions{}, along_rays, clamped};
    case operation::ortho:
    case operation::frustum:
    case operation::perspective:
    case operation::ortho_size:
    case operation::perspective_size: {
      std::vector<conventions> all;
      for (depth_convention d : {depth_convention::gl, depth_convention::d3d, depth_convention::reverse_z}) {
        conventions c = column_major;
        c.depth = d;
        c.symmetric_view = d == depth_convention::d3d && op != operation::perspective;
        c.hand = d == depth_convention::gl ? handedness::left : handedness::right;
        all.push_back(c);
      }
      return all;
    }
    default: return {conventions{}, column_major};
  }
}

// Grades float outputs (the formula's own, one ulp off, or for points the point itself and the
// light) with the filtered oracle, which takes the operation's dedicated kernels, and with the
// all-rational one; every class, the conventions above.
// The operations with dedicated error-free kernels; the others (irrational camera entries) are
// decided by the generic oracle only, whose exact side is MPFR enclosures at growing precision:
// a tenth of the cases keeps their agreement checked at a fraction of the time (their own test,
// below, covers their conventions).
bool has_dedicated_kernel(operation op) {
  return op == operation::shadow_matrix || op == operation::shadow_point || op == operation::reflection_matrix ||
         op == operation::ortho || op == operation::frustum || op == operation::normal_matrix ||
         op == operation::perspective;
}

std::size_t cases_per_class(operation op, std::size_t per_class) {
  return has_dedicated_kernel(op) ? per_class : per_class / 10;
}

template <class T>
std::size_t check_kernel_grades(std::uint64_t seed, std::size_t per_class, oracle_counters& counters) {
  const scalar_type type = std::is_same_v<T, float> ? scalar_type::f32 : scalar_type::f64;
  std::size_t graded = 0;
  for (operation op : all_operations())
    for (const conventions& conv : kernel_conventions(op))
      for (input_class cls : all_input_classes()) {
        const auto cases = generate_cases(op, type, cases_per_class(op, per_class), seed + static_cast<int>(op), cls, conv);
        std::mt19937_64 rng(seed);
        for (const auto& c : cases) {
          std::vector<double> out = float_outputs<T>(c);
          const std::uint64_t pick = rng() % 6;
          if (pick == 0)
            for (double& x : out)
              if (std::isfinite(x)) x = static_cast<T>(std::nextafter(static_cast<T>(x), T(-1e30)));
          if (op == operation::shadow_point && pick == 1) out.assign(c.inputs.begin() + 8, c.inputs.end());
          if (op == operation::shadow_point && pick == 2 && c.inputs[7] != 0)
            for (std::size_t i = 0; i < 3; ++i) out[i] = static_cast<T>(c.inputs[4 + i] / c.inputs[7]);
          // The counters watch the operations with dedicated kernels on inputs within their range.
          const bool kernel = has_dedicated_kernel(op);
          oracle_counters* tally = kernel && cls != input_class::range ? &counters : nullptr;
          const case_grade fast = grade_case(c, conv, out.data(), oracle_mode::filtered, tally);
          const case_grade slow = grade_case(c, conv, out.data(), oracle_mode::naive);
          INFO("op " << to_string(op) << ", class " << to_string(cls) << ", depth " << to_string(conv.depth)
                     << ", case " << case_json_line(c));
          require_same(fast, slow);
          ++graded;
        }
      }
  return graded;
}

// The cases check_kernel_grades grades with `per_class` cases per kernel class.
std::size_t expected_kernel_cases(std::size_t per_class) {
  std::size_t n = 0;
  for (operation op : all_operations())
    n += kernel_conventions(op).size() * all_input_classes().size() * cases_per_class(op, per_class);
  return n;
}

}  // namespace

TEST_CASE("the dedicated float kernels agree exactly with the all-rational oracle", "[verify][oracle]") {
  oracle_counters counters;
  const std::size_t graded = check_kernel_grades<float>(77, 120, counters);
  CHECK(graded == expected_kernel_cases(120));
  CHECK(counters.decided_by_intervals > 9 * counters.fell_back_to_rationals);
}

TEST_CASE("the double kernels agree exactly with the all-rational oracle", "[verify][oracle]") {
  oracle_counters counters;
  const std::size_t graded = check_kernel_grades<double>(91, 120, counters);
  CHECK(graded == expected_kernel_cases(120));
  CHECK(counters.decided_by_intervals > 9 * counters.fell_back_to_rationals);
}

namespace {

// The conventions the irrational camera builders read: handedness, and the angle's unit.
std::vector<conventions> irrational_conventions(operation op) {
  conventions left;
  left.hand = handedness::left;
  if (op == operation::look_at || op == operation::target_to) return {conventions{}, left};
  conventions left_degrees_reverse = left;
  left_degrees_reverse.angle = angle_unit::degrees;
  left_degrees_reverse.depth = depth_convention::reverse_z;
  return {conventions{}, left_degrees_reverse};
}

// Outputs that reach every verdict: the library's float formula, a few ulps off it, a relative
// 2^-20 or 2^-9 off (stable, unstable or wrong by the conditioning), and NaN in one entry.
template <class T>
std::vector<double> perturbed_outputs(const test_case& c, std::mt19937_64& rng) {
  std::vector<double> out = float_outputs<T>(c);
  if (c.op == operation::target_to && out.size() == 16) {  // float_outputs gives the view matrix
    const vec3<T> eye{static_cast<T>(c.inputs[0]), static_cast<T>(c.inputs[1]), static_cast<T>(c.inputs[2])};
    const vec3<T> target{static_cast<T>(c.inputs[3]), static_cast<T>(c.inputs[4]), static_cast<T>(c.inputs[5])};
    const vec3<T> up{static_cast<T>(c.inputs[6]), static_cast<T>(c.inputs[7]), static_cast<T>(c.inputs[8])};
    const mat4<T> V = look_at_float(eye, target, up, handedness::right);
    for (std::size_t r = 0; r < 3; ++r)
      for (std::size_t k = 0; k < 3; ++k) out[r * 4 + k] = V(k, r);
    for (std::size_t r = 0; r < 3; ++r) out[r * 4 + 3] = c.inputs[r];
  }
  const std::uint64_t pick = rng() % 5;
  for (double& x : out) {
    if (!std::isfinite(x) || x == 0) continue;
    if (pick == 1) x = static_cast<T>(std::nextafter(std::nextafter(static_cast<T>(x), T(1e30)), T(1e30)));
    if (pick == 2) x = static_cast<T>(x * (1 + std::ldexp(1.0, -20)));
    if (pick == 3) x = static_cast<T>(x * (1 - std::ldexp(1.0, -9)));
  }
  if (pick == 4) out[rng() % out.size()] = std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace

TEST_CASE("the irrational camera builders graded over intervals agree with the all-rational grade",
          "[verify][oracle]") {
  // look-at, target-to (entries q/√s) and perspective-fov (cot(fovy/2)): the references and
  // every verdict of the filtered oracle, whose intervals enclose the square roots and the
  // cotangents, against rationals and MPFR enclosures alone; every class, both types, both
  // handednesses and both angle units.
  oracle_counters counters;
  std::size_t graded = 0;
  std::array<std::size_t, 8> reached{};
  std::mt19937_64 rng(12);
  for (operation op : {operation::look_at, operation::target_to, operation::perspective_fov,
                       operation::perspective_fov_infinite})
    for (scalar_type type : {scalar_type::f32, scalar_type::f64})
      for (const conventions& conv : irrational_conventions(op))
        for (input_class cls : all_input_classes()) {
          const auto cases = generate_cases(op, type, 3, 300 + static_cast<int>(op), cls, conv);
          for (const auto& c : cases) {
            const std::vector<double> out =
                type == scalar_type::f32 ? perturbed_outputs<float>(c, rng) : perturbed_outputs<double>(c, rng);
            const case_grade fast = grade_case(c, conv, out.data(), oracle_mode::filtered, &counters);
            const case_grade slow = grade_case(c, conv, out.data(), oracle_mode::naive);
            INFO("op " << to_string(op) << ", class " << to_string(cls) << ", case " << case_json_line(c));
            require_same(fast, slow);
            ++graded;
            for (const output_grade& o : slow.outputs) ++reached[static_cast<std::size_t>(o.v)];
          }
        }
  CHECK(graded == 4 * 2 * 2 * 4 * 3);
  // The sample reaches the verdicts that take the sensitivities.
  for (verdict v : {verdict::stable, verdict::unstable, verdict::range, verdict::wrong, verdict::nonfinite}) {
    INFO("verdict " << to_string(v));
    CHECK(reached[static_cast<std::size_t>(v)] > 0);
  }
  CHECK(counters.decided_by_intervals > 9 * counters.fell_back_to_rationals);
}

TEST_CASE("a case stream read in chunks of any size yields the cases of one generate_cases call", "[verify]") {
  for (const auto& [op, type] : {std::pair{shadowproof::operation::shadow_point, shadowproof::scalar_type::f32},
                                 std::pair{shadowproof::operation::look_at, shadowproof::scalar_type::f64}}) {
    const auto whole = shadowproof::generate_cases(op, type, 40, 5);
    shadowproof::case_stream stream(op, type, 5);
    std::vector<shadowproof::test_case> chunked;
    for (std::size_t n : {1, 0, 13, 26})
      for (auto& c : stream.next(n)) chunked.push_back(std::move(c));
    REQUIRE(chunked.size() == whole.size());
    for (std::size_t i = 0; i < whole.size(); ++i) {
      CHECK(chunked[i].id == i);
      CHECK(chunked[i].cls == whole[i].cls);
      CHECK(chunked[i].inputs == whole[i].inputs);
    }
  }
}
