#pragma once
// The filter numbers of the dedicated kernels: an approximation of an exact value together with
// a rigorous bound on the distance between the two, computed in plain round-to-nearest double
// arithmetic (no rounding-mode switch, no branches on the values, so loops over cases
// vectorise). A kernel evaluates its formula once with them; when every output's bound lies
// strictly inside one rounding interval of the output type, that is the correctly rounded
// output. Otherwise the kernel redoes the case with exact expansions (expansion.h).
//
//   bounded       value v within ± e of the exact value. For f32 inputs: every product of two
//                 floats is exact in a double, so most values carry a bound of a few units of
//                 2^-53 relative, far below the 2^-24 that deciding a float rounding needs.
//   bounded_pair  a double-double hi + lo within ± e. For f64 inputs: products of two doubles
//                 are exact pairs (two_product), and sums and products of pairs are accurate to
//                 about 2^-100 relative, enough to decide a double rounding almost always.
//
// Bounds. Round-to-nearest gives |fl(x) − x| ≤ u |fl(x)| (u = 2^-53) in the normal range, and
// sums are exact in the subnormal range; each operation adds the rounding errors it makes,
// with products adding the smallest subnormal for underflow. The bound's own computation
// rounds too, always in operations on non-negative terms; a kernel performs far fewer than
// 2^10 of them, so the bound computed in floating point is below the true one by a factor of at
// most (1 + 2^-41): every decision multiplies the bound by `inflate` = 1 + 2^-40 first.
//
// Range. bounded serves f32 inputs: products of up to four of them and their approximations
// stay within 2^±900, far from under- and overflow. bounded_pair serves f64 inputs in
// polynomials of degree at most d whose magnitudes are 0 or within [2^(52 − 969/d),
// 2^(1000/d − 1)] (kernels check this first, see f64_input_in_range): every exact product of
// d inputs, and every component of an exact expansion built from them (a multiple of
// 2^(d (e_min − 52))), then lies within [2^-969, 2^1000], so every two_product of two such is
// exact (error_free.h). Products of approximations that come closer to underflow add the
// smallest subnormal per rounding to their bound.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "error_free.h"

namespace shadowproof::detail {

/// Multiplies a bound before a decision: covers the rounding of the bound's own computation.
constexpr double inflate = 1 + 0x1p-40;

/// An f64 input of a polynomial of degree ≤ `degree` the bounded_pair kernels accept: 0 or
/// 2^(52 − 969/degree) ≤ |x| ≤ 2^(1000/degree − 1) (see above).
inline bool f64_input_in_range(double x, int degree) {
  const double a = std::fabs(x);
  return x == 0 || (a >= std::ldexp(1.0, 52 - 969 / degree) && a <= std::ldexp(1.0, 1000 / degree - 1));
}

// ===========================================================================================
// bounded: value ± error in double

struct bounded {
  double v = 0;  ///< the approximation
  double e = 0;  ///< |exact − v| ≤ e

  bounded() = default;
  /// An exact double (an input, or a small constant).
  explicit bounded(double x) : v(x), e(0) {}
  bounded(double value, double error) : v(value), e(error) {}
};

inline bounded operator-(const bounded& a) { return {-a.v, a.e}; }
inline bounded operator+(const bounded& a, const bounded& b) {
  const double s = a.v + b.v;
  return {s, a.e + b.e + unit_roundoff * std::fabs(s)};
}
inline bounded operator-(const bounded& a, const bounded& b) { return a + (-b); }
inline bounded operator*(const bounded& a, const bounded& b) {
  const double p = a.v * b.v;
  return {p, std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + unit_roundoff * std::fabs(p) +
                 smallest_subnormal};
}
/// a · b for two f32 inputs: exact in double (48 significant bits at most).
inline bounded exact_product(const bounded& a, const bounded& b) { return bounded(a.v * b.v); }
/// a · 2^k, exact.
inline bounded scaled(const bounded& a, int k) { return {std::ldexp(a.v, k), std::ldexp(a.e, k)}; }

/// −1, 0 or +1 when the bound decides the sign of the exact value, 2 otherwise.
inline int sign(const bounded& a) {
  if (a.e == 0) return a.v > 0 ? 1 : (a.v < 0 ? -1 : 0);
  if (std::fabs(a.v) > a.e * inflate) return a.v > 0 ? 1 : -1;
  return 2;
}

// ===========================================================================================
// bounded_pair: double-double ± error

struct bounded_pair {
  double hi = 0, lo = 0;  ///< the approximation hi + lo, |lo| ≤ u |hi|
  double e = 0;           ///< |exact − (hi + lo)| ≤ e

