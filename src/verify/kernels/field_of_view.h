#pragma once
// cot(fovy/2) and the focal scales of perspective-fov and perspective-fov-infinite, written
// once over the real type R (lanes.h: double for one case, four doubles in batch_avx2.cpp) and
// the filter numbers over it (bounded.h: double for f32 cases, double-double for f64 ones).
// The kernels for one case (camera.cpp) and the batch filters (batch_filters.h) run the same
// code; nothing branches on a lane's value: each lane computes both alternatives and keeps one.
//
// cot(fovy/2). With x the half angle, x in (0, π/2):
//   x ≤ 0.8 (radians) or fovy ≤ 90°:  t = x, cot x = cos t / sin t;
//   otherwise:                        t = π/2 − x, cot x = sin t / cos t,
// with t = (π − fovy)/2 = ((P1 − fovy) + P2 + P3)/2 in radians (P1 − fovy exact by Sterbenz,
// π = P1 + P2 + P3 ± 2^-300 from MPFR), t = fovy·(π/360) or (180 − fovy)·(π/360) in degrees
// (180 − fovy exact by Sterbenz, π/360 a double-double constant from MPFR). So t ≤ 0.81, and
// t is a filter number whose bound e_t covers every rounding of its computation; sin and cos
// are 1-Lipschitz, so sin and cos at the point t̃ of the filter number, each widened by e_t,
// enclose them at the exact t. At t̃ = a + r, a = j/64 the nearest multiple of 1/64 (r = t̃ − a
// in filter arithmetic, its bound added to e_t), by the addition formulas with sin a and cos a
// from a table (MPFR, at 320 bits: cotangent.h) and
//   sin r = r Σ_{k=0..K} (−1)^k r^{2k}/(2k+1)!  + R_s,   |R_s| ≤ |r|^{2K+3}/(2K+3)!,
//   cos r =    Σ_{k=0..K'} (−1)^k r^{2k}/(2k)!  + R_c,   |R_c| ≤ |r|^{2K'+2}/(2K'+2)!,
// (alternating series whose terms decrease, r² < 1) by Horner's rule in filter arithmetic,
// whose operations bound their own rounding errors, with the constants 1/k! from MPFR (each
// within its own stated bound). |r| ≤ 1/128 + 2^-60: K = K' = 5 in double-double leaves a
// truncation below 2^-112 of the sums; K = 2, K' = 3 in double, below 2^-54. The rounding
// errors are of a few 2^-106 (2^-53) relative: the ratio comes out within about 2^-101 of cot
// in double-double (the test measures it on thousands of angles).
//
// j is t̃·64 rounded to the nearest integer, (t̃·64 + 1.5·2^52) − 1.5·2^52 (exact for
// 0 ≤ t̃·64 < 2^51, ties to even as nearbyint), and sin a, cos a are gathered from the table's
// columns at j. A lane outside the ranges (fovy outside the half turn or below 2^-400 radians,
// 2^-390 degrees; aspect outside [2^-300, 2^300]) computes with the harmless fovy = aspect = 1
// and is left undecided.
#include <cmath>
#include <type_traits>

