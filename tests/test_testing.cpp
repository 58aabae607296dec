// Matchers and the property runner for the user's tests (include/shadowproof/testing/), through
// the Catch2 adapter. Expected values are derived by hand in the comments; planted defects show
// each kind of failure message in full.
#include "shadowproof/testing/catch2.h"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "shadowproof/constructions/shadow.h"
#include "shadowproof/core/error.h"
#include "shadowproof/fuzz/shrink.h"

using namespace shadowproof;
using shadowproof::catch2::rounds_to;

namespace {

// P = (0, 1, 0, 0) (the ground y = 0) and the point light L = (2, 5, 1, 1): P·L = 5 and
// M = 5 I − L Pᵀ, whose column 1 is (−2, −5, −1, −1) plus 5 on the diagonal:
//   [5 −2 0 0; 0 0 0 0; 0 −1 5 0; 0 −1 0 5]. Every entry is a small integer, exact in float.
const float ground[4] = {0, 1, 0, 0};
const float lamp[4] = {2, 5, 1, 1};
const std::array<float, 16> ground_shadow = {5, -2, 0, 0, 0, 0, 0, 0, 0, -1, 5, 0, 0, -1, 0, 5};

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const error& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

// A float routine that rounds the exact matrix correctly: the fixed point of every metric.
void correctly_rounded_shadow_matrix(const float* in, float* out) {
  const auto P = make_plane<rational>(exact_value(in[0]), exact_value(in[1]), exact_value(in[2]), exact_value(in[3]));
  const auto L = make_light<rational>(exact_value(in[4]), exact_value(in[5]), exact_value(in[6]), exact_value(in[7]));
  const mat4<rational> M = shadow_matrix(P, L);
  for (std::size_t i = 0; i < 16; ++i) out[i] = to_nearest_float(M(i / 4, i % 4));
}

// The textbook float routine: P·L and every entry in float arithmetic. Catastrophic
// cancellation near P·L = 0 makes it fail on near-degenerate inputs.
void naive_shadow_matrix(const float* in, float* out) {
  const float* P = in;
  const float* L = in + 4;
  const float s = P[0] * L[0] + P[1] * L[1] + P[2] * L[2] + P[3] * L[3];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[r * 4 + c] = (r == c ? s : 0.0f) - L[r] * P[c];
}

}  // namespace

TEST_CASE("the exact shadow matrix matches, in any container of floats", "[testing]") {
  float as_c_array[16];
  std::copy(ground_shadow.begin(), ground_shadow.end(), as_c_array);
  const std::vector<float> as_vector(ground_shadow.begin(), ground_shadow.end());
  CHECK_THAT(ground_shadow, rounds_to(shadow_matrix_of(ground, lamp)));
  CHECK_THAT(as_c_array, rounds_to(shadow_matrix_of(ground, lamp)));
  CHECK_THAT(as_vector, rounds_to(shadow_matrix_of(ground, lamp)));
  CHECK(shadow_matrix_of(ground, lamp).describe() ==
        "is the correctly rounded shadow-matrix of plane (0, 1, 0, 0), light (2, 5, 1, 1) in f32");
}

TEST_CASE("an entry one ulp off fails with its name, the exact value, the ulps and the reproducer", "[testing]") {
  auto M = ground_shadow;
  M[1] = std::nextafter(-2.0f, -3.0f);  // (0,1): −2 − 2^-22, one float below −2
  auto matcher = rounds_to(shadow_matrix_of(ground, lamp));
  CHECK_FALSE(matcher.match(M));
  CHECK(matcher.toString() ==
        "is the correctly rounded shadow-matrix of plane (0, 1, 0, 0), light (2, 5, 1, 1) in f32\n"
        "  1 of 16 outputs fail (ulps>0):\n"
        "  (0,1): got -2.00000024 (-0x1.000002p+1), exact -2, correctly rounded -2 (-0x1p+1): 1 ulp\n"
        "  inputs (f32): plane (0, 1, 0, 0), light (2, 5, 1, 1)\n"
        "  exact answer: shadowproof shadow --plane 0x0p+0,0x1p+0,0x0p+0,0x0p+0 --light "
        "0x1p+1,0x1.4p+2,0x1p+0,0x1p+0\n");
  // Within one ulp it matches.
  CHECK_THAT(M, rounds_to(shadow_matrix_of(ground, lamp).within_ulps(1)));
}

