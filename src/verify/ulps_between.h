// The number of floats (or doubles) between a and b, as core/ulp.h's ulp_distance counts them,
// computed without branches on the signs: a float's bits read as sign and magnitude map to a
// position on one integer line (−0 and +0 the same), and the count is the distance there.
// Shared by the case-by-case grader (oracle.cpp) and the batch grader (batch.cpp).
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

namespace shadowproof::detail {

template <class F>
std::uint64_t ulps_between(F a, F b) {
  using bits_t = std::conditional_t<std::is_same_v<F, float>, std::uint32_t, std::uint64_t>;
  constexpr int shift = std::is_same_v<F, float> ? 31 : 63;
  auto position = [](F x) {
    bits_t raw;
    std::memcpy(&raw, &x, sizeof raw);
    const auto magnitude = static_cast<std::int64_t>(raw & ~(bits_t(1) << shift));
    const std::int64_t negative = -static_cast<std::int64_t>(raw >> shift);  // 0 or −1
    return (magnitude ^ negative) - negative;
  };
  const std::int64_t x = position(a), y = position(b);
  const std::uint64_t d = static_cast<std::uint64_t>(x) - static_cast<std::uint64_t>(y);
  return x >= y ? d : std::uint64_t(0) - d;
}

}  // namespace shadowproof::detail