#include "bounded.h"
#include "cotangent.h"
#include "fraction_form.h"
#include "lanes.h"
#include "perspective.h"
#include "rounding.h"
#include "view_volume.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {
namespace field_of_view_lanes {

// ===========================================================================================
// Filter numbers over lanes: constants, selections, the point and the bound apart.

/// A constant as a filter number: double-double, or its head alone in double.
template <class R>
inline void set_constant(const trig_constant& c, basic_bounded_pair<R>& out) {
  out = basic_bounded_pair<R>(R(c.hi), R(c.lo), R(c.e));
}
template <class R>
inline void set_constant(const trig_constant& c, basic_bounded<R>& out) {
  out = basic_bounded<R>(R(c.hi), R(std::fabs(c.lo) + c.e));
}
template <class B>
inline B constant_of(const trig_constant& c) {
  B b;
  set_constant(c, b);
  return b;
}

/// Entry j of a column of the table as a filter number (j an integer in [0, 53) in every lane).
template <class R>
inline void set_entry(const double* hi, const double* lo, const double* e, const double*, R j,
                      basic_bounded_pair<R>& out) {
  out = basic_bounded_pair<R>(gather(hi, j), gather(lo, j), gather(e, j));
}
template <class R>
inline void set_entry(const double* hi, const double*, const double*, const double* bound, R j,
                      basic_bounded<R>& out) {
  out = basic_bounded<R>(gather(hi, j), gather(bound, j));
}

/// m ? a : b, lane by lane, for filter numbers.
template <class M, class R>
inline basic_bounded_pair<R> choose(M m, const basic_bounded_pair<R>& a, const basic_bounded_pair<R>& b) {
  return {select(m, a.hi, b.hi), select(m, a.lo, b.lo), select(m, a.e, b.e)};
}
template <class M, class R>
inline basic_bounded<R> choose(M m, const basic_bounded<R>& a, const basic_bounded<R>& b) {
  return {select(m, a.v, b.v), select(m, a.e, b.e)};
}

/// The value of a filter number as an exact one (its bound set apart), and its bound.
template <class R>
inline basic_bounded_pair<R> point_of(const basic_bounded_pair<R>& a) { return {a.hi, a.lo, R(0.0)}; }
template <class R>
inline basic_bounded<R> point_of(const basic_bounded<R>& a) { return basic_bounded<R>(a.v); }
template <class R>
inline R bound_of(const basic_bounded_pair<R>& a) { return a.e; }
template <class R>
inline R bound_of(const basic_bounded<R>& a) { return a.e; }
/// An upper bound on the magnitude of the value.
template <class R>
inline R upper_magnitude(const basic_bounded_pair<R>& a) {
  return (magnitude(a.hi) + magnitude(a.lo)) * R(1 + 0x1p-50);
}
template <class R>
inline R upper_magnitude(const basic_bounded<R>& a) { return magnitude(a.v); }
/// The bound widened by e.
template <class R>
inline basic_bounded_pair<R> widened(const basic_bounded_pair<R>& a, R e) { return {a.hi, a.lo, a.e + e}; }
template <class R>
inline basic_bounded<R> widened(const basic_bounded<R>& a, R e) { return {a.v, a.e + e}; }

// ===========================================================================================
// sin t and cos t for 0 < t ≤ 0.81, cot(fovy/2) as their ratio.

/// Terms of the Taylor sums of sin r and cos r, |r| ≤ 1/128 + 2^-60: sin to r^(2K+1), cos to
/// r^(2K'). Double-double: K = K' = 5, truncation below 2^-116 of sin r and 2^-112 of cos r;
/// double: K = 2, K' = 3, below 2^-54 and 2^-70. In double-double, the Horner steps from
/// s_3 up for sin r / r (|s_3| ≤ 1/7!) and from s_4 up for cos r (|s_4| ≤ 1/8!) are taken in
/// double: their rounding errors reach the sums below 2^-53 · 2^-12.3 · 2^-42 = 2^-107 and
/// 2^-53 · 2^-15.3 · 2^-56, beside the 2^-106 of each double-double step.
template <class B>
struct taylor_terms {
  static constexpr bool pair = std::is_same_v<B, basic_bounded_pair<decltype(first_of(B()))>>;
  static constexpr int sine = pair ? 5 : 2;
  static constexpr int cosine = pair ? 5 : 3;
  static constexpr int sine_in_double = pair ? 3 : 0;
  static constexpr int cosine_in_double = pair ? 4 : 0;
};

/// An upper bound on t^n/n! for 0 ≤ t ≤ t_up: n + 1 roundings to nearest, each within a factor
/// (1 + 2^-53), covered by (1 + 2^-40); an underflow by underflow_slack.
template <int n, class R>
inline R truncation_bound(const trig_table& k, R t_up) {
  const trig_constant& f = k.inverse_factorial[n];
  R p = R(f.hi + (std::fabs(f.lo) + f.e));
  SHADOWPROOF_UNROLL
  for (int i = 0; i < n; ++i) p = p * t_up;
  return p * R(1 + 0x1p-40) + R(underflow_slack);
}

/// The filter number in double standing for a double-double one (hi alone, |lo| in the bound),
/// and back.
template <class R>
inline basic_bounded<R> in_double(const basic_bounded<R>& a) { return a; }
template <class R>
inline basic_bounded<R> in_double(const basic_bounded_pair<R>& a) { return {a.hi, magnitude(a.lo) + a.e}; }
template <class R>
inline void set_from_double(const basic_bounded<R>& a, basic_bounded<R>& out) { out = a; }
template <class R>
inline void set_from_double(const basic_bounded<R>& a, basic_bounded_pair<R>& out) { out = {a.v, R(0.0), a.e}; }

/// Σ_{k=0..K} (−1)^k y^k c[2k + offset] by Horner's rule (y = r², offset 1: sin r / r; 0: cos r):
/// s_K = ±c[2K + offset], s_i = s_{i+1} y + (−1)^i c[2i + offset], the sum s_0. The steps
/// i ≥ `in_double` are taken in double whatever B (their rounding errors, about 2^-53 |s_i|,
/// reach the sum multiplied by y^i ≤ 2^-14i), the others in B.
template <int terms, int offset, int in_double_from, class B>
inline B alternating_series(const trig_table& k, const B& y) {
  using D = decltype(in_double(y));
  const auto& f = k.inverse_factorial;
  const D y_double = in_double(y);
  D head = constant_of<D>(f[2 * terms + offset]);
  if (terms % 2) head = -head;
  SHADOWPROOF_UNROLL
  for (int i = terms - 1; i >= in_double_from; --i) {
    const D c = constant_of<D>(f[2 * i + offset]);
    head = head * y_double + (i % 2 ? -c : c);
  }
  B s;
  set_from_double(head, s);
  SHADOWPROOF_UNROLL
  for (int i = in_double_from - 1; i >= 0; --i) {
    const B c = constant_of<B>(f[2 * i + offset]);
    s = s * y + (i % 2 ? -c : c);
  }
  return s;
}

/// sin t and cos t for the filter number t, 0 < t ≤ 0.81 in every lane (see the file's
/// comment): with a = j/64 the nearest multiple of 1/64 to t̃ and r = t̃ − a,
///   sin t̃ = sin a cos r + cos a sin r,   cos t̃ = cos a cos r − sin a sin r,
/// sin a and cos a from the table, sin r and cos r by their Taylor sums.
template <class B>
inline void sine_cosine(const trig_table& k, const B& t, B& sine, B& cosine) {
  using R = decltype(first_of(t));
  const B at = point_of(t);
  const R j = (first_of(at) * R(64.0) + R(0x1.8p52)) - R(0x1.8p52);  // exact scaling; 0 ≤ j ≤ 52
  const B reduced = at - B(j * R(1.0 / 64));
  const B r = point_of(reduced);
  const B y = r * r;
  const R r_up = upper_magnitude(r), e_t = bound_of(t) + bound_of(reduced);
  using terms = taylor_terms<B>;
  constexpr int K = terms::sine, K2 = terms::cosine;
  const B sin_r = widened(r * alternating_series<K, 1, terms::sine_in_double>(k, y), truncation_bound<2 * K + 3>(k, r_up));
  const B cos_r = widened(alternating_series<K2, 0, terms::cosine_in_double>(k, y), truncation_bound<2 * K2 + 2>(k, r_up));
  B sin_a, cos_a;
  set_entry(k.sine_hi, k.sine_lo, k.sine_e, k.sine_bound, j, sin_a);
  set_entry(k.cosine_hi, k.cosine_lo, k.cosine_e, k.cosine_bound, j, cos_a);
  sine = widened(zero_preserving_product(sin_a, cos_r) + cos_a * sin_r, e_t);
  cosine = widened(cos_a * cos_r - zero_preserving_product(sin_a, sin_r), e_t);
}

/// cot(fovy/2) = num/den as two filter numbers, in the lanes where fovy lies in the half turn
/// and above the evaluation's range (the mask returned; see the file's comment).
template <class B, class R>
inline auto half_angle_ratio(R fovy, angle_unit unit, B& num, B& den) {
  const trig_table& k = cotangent_constants();
  decltype(fovy < fovy) in_range, complement;  // complement: t = π/2 − x
  B t;
  if (unit == angle_unit::radians) {
    // fovy < π exactly when fovy ≤ P1 (field_of_view_inside_half_turn).
    in_range = (fovy >= R(0x1p-400)) & (fovy <= R(0x1.921fb54442d18p+1));
    const R x = select(in_range, fovy, R(1.0));
    complement = x > R(1.6);
    const B beyond = scaled(B(R(k.pi_head) - x) + constant_of<B>(k.pi_tail), -1);  // P1 − x exact there
    t = choose(complement, beyond, B(x * R(0.5)));  // x/2 exact: x is normal
  } else {
    in_range = (fovy >= R(0x1p-390)) & (fovy < R(180.0));
    const R x = select(in_range, fovy, R(1.0));
    complement = x > R(90.0);
    t = B(select(complement, R(180.0) - x, x)) * constant_of<B>(k.degree);  // 180 − x exact there
  }
  B s, c;
  sine_cosine(k, t, s, c);
  num = choose(complement, s, c);
  den = choose(complement, c, s);
  return in_range;
}

// ===========================================================================================
// The focal scales of both builders.

/// cot(fovy/2) as num/den (half_angle_ratio), in the lanes where also 2^-300 ≤ aspect ≤ 2^300;
/// aspect becomes 1 in the other lanes.
template <class B, class R>
inline auto focal_ratio(R fovy, R& aspect, angle_unit unit, B& num, B& den) {
  const auto aspect_in_range = (aspect >= R(0x1p-300)) & (aspect <= R(0x1p300));
  aspect = select(aspect_in_range, aspect, R(1.0));
  return aspect_in_range & half_angle_ratio(fovy, unit, num, den);
}

/// The entries (1, 1) = cot(fovy/2) and (0, 0) = cot(fovy/2)/aspect correctly rounded, from
/// focal_ratio's num/den: the lanes where both are decided.
template <class B, class R>
inline auto round_focal_scales(const B& num, const B& den, R aspect, R& x_scale, R& y_scale) {
  return round_quotient(num, prepare(den), y_scale) & round_quotient(num, prepare(den * B(aspect)), x_scale);
}

/// The batch filter of perspective-fov (infinite: perspective-fov-infinite) over lanes, for
/// batch_filters.h, right-handed (the batch sends left-handed cases to the kernel for one case):
/// its 16 canonical outputs and the lanes where all are decided. The depth rows of
/// perspective(c, aspect, n, f) do not depend on c and aspect: perspective_form's filter at
/// c = aspect = 1. With the far plane at infinity (project.h) they are A = −z_far and
/// B = n (z_near − z_far), exact in double (z_near − z_far ∈ {−2, −1, 1}), rounded once to F,
/// for 2^-100 ≤ n ≤ 2^100. Nothing is decided when grading up to scale (the kernel for one
/// case refuses it).
template <class F, bool infinite>
struct field_of_view_op {
  static constexpr int inputs = infinite ? 3 : 4, outputs = 16;
  template <class R>
  static auto run(R* x, const conventions& conv, R* values, R&) {
    using B = filter_number_of<F, R>;
    auto ok = !no_lanes(x[0]);
    if constexpr (infinite) {
      const depth_ndc z = depth_of(conv);
      const R n = x[2];
      ok = (n >= R(0x1p-100)) & (n <= R(0x1p100));
      SHADOWPROOF_UNROLL
      for (int j = 0; j < 16; ++j) values[j] = R(0.0);
      values[10] = R(static_cast<double>(-z.far_ndc) + 0.0);
      const R offset = n * R(static_cast<double>(z.near_ndc - z.far_ndc));
      if constexpr (std::is_same_v<F, float>) values[11] = round_to_float_value(offset);
      else values[11] = offset;
      values[14] = R(-1.0);
    } else {
      R box[4] = {R(1.0), R(1.0), x[2], x[3]};
      ok = filter_lanes<perspective_form, F, R>(box, conv, values);
    }
    R aspect = x[1];
    B num, den;
    ok = ok & focal_ratio(x[0], aspect, conv.angle, num, den);
    ok = ok & round_focal_scales(num, den, aspect, values[0], values[5]);
    if (conv.homogeneous) ok = no_lanes(x[0]);
    return ok;
  }
};

}  // namespace field_of_view_lanes
}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