  bounded_pair() = default;
  /// An exact double (an input, or a small constant).
  explicit bounded_pair(double x) : hi(x), lo(0), e(0) {}
  bounded_pair(double h, double l, double error) : hi(h), lo(l), e(error) {}
};

inline bounded_pair operator-(const bounded_pair& a) { return {-a.hi, -a.lo, a.e}; }
// (a.hi + b.hi) exactly as s + t, then t + a.lo + b.lo rounded twice, renormalised exactly.
inline bounded_pair operator+(const bounded_pair& a, const bounded_pair& b) {
  double s, t;
  two_sum(a.hi, b.hi, s, t);
  const double t1 = t + a.lo;
  const double t2 = t1 + b.lo;
  bounded_pair r;
  two_sum(s, t2, r.hi, r.lo);
  r.e = a.e + b.e + unit_roundoff * (std::fabs(t1) + std::fabs(t2));
  return r;
}
inline bounded_pair operator-(const bounded_pair& a, const bounded_pair& b) { return a + (-b); }
// a.hi b.hi exactly as p + q; the cross terms a.hi b.lo + a.lo b.hi rounded; a.lo b.lo (below
// u² |a b|) left to the bound; then the propagated errors |a| b.e + |b| a.e + a.e b.e.
inline bounded_pair operator*(const bounded_pair& a, const bounded_pair& b) {
  double p, q;
  two_product(a.hi, b.hi, p, q);
  const double c1 = a.hi * b.lo, c2 = a.lo * b.hi;
  const double c = c1 + c2;
  const double t = q + c;
  bounded_pair r;
  two_sum(p, t, r.hi, r.lo);
  const double abs_a = std::fabs(a.hi) + std::fabs(a.lo), abs_b = std::fabs(b.hi) + std::fabs(b.lo);
  r.e = unit_roundoff * (std::fabs(c1) + std::fabs(c2) + std::fabs(c) + std::fabs(t)) +
        std::fabs(a.lo) * std::fabs(b.lo) + abs_a * b.e + abs_b * a.e + a.e * b.e + 8 * smallest_subnormal;
  return r;
}
/// a · b for two f64 inputs: exact as a pair (two_product).
inline bounded_pair exact_product(const bounded_pair& a, const bounded_pair& b) {
  bounded_pair r;
  two_product(a.hi, b.hi, r.hi, r.lo);
  return r;
}
/// a · 2^k, exact.
inline bounded_pair scaled(const bounded_pair& a, int k) {
  return {std::ldexp(a.hi, k), std::ldexp(a.lo, k), std::ldexp(a.e, k)};
}

/// −1, 0 or +1 when the bound decides the sign of the exact value, 2 otherwise.
inline int sign(const bounded_pair& a) {
  if (a.e == 0 && a.lo == 0) return a.hi > 0 ? 1 : (a.hi < 0 ? -1 : 0);
  // |lo| ≤ u |hi|: hi carries the sign when |hi| (1 − u) > e.
  if (std::fabs(a.hi) * (1 - 0x1p-52) > a.e * inflate) return a.hi > 0 ? 1 : -1;
  return 2;
}

}  // namespace shadowproof::detail
