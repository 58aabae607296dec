#pragma once
// Certified rounding tests: the output-type value nearest to every point within a bound of an
// approximation, if they all share one; a quotient num/den of two bounded values likewise.
// A test that cannot decide says so and the kernel goes on with exact expansions
// (exact_rounding.h), which also settle ties. The exact value 0 rounds to +0, as the rational
// oracle's does. Written over the real type R (lanes.h): each test returns a mask, true in
// the lanes it decides, and writes every lane's candidate.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "bounded.h"
#include "lanes.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

// ===========================================================================================
// To float (f32 kernels)

/// The float nearest to every point of [y − E, y + E] (E ≥ 0, an already inflated bound), if
/// they share one. Round-to-nearest is monotone, so equal roundings of both ends decide every
/// point between; `reach` pushes the ends out past the rounding of their own computation
/// (|fl(y ± reach) − (y ± reach)| ≤ u (|y| + reach) + 2^-1075 ≤ reach − E). A reach of
/// underflow_slack still rounds both ends of a zero value to ±0 (floats stop at 2^-149).
template <class R>
inline auto round_interval_to_float(R y, R E, R& out) {
  const R reach = (E + R(3 * unit_roundoff) * magnitude(y)) * R(inflate) + R(underflow_slack);
  const R a = round_to_float_value(y - reach), b = round_to_float_value(y + reach);
  out = select(a == R(0.0), R(0.0), a);
  return a == b;
}

/// The exact value within x correctly rounded to float: one correct rounding when x is exact.
template <class R>
inline auto round_to_float(const basic_bounded<R>& x, R& out) {
  const auto exact = x.e == R(0.0);
  const R direct = round_to_float_value(x.v);
  R via_bound;
  const auto decided = round_interval_to_float(x.v, x.e * R(inflate), via_bound);
  out = select(exact, select(direct == R(0.0), R(0.0), direct), via_bound);
  return exact | decided;
}

/// A denominator D within d prepared once for every quotient over it: its inflated bound,
/// a lower bound on |D| and an upper bound on its reciprocal (the quotients' bounds multiply by
/// it: a division per quotient costs more than the rest of its bound), and 1/d.v rounded once.
template <class R>
struct basic_bounded_denominator {
  R v = R(0.0), e = R(0.0), lower = R(0.0), inverse = R(0.0), inverse_lower = R(0.0);
  basic_bounded_denominator() = default;
  explicit basic_bounded_denominator(const basic_bounded<R>& d) : v(d.v), e(d.e * R(inflate)) {
    lower = (magnitude(v) - e) * R(1 - 0x1p-50);  // the subtraction's rounding, pushed down
    inverse = R(1.0) / v;
    inverse_lower = R(1.0) / lower * R(1 + 0x1p-50);  // ≥ 1/lower: one rounding, pushed up
  }
  /// The bound excludes 0 (else no quotient over it is decided).
  auto usable() const { return lower > R(0.0); }
};
using bounded_denominator = basic_bounded_denominator<double>;

/// num/den correctly rounded to float. With q = fl(n · fl(1/d)) = (n/d)(1 + δ), |δ| ≤ 2u + u²:
/// |N/D − q| ≤ (e_n + |n/d| e_d) / min |D| + 3u |q|, and |n/d| ≤ |q| (1 + 2^-50).
template <class R>
inline auto round_quotient_to_float(const basic_bounded<R>& num, const basic_bounded_denominator<R>& den, R& out) {
  const R q = num.v * den.inverse;
  const R E = (num.e * R(inflate) + magnitude(q) * R(1 + 0x1p-50) * den.e) * den.inverse_lower * R(inflate) +
              R(3 * unit_roundoff) * magnitude(q);
  return den.usable() & round_interval_to_float(q, E, out);
}

// ===========================================================================================
// To double (f64 kernels)

/// The double nearest to every point of hi + lo ± E, if they share one: with (y, r) =
/// TwoSum(hi, lo) the points are y + r ± E, and y is their rounding when the whole range lies
/// strictly inside half the gap to y's neighbour on each side (gaps halve exactly; a point
/// exactly at half a gap is a tie, never decided here). Zero when hi + lo = 0 and E = 0 (every
/// positive bound reaches 2^-1075, half the smallest subnormal, as doubles are its multiples).
template <class R>
inline auto round_pair_to_double(R hi, R lo, R E, R& out) {
  R y, r;
  two_sum(hi, lo, y, r);
  const R slack = E * R(inflate * (1 + 0x1p-50));  // also covers the rounding of the rooms below
  const R size = magnitude(y);
  const R outward = select(y > R(0.0), r, -r);  // r measured away from zero
  R above, below;
  neighbours(size, above, below);
  const R half_up = (above - size) * R(0.5), half_down = (size - below) * R(0.5);
  // y = 0: the neighbours are meaningless and every comparison below with NaN is false.
  const auto inside = (slack < half_up - outward) & (slack < half_down + outward) & (size < R(0x1p1000)) &
                      (size > R(0.0));
  const auto zero = (y == R(0.0)) & (slack == R(0.0));
  out = select(y == R(0.0), R(0.0), y);
  return inside | zero;
}

