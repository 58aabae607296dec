#pragma once
/// Distances between floats: units in the last place, bits of error, bit-exact hex text.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

namespace shadowproof {

/// Position of a finite x on the line of representable values of its type: consecutive
/// floats (or doubles) get consecutive integers, −0 and +0 both get 0, negatives are negative.
/// Precondition: x is finite (NaN has no position).
template <class T>
std::int64_t ordinal(T x) {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>, "float or double only");
  if constexpr (std::is_same_v<T, float>) {
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const auto magnitude = static_cast<std::int64_t>(bits & 0x7fffffffu);
    return (bits >> 31) ? -magnitude : magnitude;
  } else {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const auto magnitude = static_cast<std::int64_t>(bits & 0x7fffffffffffffffull);
    return (bits >> 63) ? -magnitude : magnitude;
  }
}

/// Number of representable T values strictly after min(a, b) up to and including max(a, b):
/// 0 when a == b (also for −0 vs +0), 1 for neighbours. Finite a, b only; the distance between
/// the largest finite values of opposite sign fits in 64 unsigned bits.
template <class T>
std::uint64_t ulp_distance(T a, T b) {
  const std::int64_t x = ordinal(a), y = ordinal(b);
  // The difference can exceed INT64_MAX (doubles of opposite sign near the largest finite
  // value), but never 2^64: subtract in unsigned arithmetic, where wrap-around gives it exactly.
  return x > y ? static_cast<std::uint64_t>(x) - static_cast<std::uint64_t>(y)
               : static_cast<std::uint64_t>(y) - static_cast<std::uint64_t>(x);
}

/// Bits of error = log2(ulps + 1): 0 for a correctly rounded result, 1 for one ulp off, and
/// the number of trailing significand bits that are wrong in general (53 = nothing right in
/// a double, 24 in a float; larger values mean the wrong binade or the wrong sign).
inline double bits_of_error(std::uint64_t ulps) {
  return std::log2(static_cast<double>(ulps) + 1.0);
}

/// Bit-exact C99 hex text of x ("0x1.8p+0", "-0x0p+0", "inf", "-inf", "nan"), read back
/// exactly by parse_number. A float is printed through its exact double value.
inline std::string hex_string(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%a", x);
  return buffer;
}

}  // namespace shadowproof
