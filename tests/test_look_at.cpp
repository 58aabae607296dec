// Look-at cameras as exact q/√s entries: the frame is orthonormal exactly, the placement
// inverts the view, and the float routine stays within a few ulps on an ordinary camera.
#include <catch2/catch.hpp>

#include <cmath>

#include "shadowproof/constructions/look_at.h"

using namespace shadowproof;

namespace {

vec3<rational> v3(long x, long y, long z) { return {rational(x), rational(y), rational(z)}; }

// (row r)·(row s) of the rotation, exactly: Σ q_r q_s / √(s_r s_s). Rows share one radicand
// each, so the sum is (Σ q_r q_s) / √(s_r s_s), and it is 0 or 1 exactly when Σ q_r q_s is 0
// or (Σ q_r q_s)² = s_r s_s.
rational dot_numerators(const std::array<root_entry<rational>, 16>& m, int r, int s) {
  rational d = 0;
  for (int c = 0; c < 3; ++c) d += m[static_cast<std::size_t>(4 * r + c)].numerator * m[static_cast<std::size_t>(4 * s + c)].numerator;
  return d;
}

}  // namespace

TEST_CASE("the look-at rotation is orthonormal exactly, for both handednesses", "[look_at]") {
  for (handedness h : {handedness::right, handedness::left}) {
    const auto m = look_at_entries(v3(3, -2, 7), v3(-1, 4, 2), v3(1, 5, -2), h);
    for (int r = 0; r < 3; ++r) {
      const rational n = dot_numerators(m, r, r);
      CHECK(n * n == m[static_cast<std::size_t>(4 * r)].radicand * m[static_cast<std::size_t>(4 * r)].radicand);
      for (int s = r + 1; s < 3; ++s) CHECK(dot_numerators(m, r, s) == 0);
    }
    // Right-handed: x × y = z (a rotation, determinant +1), checked on the numerators:
    // X × Y = (|X|² ) W for the unnormalised frame.
    const camera_frame<rational> f = make_camera_frame(v3(3, -2, 7), v3(-1, 4, 2), v3(1, 5, -2), h);
    const vec3<rational> xy = detail::cross3(f.X, f.Y);
    for (int i = 0; i < 3; ++i) CHECK(xy[static_cast<std::size_t>(i)] == f.xx * f.W[static_cast<std::size_t>(i)]);
  }
}

TEST_CASE("the eye maps to the origin of eye space, and the target onto the view axis", "[look_at]") {
  const vec3<rational> eye = v3(3, -2, 7), target = v3(-1, 4, 2), up = v3(0, 1, 0);
  for (handedness h : {handedness::right, handedness::left}) {
    const auto m = look_at_entries(eye, target, up, h);
    // Row r applied to (p, 1) is (q_r · p + t_r)/√s_r: zero numerators mean zero coordinates.
    auto row_numerator = [&](int r, const vec3<rational>& p) {
      rational s = m[static_cast<std::size_t>(4 * r + 3)].numerator;
      for (int c = 0; c < 3; ++c) s += m[static_cast<std::size_t>(4 * r + c)].numerator * p[static_cast<std::size_t>(c)];
      return s;
    };
    for (int r = 0; r < 3; ++r) CHECK(row_numerator(r, eye) == 0);
    CHECK(row_numerator(0, target) == 0);
    CHECK(row_numerator(1, target) == 0);
    // Right-handed cameras look down −z, left-handed ones down +z.
    CHECK(sgn(row_numerator(2, target)) == (h == handedness::right ? -1 : 1));
  }
}

TEST_CASE("degenerate cameras leave exactly the undefined axes undefined", "[look_at]") {
  const auto parallel = look_at_entries(v3(1, 0, 1), v3(0, 0, 0), v3(2, 0, 2), handedness::right);
  for (std::size_t i = 0; i < 8; ++i) CHECK_FALSE(parallel[i].defined);
  for (std::size_t i = 8; i < 16; ++i) CHECK(parallel[i].defined);
  const auto collapsed = target_to_entries(v3(1, 2, 3), v3(1, 2, 3), v3(0, 1, 0), handedness::right);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < 3; ++c) CHECK_FALSE(collapsed[4 * r + c].defined);
  CHECK(collapsed[3].defined);  // the placement's translation is the eye itself
  CHECK(collapsed[3].numerator == 1);
}

TEST_CASE("the float look-at is within a few ulps of the exact one on an ordinary camera", "[look_at]") {
  const vec3<double> eye{3, -2, 7}, target{-1, 4, 2}, up{0, 1, 0};
  const mat4<double> f = look_at_float(eye, target, up, handedness::right);
  const auto m = look_at_entries(v3(3, -2, 7), v3(-1, 4, 2), v3(0, 1, 0), handedness::right);
  for (std::size_t i = 0; i < 16; ++i) {
    const double exact = m[i].numerator.get_d() / std::sqrt(m[i].radicand.get_d());
    CHECK(std::fabs(f(i / 4, i % 4) - exact) <= 8 * std::numeric_limits<double>::epsilon() * (std::fabs(exact) + 1));
  }
}