/// The exact value within x correctly rounded to double.
template <class R>
inline auto round_to_double(const basic_bounded_pair<R>& x, R& out) {
  const auto exact = (x.e == R(0.0)) & (x.lo == R(0.0));  // an exact double
  R via_bound;
  const auto decided = round_pair_to_double(x.hi, x.lo, x.e, via_bound);
  out = select(exact, select(x.hi == R(0.0), R(0.0), x.hi), via_bound);
  return exact | decided;
}

/// A double-double denominator D within d, prepared once for every quotient over it.
template <class R>
struct basic_pair_denominator {
  R hi = R(0.0), lo = R(0.0), e = R(0.0), lower = R(0.0), inverse = R(0.0), inverse_lower = R(0.0);
  basic_pair_denominator() = default;
  explicit basic_pair_denominator(const basic_bounded_pair<R>& d) : hi(d.hi), lo(d.lo), e(d.e * R(inflate)) {
    lower = (magnitude(hi) - magnitude(lo) - e) * R(1 - 0x1p-50);
    inverse = R(1.0) / hi;
    inverse_lower = R(1.0) / lower * R(1 + 0x1p-50);  // ≥ 1/lower: one rounding, pushed up
  }
  /// The bound excludes 0.
  auto usable() const { return lower > R(0.0); }
};
using pair_denominator = basic_pair_denominator<double>;

/// num/den as q1 + q2 within ± E: q1 = n.hi/d.hi (through the reciprocal), the remainder
/// R1 = n − q1 d in pair arithmetic (its own bound r1.e), q2 = R1/d.hi. Then
///   N − (q1 + q2) D = (N − n) − (q1 + q2)(D − d) + (r1 − q2 d.hi) − q2 d.lo ± r1.e,
/// with |r1.hi − q2 d.hi| ≤ 3u |r1.hi|, so
///   |N/D − (q1 + q2)| ≤ (e_n + (|q1| + |q2|) e_d + 3u |r1.hi| + |r1.lo| + r1.e + |q2 d.lo|) / min |D|.
template <class R>
inline void pair_quotient(const basic_bounded_pair<R>& num, const basic_pair_denominator<R>& den, R& q1, R& q2,
                          R& E) {
  q1 = num.hi * den.inverse;
  const basic_bounded_pair<R> r1 = basic_bounded_pair<R>(num.hi, num.lo, R(0.0)) -
                                   basic_bounded_pair<R>(q1) * basic_bounded_pair<R>(den.hi, den.lo, R(0.0));
  q2 = r1.hi * den.inverse;
  E = (num.e * R(inflate) + (magnitude(q1) + magnitude(q2)) * den.e + R(3 * unit_roundoff) * magnitude(r1.hi) +
       magnitude(r1.lo) + r1.e * R(inflate) + magnitude(q2 * den.lo) * R(1 + 0x1p-50)) *
      den.inverse_lower * R(inflate);
}

/// num/den correctly rounded to double; an exactly zero numerator gives 0.
template <class R>
inline auto round_quotient_to_double(const basic_bounded_pair<R>& num, const basic_pair_denominator<R>& den, R& out) {
  R q1, q2, E, rounded;
  pair_quotient(num, den, q1, q2, E);
  const auto decided = round_pair_to_double(q1, q2, E, rounded);
  const auto zero = exact_zero(num);
  out = select(zero, R(0.0), rounded);
  return den.usable() & (zero | decided);
}

/// Σ t[0..n) of n exact doubles (overwritten) as hi + lo within ± E. `sweeps` sweeps of TwoSum
/// along the terms (Ogita, Rump and Oishi's VecSum, each an error-free transformation: the exact
/// sum does not change) leave in the last term the recursive sum and in the others its errors,
/// of the order u^sweeps Σ|t|; then hi + lo = TwoSum(last, fl(Σ others)), within
/// γ_{n−2} Σ|others| (recursive summation, Higham §4.2) of the exact sum, which E bounds (sums
/// are exact near underflow). All terms zero: an exact zero.
template <int n, int sweeps, class R>
inline void swept_sum(R* t, R& hi, R& lo, R& E) {
  SHADOWPROOF_UNROLL
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    SHADOWPROOF_UNROLL
    for (int i = 1; i < n; ++i) {
      R s, e;
      two_sum(t[i], t[i - 1], s, e);
      t[i] = s;
      t[i - 1] = e;
    }
  }
  R rest = t[0], mass = magnitude(t[0]);
  SHADOWPROOF_UNROLL
  for (int i = 1; i < n - 1; ++i) {
    rest = rest + t[i];
    mass = mass + magnitude(t[i]);
  }
  two_sum(t[n - 1], rest, hi, lo);
  E = mass * R((n - 1) * unit_roundoff * inflate);
}