TEST_CASE("a multiple of the matrix matches up to scale only, and the scale is named", "[testing]") {
  std::array<float, 16> doubled{};
  for (std::size_t i = 0; i < 16; ++i) doubled[i] = 2 * ground_shadow[i];
  CHECK_THAT(doubled, rounds_to(shadow_matrix_of(ground, lamp).up_to_scale()));
  CHECK_FALSE(shadow_matrix_of(ground, lamp).match(doubled).matches);
  // One ulp off in (3,3). The scale comes from the first entry of largest exact magnitude,
  // |5| at (0,0): λ = 10/5 = 2.
  doubled[15] = std::nextafter(10.0f, 11.0f);
  const match_result r = shadow_matrix_of(ground, lamp).up_to_scale().match(doubled);
  CHECK_FALSE(r.matches);
  CHECK(r.explanation ==
        "  1 of 16 outputs fail (ulps>0):\n"
        "  up to scale: exact values are λ times the exact matrix, λ = 2 from entry (0,0)\n"
        "  (3,3): got 10.000001 (0x1.400002p+3), exact 10, correctly rounded 10 (0x1.4p+3): 1 ulp\n"
        "  inputs (f32): plane (0, 1, 0, 0), light (2, 5, 1, 1)\n"
        "  exact answer: shadowproof shadow --plane 0x0p+0,0x1p+0,0x0p+0,0x0p+0 --light "
        "0x1p+1,0x1.4p+2,0x1p+0,0x1p+0\n");
}

TEST_CASE("column-major storage matches when declared, and entries are named by (row, col)", "[testing]") {
  std::array<float, 16> stored{};
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t c = 0; c < 4; ++c) stored[c * 4 + r] = ground_shadow[r * 4 + c];
  CHECK_THAT(stored, rounds_to(shadow_matrix_of(ground, lamp).column_major()));
  stored[4] = -3;  // column 1, row 0: the entry (0,1), exactly −2
  const match_result r = shadow_matrix_of(ground, lamp).column_major().match(stored);
  CHECK(r.explanation ==
        "  1 of 16 outputs fail (ulps>0):\n"
        "  (0,1) [stored at 4]: got -3 (-0x1.8p+1), exact -2, correctly rounded -2 (-0x1p+1): 4194304 ulps\n"
        "  inputs (f32): plane (0, 1, 0, 0), light (2, 5, 1, 1)\n"
        "  exact answer: shadowproof shadow --plane 0x0p+0,0x1p+0,0x0p+0,0x0p+0 --light "
        "0x1p+1,0x1.4p+2,0x1p+0,0x1p+0\n");
}

TEST_CASE("a shadow point left where it is fails in every output", "[testing]") {
  // V = (1, 2, 3): M V = (5 − 4, 0, −2 + 15, −2 + 5) = (1, 0, 13, 3), so the shadow is
  // (1/3, 0, 13/3), a real shadow (0 < P·V / P·L = 2/5 < 1). Leaving V in place is off by
  // 0x3f800000 − 0x3eaaaaab = 13981013 float steps in x (1 against 0x1.555556p-2), 0x40000000
  // in y (2 against 0) and 0x408aaaab − 0x40400000 = 4893355 in z (3 against 0x1.155556p+2).
  // An image at V itself is not a misclassification (docs/verdicts.md: the correctly rounded
  // image of a point within half an ulp of the receiver is V): the values fail it.
  const float V[3] = {1, 2, 3};
  const float right[3] = {1.0f / 3.0f, 0, 13.0f / 3.0f};  // each correctly rounded (one division)
  CHECK_THAT(right, rounds_to(shadow_point_of(ground, lamp, V)));
  const match_result r = shadow_point_of(ground, lamp, V).match(V);
  CHECK(r.explanation ==
        "  3 of 3 outputs fail (ulps>0):\n"
        "  x: got 1 (0x1p+0), exact 1/3, correctly rounded 0.333333343 (0x1.555556p-2): 13981013 ulps\n"
        "  y: got 2 (0x1p+1), exact 0, correctly rounded 0 (0x0p+0): 1073741824 ulps\n"
        "  z: got 3 (0x1.8p+1), exact 13/3, correctly rounded 4.33333349 (0x1.155556p+2): 4893355 ulps\n"
        "  inputs (f32): plane (0, 1, 0, 0), light (2, 5, 1, 1), point (1, 2, 3)\n"
        "  exact answer: shadowproof shadow --plane 0x0p+0,0x1p+0,0x0p+0,0x0p+0 --light "
        "0x1p+1,0x1.4p+2,0x1p+0,0x1p+0 --point 0x1p+0,0x1p+1,0x1.8p+1\n");
}

