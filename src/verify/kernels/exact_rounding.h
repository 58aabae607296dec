#pragma once
// Correct rounding of an exact quotient num/den of two expansions, every case decided: first
// the double-double quotient and its bound (rounding.h), which settles all but values within
// about 2^-100 relative of a rounding boundary; then the boundary m between the two candidate
// values, and the exact sign of num − m · den, which says on which side of m the quotient lies
// (0: exactly on it, a tie, rounded to even). m is a double for float outputs (a float
// midpoint has 25 significant bits) and the pair y + gap/2 for double outputs.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "expansion.h"
#include "rounding.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// x as a double-double hi + lo within a bound about 2^-104 |x|: the components summed in
/// pair arithmetic from the smallest up. (The largest components alone can be far less
/// accurate: a nonoverlapping expansion may carry a component of a few bits on top.)
inline bounded_pair approximate(const expansion& x) {
  const int n = x.size();
  if (n == 0) return bounded_pair(0.0);
  bounded_pair r(x.component(0));
  for (int i = 1; i < n; ++i) r = r + bounded_pair(x.component(i));
  return r;
}

namespace exact_detail {

inline bool even_float(float x) {
  std::uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return (bits & 1) == 0;
}
inline bool even_double(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return (bits & 1) == 0;
}

// Whether m times every component of den is exact as a two_product (error_free.h): the
// components increase in magnitude, so the first and the last bound them all.
inline bool products_exact(const expansion& den, double m) {
  if (m == 0) return true;
  const double smallest = std::fabs(m) * std::fabs(den.component(0));
  const double largest = std::fabs(m) * std::fabs(den.top());
  return smallest >= 0x1p-968 && largest <= 0x1p1000;
}

// Sign of num/den − (m_hi + m_lo): sign(num − m den) · sign(den), exactly.
inline int side_of(const expansion& num, const expansion& den, double m_hi, double m_lo, bool& ok) {
  ok = products_exact(den, m_hi) && products_exact(den, m_lo);
  if (!ok) return 0;
  expansion r = num;
  for (int i = 0; i < den.size(); ++i) {
    r.add_product(-m_hi, den.component(i));
    if (m_lo != 0) r.add_product(-m_lo, den.component(i));
  }
  ok = !r.overflowed();
  return r.sign() * den.sign();
}

}  // namespace exact_detail

/// num/den (den ≠ 0) correctly rounded to F (float or double), as a double, +0 for 0. False
/// only when an expansion overflowed its capacity, or when the boundary times den's components
/// would come near under- or overflow (a quotient or a denominator of extreme magnitude).
template <class F>
bool round_exact_quotient(const expansion& num, const expansion& den, double& out) {
  if (num.overflowed() || den.overflowed() || den.is_zero()) return false;
  if (num.is_zero()) {
    out = 0;
    return true;
  }
  const pair_denominator d(approximate(den));
  if (!d.usable()) return false;
  double q1, q2, E;
  pair_quotient(approximate(num), d, q1, q2, E);
  double y, r;
  two_sum(q1, q2, y, r);
  bool ok = true;
  if constexpr (std::is_same_v<F, float>) {
    if (round_interval_to_float(y, (std::fabs(r) + E) * inflate, out)) return true;
    // The candidates: the floats nearest to both ends, adjacent since E ≪ their gap.
    const double reach = (std::fabs(r) + E) * 2 * inflate + 3 * unit_roundoff * std::fabs(y);
    const float a = static_cast<float>(y - reach), b = static_cast<float>(y + reach);
    if (!(a < b) || std::nextafter(a, b) != b || (a == 0 && b == 0)) return false;
    double m;  // the boundary between a and b
    if (std::isinf(b)) m = 0x1.ffffffp127;        // FLT_MAX + half its ulp: from there on, +inf
    else if (std::isinf(a)) m = -0x1.ffffffp127;
    else m = (static_cast<double>(a) + static_cast<double>(b)) / 2;  // exact: 25 bits
    const int side = exact_detail::side_of(num, den, m, 0, ok);
    float pick;
    if (side > 0) pick = b;
    else if (side < 0) pick = a;
    else if (std::isinf(b) || std::isinf(a)) pick = std::isinf(b) ? b : a;  // the tie at overflow: even is 2^128
    else pick = exact_detail::even_float(a) ? a : b;
    out = pick == 0 ? 0.0 : static_cast<double>(pick);
    return ok;
  } else {
    if (round_pair_to_double(y, r, E, out)) return true;
    const double magnitude = std::fabs(y);
    if (!(magnitude > 0x1p-1000 && magnitude < 0x1p1000)) return false;  // half gaps are doubles
    // X lies within y + r ± E, |r| ≤ half a gap, E ≪ a gap: the boundary is half the gap to the
    // neighbour on the side where r points (or either side when r = 0 and E straddles).
    const double up = std::nextafter(y, HUGE_VAL), down = std::nextafter(y, -HUGE_VAL);
    const double half_up = (up - y) / 2, half_down = (y - down) / 2;  // exact
    if (!(E * inflate * 4 < half_up && E * inflate * 4 < half_down)) return false;  // not ≪ a gap
    const bool towards_up = r + E * inflate >= half_up;
    const double low = towards_up ? y : down, high = towards_up ? up : y;
    const double m_lo = towards_up ? half_up : -half_down;
    const int side = exact_detail::side_of(num, den, y, m_lo, ok);
    double pick;
    if (side > 0) pick = high;
    else if (side < 0) pick = low;
    else pick = exact_detail::even_double(low) ? low : high;
    out = pick == 0 ? 0.0 : pick;
    return ok;
  }
}

