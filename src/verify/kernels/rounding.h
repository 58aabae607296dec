#pragma once
// Certified rounding tests: the output-type value nearest to every point within a bound of an
// approximation, if they all share one; a quotient num/den of two bounded values likewise.
// A test that cannot decide returns false and the kernel goes on with exact expansions
// (exact_rounding.h), which also settle ties. The exact value 0 rounds to +0, as the rational
// oracle's does.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "bounded.h"

namespace shadowproof::detail {

// ===========================================================================================
// To float (f32 kernels)

/// The float nearest to every point of [y − E, y + E] (E ≥ 0, an already inflated bound), if
/// they share one. Round-to-nearest is monotone, so equal roundings of both ends decide every
/// point between; `reach` pushes the ends out past the rounding of their own computation
/// (|fl(y ± reach) − (y ± reach)| ≤ u (|y| + reach) + 2^-1075 ≤ reach − E).
inline bool round_interval_to_float(double y, double E, double& out) {
  const double reach = (E + 3 * unit_roundoff * std::fabs(y)) * inflate + 0x1p-1060;
  const float a = static_cast<float>(y - reach), b = static_cast<float>(y + reach);
  out = a == 0 ? 0.0 : static_cast<double>(a);
  return a == b;
}

/// The exact value within x correctly rounded to float.
inline bool round_to_float(const bounded& x, double& out) {
  if (x.e == 0) {  // x.v is the exact value: one correct rounding
    const float a = static_cast<float>(x.v);
    out = a == 0 ? 0.0 : static_cast<double>(a);
    return true;
  }
  return round_interval_to_float(x.v, x.e * inflate, out);
}

/// A denominator D within d prepared once for every quotient over it: its inflated bound,
/// a lower bound on |D|, and 1/d.v rounded once.
struct bounded_denominator {
  double v = 0, e = 0, lower = 0, inverse = 0;
  bool usable = false;  ///< the bound excludes 0 (else no quotient over it is decided)
  bounded_denominator() = default;
  explicit bounded_denominator(const bounded& d) : v(d.v), e(d.e * inflate) {
    lower = (std::fabs(v) - e) * (1 - 0x1p-50);  // the subtraction's rounding, pushed down
    usable = lower > 0;
    inverse = 1 / v;
  }
};

/// num/den correctly rounded to float. With q = fl(n · fl(1/d)) = (n/d)(1 + δ), |δ| ≤ 2u + u²:
/// |N/D − q| ≤ (e_n + |n/d| e_d) / min |D| + 3u |q|, and |n/d| ≤ |q| (1 + 2^-50).
inline bool round_quotient_to_float(const bounded& num, const bounded_denominator& den, double& out) {
  const double q = num.v * den.inverse;
  const double E = (num.e * inflate + std::fabs(q) * (1 + 0x1p-50) * den.e) / den.lower * inflate +
                   3 * unit_roundoff * std::fabs(q);
  return den.usable && round_interval_to_float(q, E, out);
}

// ===========================================================================================
// To double (f64 kernels)

/// The double nearest to every point of hi + lo ± E, if they share one: with (y, r) =
/// TwoSum(hi, lo) the points are y + r ± E, and y is their rounding when the whole range lies
/// strictly inside half the gap to y's neighbour on each side (gaps halve exactly; a point
/// exactly at half a gap is a tie, never decided here). Zero when hi + lo = 0 and E = 0 (every
/// positive bound reaches 2^-1075, half the smallest subnormal, as doubles are its multiples).
inline bool round_pair_to_double(double hi, double lo, double E, double& out) {
  double y, r;
  two_sum(hi, lo, y, r);
  const double slack = E * inflate * (1 + 0x1p-50);  // also covers the rounding of the rooms below
  if (y == 0) {
    out = 0;
    return slack == 0;
  }
  const double magnitude = std::fabs(y);
  if (!(magnitude < 0x1p1000)) return false;  // no overflow threshold to consider
  const double outward = y > 0 ? r : -r;      // r measured away from zero
  // Neighbours of a positive finite double: its bit pattern ± 1.
  std::uint64_t bits;
  std::memcpy(&bits, &magnitude, sizeof bits);
  const std::uint64_t bits_above = bits + 1, bits_below = bits - 1;
  double above, below;
  std::memcpy(&above, &bits_above, sizeof above);
  std::memcpy(&below, &bits_below, sizeof below);
  const double half_up = (above - magnitude) / 2, half_down = (magnitude - below) / 2;
  out = y;
  return slack < half_up - outward && slack < half_down + outward;
}

/// The exact value within x correctly rounded to double.
inline bool round_to_double(const bounded_pair& x, double& out) {
  if (x.e == 0 && x.lo == 0) {  // an exact double
    out = x.hi == 0 ? 0.0 : x.hi;
    return true;
  }
  return round_pair_to_double(x.hi, x.lo, x.e, out);
}

/// A double-double denominator D within d, prepared once for every quotient over it.
struct pair_denominator {
  double hi = 0, lo = 0, e = 0, lower = 0, inverse = 0;
  bool usable = false;  ///< the bound excludes 0
  pair_denominator() = default;
  explicit pair_denominator(const bounded_pair& d) : hi(d.hi), lo(d.lo), e(d.e * inflate) {
    lower = (std::fabs(hi) - std::fabs(lo) - e) * (1 - 0x1p-50);
    usable = lower > 0;
    inverse = 1 / hi;
  }
};

/// num/den as q1 + q2 within ± E: q1 = n.hi/d.hi (through the reciprocal), the remainder
/// R1 = n − q1 d in pair arithmetic (its own bound r1.e), q2 = R1/d.hi. Then
///   N − (q1 + q2) D = (N − n) − (q1 + q2)(D − d) + (r1 − q2 d.hi) − q2 d.lo ± r1.e,
/// with |r1.hi − q2 d.hi| ≤ 3u |r1.hi|, so
///   |N/D − (q1 + q2)| ≤ (e_n + (|q1| + |q2|) e_d + 3u |r1.hi| + |r1.lo| + r1.e + |q2 d.lo|) / min |D|.
inline void pair_quotient(const bounded_pair& num, const pair_denominator& den, double& q1, double& q2, double& E) {
  q1 = num.hi * den.inverse;
  const bounded_pair r1 = bounded_pair(num.hi, num.lo, 0) - bounded_pair(q1) * bounded_pair(den.hi, den.lo, 0);
  q2 = r1.hi * den.inverse;
  E = (num.e * inflate + (std::fabs(q1) + std::fabs(q2)) * den.e + 3 * unit_roundoff * std::fabs(r1.hi) +
       std::fabs(r1.lo) + r1.e * inflate + std::fabs(q2 * den.lo) * (1 + 0x1p-50)) /
      den.lower * inflate;
}

/// num/den correctly rounded to double.
inline bool round_quotient_to_double(const bounded_pair& num, const pair_denominator& den, double& out) {
  if (!den.usable) return false;
  if (num.hi == 0 && num.e == 0) {  // exactly 0 (lo = 0 when hi = 0)
    out = 0;
    return true;
  }
  double q1, q2, E;
  pair_quotient(num, den, q1, q2, E);
  return round_pair_to_double(q1, q2, E, out);
}

// ===========================================================================================
// The two families under one name, for kernels written once over the filter number type.

inline bool round_value(const bounded& x, double& out) { return round_to_float(x, out); }
inline bool round_value(const bounded_pair& x, double& out) { return round_to_double(x, out); }

/// The prepared denominator of each filter number type.
inline bounded_denominator prepare(const bounded& d) { return bounded_denominator(d); }
inline pair_denominator prepare(const bounded_pair& d) { return pair_denominator(d); }

inline bool round_quotient(const bounded& n, const bounded_denominator& d, double& out) {
  return round_quotient_to_float(n, d, out);
}
inline bool round_quotient(const bounded_pair& n, const pair_denominator& d, double& out) {
  return round_quotient_to_double(n, d, out);
}

}  // namespace shadowproof::detail