TEST_CASE("NaN where the exact value is finite, and a number where none exists, always fail", "[testing]") {
  auto M = ground_shadow;
  M[0] = std::numeric_limits<float>::quiet_NaN();
  const match_result nan = shadow_matrix_of(ground, lamp).within_ulps(1000).match(M);
  CHECK_FALSE(nan.matches);
  CHECK(nan.explanation.find("  (0,0): got nan, exact 5, correctly rounded 5 (0x1.4p+2): non-finite where the "
                             "exact value is finite\n") != std::string::npos);
  // V = (1, 5, 0) is level with the light (P·V = 5 = P·L): its image is at infinity, no
  // affine point exists, and any finite answer is garbage.
  const float level[3] = {1, 5, 0};
  const float finite[3] = {0, 0, 0};
  const match_result garbage = shadow_point_of(ground, lamp, level).within_ulps(1000).match(finite);
  CHECK_FALSE(garbage.matches);
  CHECK(garbage.explanation.find("  x: got 0 (0x0p+0), but no exact value exists (a finite number where none "
                                 "exists)\n") != std::string::npos);
  const float nans[3] = {NAN, NAN, NAN};
  CHECK_THAT(nans, rounds_to(shadow_point_of(ground, lamp, level)));
}

TEST_CASE("outputs of the wrong count or format do not match", "[testing]") {
  const std::vector<float> fifteen(15, 0.0f);
  CHECK(shadow_matrix_of(ground, lamp).match(fifteen).explanation == "  shadow-matrix has 16 outputs, given 15\n");
  const std::array<double, 16> doubles{};
  CHECK(shadow_matrix_of(ground, lamp).match(doubles).explanation ==
        "  the outputs are f64 but the inputs are f32: grade a routine in the format it computes in\n");
}

TEST_CASE("inputs that name no configuration, or mix formats, are errors naming the input", "[testing]") {
  const float nan_plane[4] = {0, NAN, 0, 0};
  CHECK(message_of([&] { shadow_matrix_of(nan_plane, lamp); }) ==
        "[shadowproof.testing.input] plane[1] = nan is not a finite float");
  const float flat[4] = {0, 0, 0, 1};
  CHECK(message_of([&] { shadow_matrix_of(flat, lamp); }) ==
        "[shadowproof.testing.input] shadow-matrix: the plane needs a non-zero normal (a, b, c)");
  const double lamp64[4] = {2, 5, 1, 1};
  CHECK(message_of([&] { shadow_matrix_of(ground, lamp64); }) ==
        "[shadowproof.testing.input] light is f64 but the inputs before it are f32: give every input in the format "
        "the routine computes in");
  const std::vector<float> three(3, 1.0f);
  CHECK(message_of([&] { shadow_matrix_of(three, lamp); }) ==
        "[shadowproof.testing.input] plane has 3 numbers, expected 4");
}