/// The sum of n exact doubles t[0..n) (overwritten) correctly rounded to double, when a bound
/// decides it. After one sweep (swept_sum) the errors left in the terms are of the order
/// u Σ|t| and the bound of the order u² Σ|t|: enough for every sum that does not cancel to
/// within about 2^-50 of its terms or fall near a rounding boundary. Where a lane is left
/// undecided a second sweep brings the errors to the order u² Σ|t| (plus u times the sum
/// itself) and the bound to u³ Σ|t|: sums that cancel to a few ulps of their terms, like a
/// plane value of a point on the plane, are then decided with about 2^-100 relative accuracy,
/// and an exact zero sum usually leaves every term 0 (bound 0). Both bounds hold, so a lane is
/// decided where either decides: the same lanes whether or not a vector skips the second sweep.
template <int n, class R>
inline auto round_sum_to_double(R* t, R& out) {
  R hi, lo, E, first;
  swept_sum<n, 1>(t, hi, lo, E);
  const auto decided = round_pair_to_double(hi, lo, E, first);
  if constexpr (!std::is_same_v<R, double>) {  // a vector: the second sweep only if a lane needs it
    if (!any_lane(!decided)) {
      out = first;
      return decided;
    }
  }
  R second;
  swept_sum<n, 1>(t, hi, lo, E);  // the second sweep over the terms the first left
  const auto decided_again = round_pair_to_double(hi, lo, E, second);
  out = select(decided, first, second);
  return decided | decided_again;
}

// ===========================================================================================
// Quotients of two exact values of the output type

/// num/den correctly rounded to F where num and den are exact values of F (a zero bound, and
/// floats for F = float): one division in F, which IEEE arithmetic rounds correctly. Decided
/// where both are such values and the quotient is a normal number of F, or num = 0 (then +0;
/// den ≠ 0 is the caller's test); the rest (subnormal, overflowing, undefined) is left to the
/// tests that decide them one case at a time.
template <class F, class R>
inline auto round_direct_quotient(const basic_bounded<R>& num, const basic_bounded<R>& den, R& out) {
  static_assert(std::is_same_v<F, float>, "bounded numbers serve the f32 kernels");
  const auto exact = (num.e == R(0.0)) & (den.e == R(0.0)) & (round_to_float_value(num.v) == num.v) &
                     (round_to_float_value(den.v) == den.v);
  const R q = quotient_in_float(num.v, den.v);
  const auto normal = (magnitude(q) >= R(0x1p-126)) & (magnitude(q) <= R(0x1.fffffep127));
  const auto zero = num.v == R(0.0);
  out = select(zero, R(0.0), q);
  return exact & (normal | zero);
}
template <class F, class R>
inline auto round_direct_quotient(const basic_bounded_pair<R>& num, const basic_bounded_pair<R>& den, R& out) {
  static_assert(std::is_same_v<F, double>, "bounded pairs serve the f64 kernels");
  const auto exact = (num.e == R(0.0)) & (num.lo == R(0.0)) & (den.e == R(0.0)) & (den.lo == R(0.0));
  const R q = num.hi / den.hi;
  const auto normal = (magnitude(q) >= R(0x1p-1022)) & (magnitude(q) <= R(0x1.fffffffffffffp1023));
  const auto zero = num.hi == R(0.0);
  out = select(zero, R(0.0), q);
  return exact & (normal | zero);
}

// ===========================================================================================
// The two families under one name, for kernels written once over the filter number type.

template <class R>
inline auto round_value(const basic_bounded<R>& x, R& out) { return round_to_float(x, out); }
template <class R>
inline auto round_value(const basic_bounded_pair<R>& x, R& out) { return round_to_double(x, out); }

/// The prepared denominator of each filter number type.
template <class R>
inline basic_bounded_denominator<R> prepare(const basic_bounded<R>& d) { return basic_bounded_denominator<R>(d); }
template <class R>
inline basic_pair_denominator<R> prepare(const basic_bounded_pair<R>& d) { return basic_pair_denominator<R>(d); }

template <class R>
inline auto round_quotient(const basic_bounded<R>& n, const basic_bounded_denominator<R>& d, R& out) {
  return round_quotient_to_float(n, d, out);
}
template <class R>
inline auto round_quotient(const basic_bounded_pair<R>& n, const basic_pair_denominator<R>& d, R& out) {
  return round_quotient_to_double(n, d, out);
}

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
