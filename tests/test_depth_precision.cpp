// Depth-buffer precision: the exact counts are checked against a value-by-value enumeration
// (std::nextafterf for binary32, k ↦ k + 1 for 24-bit codes) that decides for each value, with
// exact rationals, whether its rounding cell meets the image of the interval.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "shadowproof/constructions/depth_precision.h"
#include "shadowproof/core/error.h"
#include "support/exact_helpers.h"

using namespace shadowproof;
using shadowproof::testing::q;
using shadowproof::testing::error_text;

namespace {

rational exact(float v) { return exact_value(static_cast<double>(v)); }

bool even_bits(float v) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return (bits & 1u) == 0;
}

// NDC depth of the eye point at distance s on the view axis, straight from the matrix.
rational ndc_depth(const mat4<rational>& M, const rational& s) {
  const vec4<rational> v = M * make_point<rational>(0, 0, -s);
  return v[2] / v[3];
}

// The quantity each format holds, restated from the documented model: binary32 holds z_ndc;
// 24-bit codes hold the window depth, (z + 1)/2 for gl and z otherwise.
rational held(const rational& z_ndc, depth_convention c, depth_format f) {
  if (f == depth_format::f32 || c != depth_convention::gl) return z_ndc;
  return (z_ndc + 1) / 2;
}

// [lo, hi] = the image of the eye interval (the quantity is monotonic in s, so the ends suffice).
std::pair<rational, rational> image(const mat4<rational>& M, depth_convention c, depth_format f,
                                    const rational& from, const rational& to) {
  const rational a = held(ndc_depth(M, from), c, f), b = held(ndc_depth(M, to), c, f);
  return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
}

// Counts the floats v whose round-to-nearest-even cell meets [lo, hi]: the cell of v runs
// between the midpoints with its neighbours, each midpoint belonging to v when v is even.
std::uint64_t enumerate_f32(const rational& lo, const rational& hi) {
  const float inf = std::numeric_limits<float>::infinity();
  float v = static_cast<float>(to_nearest_double(lo));
  for (int i = 0; i < 3; ++i) v = std::nextafterf(v, -inf);  // start safely below lo
  std::uint64_t count = 0;
  bool first = true, first_was_hit = false;
  for (;;) {
    const rational m_lo = (exact(std::nextafterf(v, -inf)) + exact(v)) / 2;
    const rational m_hi = (exact(v) + exact(std::nextafterf(v, inf))) / 2;
    const bool e = even_bits(v);
    const bool starts_below_hi = m_lo < hi || (m_lo == hi && e);
    const bool ends_above_lo = lo < m_hi || (lo == m_hi && e);
    if (!starts_below_hi) break;
    if (ends_above_lo) {
      first_was_hit = first_was_hit || first;
      ++count;
    }
    first = false;
    v = std::nextafterf(v, inf);
  }
  REQUIRE_FALSE(first_was_hit);  // the walk must start below every hit
  return count;
}

// The same for the codes k/(2²⁴ − 1), cells [(k − 1/2)/N, (k + 1/2)/N], ties to even k.
std::uint64_t enumerate_unorm24(const rational& lo, const rational& hi) {
  const long N = (1L << 24) - 1;
  long k = static_cast<long>(std::floor(to_nearest_double(lo) * N)) - 3;
  std::uint64_t count = 0;
  for (;; ++k) {
    const rational m_lo = q(2 * k - 1, 2 * N), m_hi = q(2 * k + 1, 2 * N);
    const bool e = k % 2 == 0;
    if (!(m_lo < hi || (m_lo == hi && e))) break;
    if (lo < m_hi || (lo == m_hi && e)) ++count;
  }
  return count;
}

struct scenario {
  const char* what;
  mat4<rational> M;
  depth_convention c;
  rational from, to;
};

