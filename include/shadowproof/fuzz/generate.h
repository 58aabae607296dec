#pragma once
/// Reproducible generators of shadow configurations biased to exact degeneracies and their
/// neighbourhoods. Every generated coordinate is a value of the float type F under test, so the
/// exact answer for the very same input is known.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "shadowproof/core/random.h"
#include "shadowproof/core/vec3.h"

namespace shadowproof {

/// One configuration: receiver plane (a, b, c, d), homogeneous light (x, y, z, w), point (x, y, z).
template <class F>
struct generated_case {
  std::array<F, 4> plane{};
  std::array<F, 4> light{};
  std::array<F, 3> point{};
  std::string family;  ///< what the generator aimed at, e.g. "light_parallel", "near_parallel_ulp"
};

/// The fuzzer's random choices: core/random.h's exactly uniform below(n).
using prng_source = random_source;

namespace detail {

template <class Source>
long small_int(Source& src, long r) {
  return static_cast<long>(src.below(static_cast<std::uint64_t>(2 * r + 1))) - r;
}

// Small integers times a power of two: exact in float, and products of a few of them too.
template <class F, class Source>
std::array<F, 3> small_vector(Source& src, long r) {
  return {F(small_int(src, r)), F(small_int(src, r)), F(small_int(src, r))};
}

template <class F, class Source>
std::array<F, 3> nonzero_vector(Source& src, long r) {
  auto v = small_vector<F>(src, r);
  while (is_zero(v)) v[src.below(3)] = F(1 + static_cast<long>(src.below(static_cast<std::uint64_t>(r))));
  return v;
}

// A normal that is axis-aligned half the time (the common ground/wall case).
template <class F, class Source>
std::array<F, 3> random_normal(Source& src) {
  if (src.below(2) == 0) {
    std::array<F, 3> n{0, 0, 0};
    n[src.below(3)] = F(src.below(2) ? 1 : -1) * F(1 + static_cast<long>(src.below(4)));
    return n;
  }
  return nonzero_vector<F>(src, 9);
}

// A vector orthogonal to n, non-zero: n × r for a random r not parallel to n. Exact for the
// small integers used here.
// Falls back to the axes, one of which is never parallel to n, so a source that has run out
// of choices (a short fuzz input) cannot loop forever.
template <class F, class Source>
std::array<F, 3> orthogonal_to(Source& src, const std::array<F, 3>& n) {
  auto u = cross(n, nonzero_vector<F>(src, 5));
  for (std::size_t axis = 0; is_zero(u) && axis < 3; ++axis) {
    std::array<F, 3> e{F(0), F(0), F(0)};
    e[axis] = F(1);
    u = cross(n, e);
  }
  return u;
}

template <class F>
F plane_value(const std::array<F, 4>& P, const std::array<F, 3>& X) {
  return P[0] * X[0] + P[1] * X[1] + P[2] * X[2] + P[3];
}

}  // namespace detail

/// The degenerate families, in the order the generator cycles through them.
inline constexpr std::array<const char*, 10> exact_families = {
    "regular",          "light_parallel",        "light_on_plane", "vertex_on_plane",
    "vertex_at_light_height", "vertex_at_light", "vertex_beyond_light", "vertex_below_receiver",
    "directional_regular", "axis_aligned"};

/// Generates one case from `src`. About a third of the cases are exactly degenerate, a third are
/// those perturbed by one ulp or by 2^-k (k = 1..40) in one coordinate, and the rest are scaled
/// to huge, tiny or subnormal magnitudes, given non-normalised plane equations, lights with
/// w ≠ 1 (2, −1, 3, 1/2) or signed zeros. Scalings by powers of two and by small integers keep
/// an exact degeneracy exact.
/// What an implementation under test accepts; the generator builds every family within it.
struct generator_requirements {
  bool unit_normal = false;       ///< the plane's normal is ±1 on one axis
  bool directional_only = false;  ///< lights have w = 0
  bool point_light_only = false;  ///< lights have w = 1
};

template <class F, class Source>
generated_case<F> generate_shadow_case(Source& src, const generator_requirements& req = {}) {
  using namespace detail;
  generated_case<F> c;
  std::string family = exact_families[src.below(exact_families.size())];
  // Families that need a point light become their directional counterpart and vice versa.
  if (req.directional_only && family != "light_parallel" && family != "vertex_on_plane" &&
      family != "vertex_below_receiver" && family != "axis_aligned")
    family = "directional_regular";
  if (req.point_light_only && (family == "light_parallel" || family == "directional_regular")) family = "regular";
  c.family = family;
  auto n = random_normal<F>(src);
  if (family == "axis_aligned" || req.unit_normal) {
    n = {F(0), F(0), F(0)};
    n[family == "axis_aligned" ? 1 : src.below(3)] = src.below(2) ? F(1) : F(-1);
  }
  auto light_pos = small_vector<F>(src, 12);
  auto V = small_vector<F>(src, 12);
  F d = F(small_int(src, 12));
  std::array<F, 4> P{n[0], n[1], n[2], d};
  c.light = {light_pos[0], light_pos[1], light_pos[2], F(1)};
  if (req.directional_only) {
    const auto dir = nonzero_vector<F>(src, 9);
    c.light = {dir[0], dir[1], dir[2], F(0)};
  }

  if (family == "light_parallel") {
    const auto dir = orthogonal_to<F>(src, n);
    c.light = {dir[0], dir[1], dir[2], F(0)};
  } else if (family == "directional_regular") {
    const auto dir = nonzero_vector<F>(src, 9);
    c.light = {dir[0], dir[1], dir[2], F(0)};
  } else if (family == "light_on_plane") {
    P[3] = -dot(n, light_pos);
  } else if (family == "vertex_on_plane") {
    P[3] = -dot(n, V);
  } else if (family == "vertex_at_light_height") {
    const auto u = orthogonal_to<F>(src, n);
    V = {light_pos[0] + u[0], light_pos[1] + u[1], light_pos[2] + u[2]};
  } else if (family == "vertex_at_light") {
    V = light_pos;
  } else if (family == "vertex_beyond_light" || family == "vertex_below_receiver") {
    // Step along the normal from the light away from the receiver (beyond the light), or from
    // a point of the receiver to the side away from the light (below the receiver).
    const bool beyond = family == "vertex_beyond_light";
    const auto base = beyond ? light_pos : V;
    if (!beyond) P[3] = -dot(n, base);  // put the base point on the receiver
    const F light_value = c.light[3] == 0 ? dot(n, {c.light[0], c.light[1], c.light[2]}) : plane_value(P, light_pos);
    const F side = light_value >= 0 ? F(1) : F(-1);
    const F k = (beyond ? side : -side) * F(1 + static_cast<long>(src.below(4)));
    V = {base[0] + k * n[0], base[1] + k * n[1], base[2] + k * n[2]};
  }
  c.plane = P;
  c.point = V;

  // Variations on top of the exact configuration.
  switch (src.below(9)) {
    case 0: case 1: case 2:
      break;  // exact as constructed
    case 3: {  // one ulp away in one coordinate
      // Coordinates a requirement fixes (a unit normal, the light's w) are not nudged.
      std::array<F*, 11> coords{};
      std::size_t count = 0;
      if (!req.unit_normal) for (int i = 0; i < 3; ++i) coords[count++] = &c.plane[i];
      coords[count++] = &c.plane[3];
      for (int i = 0; i < 3; ++i) coords[count++] = &c.light[i];
      if (!req.directional_only && !req.point_light_only) coords[count++] = &c.light[3];
      for (int i = 0; i < 3; ++i) coords[count++] = &c.point[i];
      F& x = *coords[src.below(count)];
      x = std::nextafter(x, src.below(2) ? std::numeric_limits<F>::infinity() : -std::numeric_limits<F>::infinity());
      c.family += "+ulp";
      break;
    }
    case 4: {  // a 2^-k nudge of the light or the point, rounded to F
      const int k = 1 + static_cast<int>(src.below(40));
      F& x = src.below(2) ? c.light[src.below(3)] : c.point[src.below(3)];
      x = x + std::ldexp(F(src.below(2) ? 1 : -1), -k);
      c.family += "+2^-" + std::to_string(k);
      break;
    }
    case 5: {  // the whole scene scaled by 2^e: huge, tiny, or into the subnormals
      const int choices[] = {40, 100, -40, -100, std::numeric_limits<F>::min_exponent - 8};
      const int e = choices[src.below(5)];
      c.plane[3] = std::ldexp(c.plane[3], e);
      for (int i = 0; i < 3; ++i) {
        c.point[i] = std::ldexp(c.point[i], e);
        if (c.light[3] != 0) c.light[i] = std::ldexp(c.light[i], e);
      }
      c.family += "*2^" + std::to_string(e);
      break;
    }
    case 6: {  // a non-normalised plane equation
      if (req.unit_normal) break;
      const F s = F(src.below(2) ? 3 : -5);
      for (auto& x : c.plane) x *= s;
      c.family += "+plane*" + std::to_string(static_cast<int>(s));
      break;
    }
    case 7: {  // the same light with w ≠ 1
      if (req.point_light_only || c.light[3] == 0) break;
      const F w[] = {F(2), F(-1), F(3), F(0.5)};
      const F s = w[src.below(4)];
      for (auto& x : c.light) x *= s;
      c.family += "+light*w";
      break;
    }
    default: {  // signed zeros
      for (auto& x : c.plane) if (x == 0) x = -F(0);
      for (auto& x : c.point) if (x == 0) x = -F(0);
      c.family += "+signed_zero";
      break;
    }
  }
  // A plane whose normal a ulp nudge zeroed is impossible here (nextafter never gives 0 from
  // a non-zero integer), and a zero light cannot arise: every family keeps one non-zero entry.
  return c;
}

}  // namespace shadowproof
