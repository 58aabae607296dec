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
// with products adding underflow_slack (error_free.h) for underflow. The bound's own computation
// rounds too, always in operations on non-negative terms; a kernel performs far fewer than
// 2^10 of them, so the bound computed in floating point is below the true one by a factor of at
// most (1 + 2^-41): every decision multiplies the bound by `inflate` = 1 + 2^-40 first.
//
// Range. bounded serves f32 inputs: products of up to four of them and their approximations
// stay within 2^±900, far from under- and overflow. bounded_pair serves f64 inputs in
// polynomials of degree at most d whose magnitudes are 0 or within [2^(52 − 969/d),
// 2^(1000/d − 1)] (kernels check this first: f64_input_in_range): every exact product of
// d inputs, and every component of an exact expansion built from them (a multiple of
// 2^(d (e_min − 52))), then lies within [2^-969, 2^1000], so every two_product of two such is
// exact (error_free.h). Products of approximations that come closer to underflow add
// underflow_slack to their bound.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "error_free.h"
#include "lanes.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// Multiplies a bound before a decision: covers the rounding of the bound's own computation.
constexpr double inflate = 1 + 0x1p-40;

/// An f64 input of a polynomial of degree ≤ `degree` the bounded_pair kernels accept: 0 or
/// 2^(52 − 969/degree) ≤ |x| ≤ 2^(1000/degree − 1) (see above).
template <int degree, class R>
inline auto f64_input_in_range(R x) {
  constexpr double smallest = power_of_two(52 - 969 / degree), largest = power_of_two(1000 / degree - 1);
  const R a = magnitude(x);
  return (x == R(0.0)) | ((a >= R(smallest)) & (a <= R(largest)));
}
/// An f32 input: exactly a float.
template <class R>
inline auto f32_input_in_range(R x) {
  return round_to_float_value(x) == x;
}

// ===========================================================================================
// bounded: value ± error in double

template <class R>
struct basic_bounded {
  R v = R(0.0);  ///< the approximation
  R e = R(0.0);  ///< |exact − v| ≤ e

  basic_bounded() = default;
  /// An exact value (an input, or a small constant).
  explicit basic_bounded(R x) : v(x), e(R(0.0)) {}
  basic_bounded(R value, R error) : v(value), e(error) {}
};
using bounded = basic_bounded<double>;

template <class R>
inline basic_bounded<R> operator-(const basic_bounded<R>& a) { return {-a.v, a.e}; }
template <class R>
inline basic_bounded<R> operator+(const basic_bounded<R>& a, const basic_bounded<R>& b) {
  const R s = a.v + b.v;
  return {s, a.e + b.e + R(unit_roundoff) * magnitude(s)};
}
template <class R>
inline basic_bounded<R> operator-(const basic_bounded<R>& a, const basic_bounded<R>& b) { return a + (-b); }
template <class R>
inline basic_bounded<R> operator*(const basic_bounded<R>& a, const basic_bounded<R>& b) {
  const R p = a.v * b.v;
  return {p, magnitude(a.v) * b.e + magnitude(b.v) * a.e + a.e * b.e + R(unit_roundoff) * magnitude(p) +
                 R(underflow_slack)};
}
/// a · b for two f32 inputs: exact in double (48 significant bits at most).
template <class R>
inline basic_bounded<R> exact_product(const basic_bounded<R>& a, const basic_bounded<R>& b) {
  return basic_bounded<R>(a.v * b.v);
}
/// An output that is the product of two inputs, a · b, by its correct rounding to the output
/// type: for f32 inputs the product itself, exact in double.
template <class R>
inline basic_bounded<R> rounded_product(const basic_bounded<R>& a, const basic_bounded<R>& b) {
  return exact_product(a, b);
}
/// a · 2^k, exact (k small: no over- or underflow).
template <class R>
inline basic_bounded<R> scaled(const basic_bounded<R>& a, int k) {
  const R factor(power_of_two(k));
  return {a.v * factor, a.e * factor};
}

/// a · c for c = 0 or ±2^k (small k): exact.
template <class R>
inline basic_bounded<R> scaled_by(const basic_bounded<R>& a, double c) {
  return {a.v * R(c), a.e * R(std::fabs(c))};
}

/// −1, 0 or +1 when the bound decides the sign of the exact value, 2 otherwise.
inline int sign(const bounded& a) {
  if (a.e == 0) return a.v > 0 ? 1 : (a.v < 0 ? -1 : 0);
  if (std::fabs(a.v) > a.e * inflate) return a.v > 0 ? 1 : -1;
  return 2;
}
/// The bound excludes 0 (lane by lane).
template <class R>
inline auto nonzero(const basic_bounded<R>& a) {
  return magnitude(a.v) > a.e * R(inflate);
}
/// The leading part of the approximation (its sign is the exact sign where nonzero says so).
template <class R>
inline R first_of(const basic_bounded<R>& a) { return a.v; }

// ===========================================================================================
// bounded_pair: double-double ± error

template <class R>
struct basic_bounded_pair {
  R hi = R(0.0), lo = R(0.0);  ///< the approximation hi + lo, |lo| ≤ u |hi|
  R e = R(0.0);                ///< |exact − (hi + lo)| ≤ e

  basic_bounded_pair() = default;
  /// An exact value (an input, or a small constant).
  explicit basic_bounded_pair(R x) : hi(x), lo(R(0.0)), e(R(0.0)) {}
  basic_bounded_pair(R h, R l, R error) : hi(h), lo(l), e(error) {}
};
using bounded_pair = basic_bounded_pair<double>;

