#pragma once
// Deterministic random small rationals for property tests (std::mt19937_64 with our own
// mapping, so every platform draws the same numbers).
#include <cstdint>
#include <random>

#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/plane.h"

namespace shadowproof::testing {

class random_exact {
 public:
  explicit random_exact(std::uint64_t seed) : rng_(seed) {}

  /// Integer in [lo, hi].
  long integer(long lo, long hi) {
    return lo + static_cast<long>(rng_() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  /// p/q with |p| ≤ 20, 1 ≤ q ≤ 8; zero about one time in ten.
  rational small() {
    if (integer(0, 9) == 0) return 0;
    rational r(integer(-20, 20), integer(1, 8));
    r.canonicalize();
    return r;
  }
  rational nonzero() {
    rational r = small();
    while (r == 0) r = small();
    return r;
  }
  vec4<rational> point() { return make_point(small(), small(), small()); }
  plane<rational> plane_() {
    rational a = small(), b = small(), c = small();
    while (a == 0 && b == 0 && c == 0) a = small();
    return make_plane(a, b, c, small());
  }
  light<rational> point_light() { return make_light(small(), small(), small(), nonzero()); }
  light<rational> directional_light() {
    rational x = small(), y = small(), z = small();
    while (x == 0 && y == 0 && z == 0) x = small();
    return make_light(x, y, z, rational(0));
  }

 private:
  std::mt19937_64 rng_;
};

}  // namespace shadowproof::testing