std::vector<scenario> f32_scenarios() {
  const auto gl = depth_convention::gl, d3d = depth_convention::d3d, rz = depth_convention::reverse_z;
  const rational n = q(1, 10), f = 100;
  return {
      {"d3d far from the eye", perspective<rational>(1, 1, n, f, d3d), d3d, 50, q(501, 10)},
      {"gl far from the eye", perspective<rational>(1, 1, n, f, gl), gl, 50, q(501, 10)},
      {"reverse-z far from the eye", perspective<rational>(1, 1, n, f, rz), rz, 50, q(501, 10)},
      {"gl at the near plane (negative NDC depths)", perspective<rational>(1, 1, n, f, gl), gl, n,
       q(1001, 10000)},
      {"d3d, infinite far", perspective<rational>(2, q(4, 3), n, 0, d3d, true), d3d, 1000, 1100},
      {"reverse-z, infinite far", perspective<rational>(2, q(4, 3), n, 0, rz, true), rz, 1000, q(10001, 10)},
      {"frustum, d3d", frustum<rational>(-1, 2, -1, 1, q(1, 2), 20, d3d), d3d, 5, q(51, 10)},
  };
}

}  // namespace

TEST_CASE("depth formats print and parse", "[depth_precision]") {
  CHECK(to_string(depth_format::f32) == "f32");
  CHECK(to_string(depth_format::unorm24) == "unorm24");
  CHECK(parse_depth_format("unorm24") == depth_format::unorm24);
  CHECK(error_text([] { parse_depth_format("d24s8"); }) ==
        "[shadowproof.depth_precision.format] unknown depth format 'd24s8': expected f32 or unorm24");
}

TEST_CASE("f32 distinct-value counts equal a float-by-float enumeration", "[depth_precision]") {
  for (const auto& sc : f32_scenarios()) {
    INFO(sc.what);
    const auto report = depth_precision(sc.M, sc.c, depth_format::f32, sc.from, sc.to, {});
    const auto [lo, hi] = image(sc.M, sc.c, depth_format::f32, sc.from, sc.to);
    const std::uint64_t expected = enumerate_f32(lo, hi);
    CHECK(report.distinct_values == expected);
    CHECK(expected > 1);  // the scenarios are chosen to span several floats
  }
}

TEST_CASE("unorm24 distinct-value counts equal a code-by-code enumeration", "[depth_precision]") {
  const rational n = q(1, 10), f = 100;
  for (const auto c : {depth_convention::gl, depth_convention::d3d, depth_convention::reverse_z}) {
    INFO(to_string(c));
    const mat4<rational> M = perspective<rational>(1, 1, n, f, c);
    const std::vector<std::pair<rational, rational>> intervals = {{10, 11}, {50, 60}, {n, q(101, 1000)}};
    for (const auto& [from, to] : intervals) {
      INFO("[" << from << ", " << to << "]");
      const auto report = depth_precision(M, c, depth_format::unorm24, from, to, {});
      const auto [lo, hi] = image(M, c, depth_format::unorm24, from, to);
      CHECK(report.distinct_values == enumerate_unorm24(lo, hi));
    }
  }
}

TEST_CASE("a linear depth map gives the counts and gaps derived by hand", "[depth_precision]") {
  // Orthographic d3d with n = 0, f = N = 2²⁴ − 1: z_ndc = s/N, so code k is exactly distance k.
  // Distances [1, 10] hit codes 1 … 10 (10 values), and consecutive codes are 1 apart.
  const long N = (1L << 24) - 1;
  const mat4<rational> M = orthographic<rational>(-1, 1, -1, 1, 0, N, depth_convention::d3d);
  const auto r = depth_precision(M, depth_convention::d3d, depth_format::unorm24, 1, 10, {3, q(7, 2)});
  CHECK(r.distinct_values == 10);
  REQUIRE(r.samples.size() == 2);
  CHECK(r.samples[0].stored == q(3, N));
  CHECK(*r.samples[0].spacing == 1);
  // 7/2 is a tie between codes 3 and 4: round half to even picks 4.
  CHECK(r.samples[1].stored == q(4, N));

  // Orthographic d3d with n = 0, f = 1: z_ndc = s. The floats in [1/2, 1] are 1/2 + k 2⁻²⁴ for
  // k = 0 … 2²³, i.e. 2²³ + 1 values; the gap is 2⁻²⁴ below 1 and 2⁻²³ from 1 upwards.
  const mat4<rational> U = orthographic<rational>(-1, 1, -1, 1, 0, 1, depth_convention::d3d);
  const auto u = depth_precision(U, depth_convention::d3d, depth_format::f32, q(1, 2), 1, {q(3, 4), 1});
  CHECK(u.distinct_values == (1u << 23) + 1);
  CHECK(*u.samples[0].spacing == rational(1, 1 << 24));
  CHECK(*u.samples[1].spacing == rational(1, 1 << 23));
}