template <class R>
inline basic_bounded_pair<R> operator-(const basic_bounded_pair<R>& a) { return {-a.hi, -a.lo, a.e}; }
// (a.hi + b.hi) exactly as s + t, then t + a.lo + b.lo rounded twice, renormalised exactly.
template <class R>
inline basic_bounded_pair<R> operator+(const basic_bounded_pair<R>& a, const basic_bounded_pair<R>& b) {
  R s, t;
  two_sum(a.hi, b.hi, s, t);
  const R t1 = t + a.lo;
  const R t2 = t1 + b.lo;
  basic_bounded_pair<R> r;
  two_sum(s, t2, r.hi, r.lo);
  r.e = a.e + b.e + R(unit_roundoff) * (magnitude(t1) + magnitude(t2));
  return r;
}
template <class R>
inline basic_bounded_pair<R> operator-(const basic_bounded_pair<R>& a, const basic_bounded_pair<R>& b) {
  return a + (-b);
}
// a.hi b.hi exactly as p + q; the cross terms a.hi b.lo + a.lo b.hi rounded; a.lo b.lo (below
// u² |a b|) left to the bound; then the propagated errors |a| b.e + |b| a.e + a.e b.e, and
// underflow_slack for the roundings that might underflow (at most 8 · 2^-1075).
template <class R>
inline basic_bounded_pair<R> operator*(const basic_bounded_pair<R>& a, const basic_bounded_pair<R>& b) {
  R p, q;
  two_product(a.hi, b.hi, p, q);
  const R c1 = a.hi * b.lo, c2 = a.lo * b.hi;
  const R c = c1 + c2;
  const R t = q + c;
  basic_bounded_pair<R> r;
  two_sum(p, t, r.hi, r.lo);
  const R abs_a = magnitude(a.hi) + magnitude(a.lo), abs_b = magnitude(b.hi) + magnitude(b.lo);
  r.e = R(unit_roundoff) * (magnitude(c1) + magnitude(c2) + magnitude(c) + magnitude(t)) +
        magnitude(a.lo) * magnitude(b.lo) + abs_a * b.e + abs_b * a.e + a.e * b.e + R(underflow_slack);
  return r;
}
/// a · b for two f64 inputs: exact as a pair (two_product).
template <class R>
inline basic_bounded_pair<R> exact_product(const basic_bounded_pair<R>& a, const basic_bounded_pair<R>& b) {
  basic_bounded_pair<R> r;
  two_product(a.hi, b.hi, r.hi, r.lo);
  return r;
}
/// An output that is the product of two inputs, a · b, by its correct rounding to the output
/// type: for f64 inputs IEEE multiplication rounds correctly, so fl(a · b) stands exactly for
/// the output's rounded value (not for the product; use it only as an output by itself).
template <class R>
inline basic_bounded_pair<R> rounded_product(const basic_bounded_pair<R>& a, const basic_bounded_pair<R>& b) {
  return basic_bounded_pair<R>(a.hi * b.hi);
}
/// a · 2^k, exact (k small: no over- or underflow).
template <class R>
inline basic_bounded_pair<R> scaled(const basic_bounded_pair<R>& a, int k) {
  const R factor(power_of_two(k));
  return {a.hi * factor, a.lo * factor, a.e * factor};
}

/// a · c for c = 0 or ±2^k (small k): exact.
template <class R>
inline basic_bounded_pair<R> scaled_by(const basic_bounded_pair<R>& a, double c) {
  return {a.hi * R(c), a.lo * R(c), a.e * R(std::fabs(c))};
}

/// −1, 0 or +1 when the bound decides the sign of the exact value, 2 otherwise.
inline int sign(const bounded_pair& a) {
  if (a.e == 0) return a.hi > 0 ? 1 : (a.hi < 0 ? -1 : 0);  // lo = 0 when hi = 0
  // |lo| ≤ u |hi|: hi carries the sign when |hi| (1 − 2u) > e.
  if (std::fabs(a.hi) * (1 - 0x1p-52) > a.e * inflate) return a.hi > 0 ? 1 : -1;
  return 2;
}
/// The bound excludes 0 (lane by lane).
template <class R>
inline auto nonzero(const basic_bounded_pair<R>& a) {
  return magnitude(a.hi) * R(1 - 0x1p-52) > a.e * R(inflate);
}
/// The leading part of the approximation (its sign is the exact sign where nonzero says so).
template <class R>
inline R first_of(const basic_bounded_pair<R>& a) { return a.hi; }

// ===========================================================================================
// Exact zeros, for formulas whose zero entries must stay exact (a frame with an axis-aligned
// up, sin 0 in a table)

/// The value is exactly 0 (lane by lane).
template <class R>
inline auto exact_zero(const basic_bounded<R>& a) {
  return (a.v == R(0.0)) & (a.e == R(0.0));
}
template <class R>
inline auto exact_zero(const basic_bounded_pair<R>& a) {
  return (a.hi == R(0.0)) & (a.e == R(0.0));  // lo = 0 when hi = 0
}
/// a where m is false, an exact 0 where it is true.
template <class M, class R>
inline basic_bounded<R> zero_where(M m, const basic_bounded<R>& a) {
  return {select(m, R(0.0), a.v), select(m, R(0.0), a.e)};
}
template <class M, class R>
inline basic_bounded_pair<R> zero_where(M m, const basic_bounded_pair<R>& a) {
  return {select(m, R(0.0), a.hi), select(m, R(0.0), a.lo), select(m, R(0.0), a.e)};
}
/// a · b, an exact zero where either factor is one (the product's bound is not 0 otherwise).
template <class B>
[[gnu::always_inline]] inline B zero_preserving_product(const B& a, const B& b) {
  return zero_where(exact_zero(a) | exact_zero(b), a * b);
}

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