/// x correctly rounded to F (float or double), +0 for 0: the quotient's method without the
/// denominator, so the boundary test needs no product (x − m is a sum of doubles). False only
/// for an overflowed expansion or a double beyond 2^±1000.
template <class F>
bool round_exact_value(const expansion& x, double& out) {
  if (x.overflowed()) return false;
  if (x.is_zero()) {
    out = 0;
    return true;
  }
  const bounded_pair a = approximate(x);
  double y, r;
  two_sum(a.hi, a.lo, y, r);
  // The sign of x − m for a boundary m = m_hi + m_lo, exactly.
  auto side = [&](double m_hi, double m_lo) {
    expansion d = x;
    d.add(-m_hi);
    d.add(-m_lo);
    return d.overflowed() ? 2 : d.sign();
  };
  if constexpr (std::is_same_v<F, float>) {
    if (round_interval_to_float(y, (std::fabs(r) + a.e) * inflate, out)) return true;
    const double reach = (std::fabs(r) + a.e) * 2 * inflate + 3 * unit_roundoff * std::fabs(y);
    const float lo = static_cast<float>(y - reach), hi = static_cast<float>(y + reach);
    if (!(lo < hi) || std::nextafter(lo, hi) != hi) return false;
    double m;
    if (std::isinf(hi)) m = 0x1.ffffffp127;
    else if (std::isinf(lo)) m = -0x1.ffffffp127;
    else m = (static_cast<double>(lo) + static_cast<double>(hi)) / 2;
    const int s = side(m, 0);
    if (s == 2) return false;
    float pick;
    if (s > 0) pick = hi;
    else if (s < 0) pick = lo;
    else if (std::isinf(hi) || std::isinf(lo)) pick = std::isinf(hi) ? hi : lo;
    else pick = exact_detail::even_float(lo) ? lo : hi;
    out = pick == 0 ? 0.0 : static_cast<double>(pick);
    return true;
  } else {
    if (round_pair_to_double(y, r, a.e, out)) return true;
    const double magnitude = std::fabs(y);
    if (!(magnitude > 0x1p-1000 && magnitude < 0x1p1000)) return false;  // half gaps are doubles
    const double up = std::nextafter(y, HUGE_VAL), down = std::nextafter(y, -HUGE_VAL);
    const double half_up = (up - y) / 2, half_down = (y - down) / 2;  // exact
    if (!(a.e * inflate * 4 < half_up && a.e * inflate * 4 < half_down)) return false;
    const bool towards_up = r + a.e * inflate >= half_up;
    const double low = towards_up ? y : down, high = towards_up ? up : y;
    const int s = side(y, towards_up ? half_up : -half_down);
    if (s == 2) return false;
    double pick;
    if (s > 0) pick = high;
    else if (s < 0) pick = low;
    else pick = exact_detail::even_double(low) ? low : high;
    out = pick == 0 ? 0.0 : pick;
    return true;
  }
}

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