TEST_CASE("gaps join consecutive stored values whose preimages are exact", "[depth_precision]") {
  const float inf = std::numeric_limits<float>::infinity();
  for (const auto& sc : f32_scenarios()) {
    INFO(sc.what);
    const std::vector<rational> at = {sc.from, (sc.from + sc.to) / 2, sc.to};
    const auto r = depth_precision(sc.M, sc.c, depth_format::f32, sc.from, sc.to, at);
    // Stored depth grows with distance for gl and d3d, shrinks for reverse-z.
    const bool grows = sc.c != depth_convention::reverse_z;
    for (const auto& s : r.samples) {
      REQUIRE(s.stored_distance);
      REQUIRE(s.spacing);
      CHECK(*s.spacing > 0);
      // The stored value's preimage maps back onto it exactly, and the far end of the gap maps
      // onto the next float in the direction of greater distance.
      CHECK(ndc_depth(sc.M, *s.stored_distance) == s.stored);
      const float next = std::nextafterf(static_cast<float>(to_nearest_double(s.stored)), grows ? inf : -inf);
      CHECK(exact(static_cast<float>(to_nearest_double(s.stored))) == s.stored);
      CHECK(ndc_depth(sc.M, *s.stored_distance + *s.spacing) == exact(next));
      // The sample distance rounds to the stored value: it lies within the gaps around it.
      CHECK(s.depth == ndc_depth(sc.M, s.distance));
    }
  }
}

TEST_CASE("reverse-z keeps far more distinct depths than d3d far from the eye", "[depth_precision]") {
  const rational n = q(1, 10), f = 1000;
  const auto d3d = depth_precision(perspective<rational>(1, 1, n, f, depth_convention::d3d), depth_convention::d3d,
                                   depth_format::f32, 500, 501, {});
  const auto rz = depth_precision(perspective<rational>(1, 1, n, f, depth_convention::reverse_z),
                                  depth_convention::reverse_z, depth_format::f32, 500, 501, {});
  CHECK(rz.distinct_values > 1000 * d3d.distinct_values);
  // With a 24-bit fixed-point buffer reversing gains nothing: the codes are evenly spaced, and
  // both conventions cover the same window-depth length.
  const auto d3d24 = depth_precision(perspective<rational>(1, 1, n, f, depth_convention::d3d),
                                     depth_convention::d3d, depth_format::unorm24, 500, 501, {});
  const auto rz24 = depth_precision(perspective<rational>(1, 1, n, f, depth_convention::reverse_z),
                                    depth_convention::reverse_z, depth_format::unorm24, 500, 501, {});
  CHECK(d3d24.distinct_values + 1 >= rz24.distinct_values);
  CHECK(rz24.distinct_values + 1 >= d3d24.distinct_values);
}

TEST_CASE("bad intervals are errors naming the culprit", "[depth_precision]") {
  const auto d3d = depth_convention::d3d;
  const mat4<rational> M = perspective<rational>(1, 1, 1, 100, d3d);
  CHECK(error_text([&] { depth_precision(M, d3d, depth_format::f32, 5, 5, {}); }) ==
        "[shadowproof.depth_precision.interval] the eye-distance interval [5, 5] must satisfy 0 < from < to");
  CHECK(error_text([&] { depth_precision(M, d3d, depth_format::f32, 50, 200, {}); }) ==
        "[shadowproof.depth_precision.outside_volume] interval end: distance 200 has NDC depth 199/198, outside the "
        "near/far range of d3d: it would be clipped");
  const mat4<rational> O = orthographic<rational>(-1, 1, -1, 1, 1, 100, d3d);
  CHECK(error_text([&] { depth_precision(O * oblique_shear<rational>(0, 0), d3d, depth_format::f32, 2, 3, {}); }) ==
        "no error");
  // Depth that depends on x: not a function of the eye depth alone.
  mat4<rational> X = O;
  X(2, 0) = 1;
  CHECK(error_text([&] { depth_precision(X, d3d, depth_format::f32, 2, 3, {}); }) ==
        "[shadowproof.depth_precision.not_separable] the projection's depth depends on x or y, not on the eye "
        "depth alone");
}