TEST_CASE("failure policies read ulps thresholds and the verdicts graded today", "[testing]") {
  CHECK(failure_policy().to_string() == "ulps>0");
  CHECK(failure_policy::parse("ulps>2").ulps_threshold() == 2u);
  CHECK(failure_policy::parse("garbage,ulps>4,nonfinite").to_string() == "ulps>4,nonfinite,garbage");
  CHECK_FALSE(failure_policy::parse("nonfinite").ulps_threshold().has_value());
  CHECK(message_of([] { failure_policy::parse("unstable"); }) ==
        "[shadowproof.testing.fail_on] the verdict 'unstable' is not graded yet; fail on ulps>N, nonfinite or garbage");
  CHECK(message_of([] { failure_policy::parse("nan"); }) ==
        "[shadowproof.testing.fail_on] unknown verdict 'nan' (one of: exact, faithful, stable, unstable, wrong, range, "
        "nonfinite, garbage)");
  CHECK(message_of([] { failure_policy::parse("ulps>two"); }) ==
        "[shadowproof.testing.fail_on] cannot read 'ulps>two': expected ulps>N with N a whole number below 2^64");
  CHECK(message_of([] { failure_policy::parse(""); }) ==
        "[shadowproof.testing.fail_on] empty term in '' (expected ulps>N or verdict names, separated by commas)");
  // A policy of verdicts only ignores ulps: the one-ulp defect passes, a NaN does not.
  auto M = ground_shadow;
  M[1] = std::nextafter(-2.0f, -3.0f);
  CHECK_THAT(M, rounds_to(shadow_matrix_of(ground, lamp).failing_on(failure_policy::parse("nonfinite"))));
  M[2] = NAN;
  CHECK_FALSE(shadow_matrix_of(ground, lamp).failing_on(failure_policy::parse("nonfinite")).match(M).matches);
}

TEST_CASE("check passes a correctly rounding routine on every class of cases", "[testing][check]") {
  const check_result r = check(operation::shadow_matrix, correctly_rounded_shadow_matrix, {600, 3});
  CHECK(r);
  CHECK(r.cases == 600);
  CHECK(r.failed == 0);
  std::ostringstream text;
  text << r;
  CHECK(text.str() == "shadow-matrix (f32): 600 cases pass");
}

TEST_CASE("check fails the naive routine with its worst case shrunk, and the shrunk case still fails",
          "[testing][check]") {
  const check_settings settings{300, 7, {input_class::near_degenerate, input_class::degenerate},
                                failure_policy::ulps_above(2)};
  const check_result r = check(operation::shadow_matrix, naive_shadow_matrix, settings);
  REQUIRE_FALSE(r);
  REQUIRE(r.worst);
  REQUIRE(r.shrunk);
  CHECK(r.worst->cls != input_class::regular);
  CHECK(input_bits(r.shrunk->inputs) <= input_bits(r.worst->inputs));
  // The shrunk inputs, run again through the routine, still fail the matcher.
  std::array<float, 16> out{};
  std::array<float, 8> in{};
  for (std::size_t i = 0; i < 8; ++i) in[i] = static_cast<float>(r.shrunk->inputs[i]);
  naive_shadow_matrix(in.data(), out.data());
  const std::array<float, 4> P{in[0], in[1], in[2], in[3]}, L{in[4], in[5], in[6], in[7]};
  CHECK_FALSE(shadow_matrix_of(P, L).within_ulps(2).match(out).matches);
  CHECK(r.report.rfind("shadow-matrix (f32): " + std::to_string(r.failed) + " of 300 cases fail (ulps>2; seed 7):", 0) ==
        0);
  CHECK(r.report.find("\nworst case, shrunk from ") != std::string::npos);
  CHECK(r.report.find("  exact answer: shadowproof shadow --plane ") != std::string::npos);
  // The same seed gives the same run.
  CHECK(check(operation::shadow_matrix, naive_shadow_matrix, settings).report == r.report);
}

TEST_CASE("a routine that throws or leaves outputs unwritten fails", "[testing][check]") {
  const check_result threw = check(
      operation::reflection_matrix, [](const double*, double*) { throw std::runtime_error("mirror not ready"); },
      {5, 1});
  CHECK(threw.failed == 5);
  CHECK(threw.failed_by_verdict.at("threw") == 5);
  CHECK(threw.report.find("  the routine threw: mirror not ready\n") != std::string::npos);
  const check_result silent = check(operation::reflection_matrix, [](const double*, double*) {}, {5, 1});
  CHECK(silent.failed_by_verdict.at("nonfinite") == 5);
}
