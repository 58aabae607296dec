#pragma once
/// Reproducible random choices: std::mt19937_64 (fully specified by the standard) with our own
/// mappings to integers, because std::uniform_int_distribution's output differs between
/// standard libraries. The same seed gives the same choices on every platform.
#include <cstdint>
#include <limits>
#include <random>

namespace shadowproof {

class random_source {
 public:
  explicit random_source(std::uint64_t seed) : engine_(seed) {}

  /// The next 64 raw bits.
  std::uint64_t raw() { return engine_(); }

  /// Exactly uniform in [0, n) (rejection sampling); 0 for n ≤ 1.
  std::uint64_t below(std::uint64_t n) {
    if (n <= 1) return 0;
    const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % n;
    std::uint64_t x;
    do x = engine_(); while (x >= limit);
    return x % n;
  }

  /// In [lo, hi] by one draw reduced modulo the span: cheaper than below(), with a bias below
  /// span / 2^64 (under 2^-40 for spans under 2^24, the generators' ranges).
  long long integer(long long lo, long long hi) {
    return lo + static_cast<long long>(raw() % static_cast<std::uint64_t>(hi - lo + 1));
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace shadowproof
