// The kernels of the camera builders with irrational values: perspective-fov and
// perspective-fov-infinite (cot(fovy/2)), look-at and target-to (q/√s). Each evaluates its
// entries with filter numbers (bounded.h: double for f32 cases, double-double for f64 ones)
// and rounds an entry only where the whole bound rounds to one value; otherwise, or for inputs
// outside the ranges below, it returns false and the generic oracle decides (intervals, then
// the rational oracle's MPFR enclosures). Nothing here has an exact stage: an irrational
// value is never a tie, and the exact zeros and the undefined entries are decided on the
// inputs themselves.
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
// from a table (MPFR, at 320 bits) and
//   sin r = r Σ_{k=0..K} (−1)^k r^{2k}/(2k+1)!  + R_s,   |R_s| ≤ |r|^{2K+3}/(2K+3)!,
//   cos r =    Σ_{k=0..K'} (−1)^k r^{2k}/(2k)!  + R_c,   |R_c| ≤ |r|^{2K'+2}/(2K'+2)!,
// (alternating series whose terms decrease, r² < 1) by Horner's rule in filter arithmetic,
// whose operations bound their own rounding errors, with the constants 1/k! from MPFR (each
// within its own stated bound). |r| ≤ 1/128 + 2^-60: K = K' = 5 in double-double leaves a
// truncation below 2^-112 of the sums; K = 2, K' = 3 in double, below 2^-54. The rounding
// errors are of a few 2^-106 (2^-53) relative: the ratio comes out within about 2^-101 of cot
// in double-double (the test measures it on thousands of angles).
//
// q/√s (look-at, target-to: constructions/look_at.h): the filter of look_at.h, written once
// for one case and for the batch's four, on one case.
#include <mpfr.h>

#include <array>
#include <cmath>
#include <type_traits>

#include "../oracle_fast.h"
#include "../operations/irrational_entries.h"
#include "bounded.h"
#include "cotangent.h"
#include "look_at.h"
#include "rounding.h"
#include "view_volume.h"

namespace shadowproof::detail {
namespace {

// ===========================================================================================
// Constants from MPFR, computed once: each c as hi + lo within ± e.

struct constant {
  double hi = 0, lo = 0, e = 0;  // |c − (hi + lo)| ≤ e
};

constexpr long constant_precision = 320;

// c (within a relative 2^-310 of the constant it stands for: one or two MPFR roundings at 320
// bits) split into hi + lo + rest, each part rounded to nearest; e bounds |rest| and the 2^-310.
constant split_constant(mpfr_t c, double* third = nullptr) {
  constant k;
  mpfr_t rest;
  mpfr_init2(rest, constant_precision);
  k.hi = mpfr_get_d(c, MPFR_RNDN);
  mpfr_sub_d(rest, c, k.hi, MPFR_RNDN);  // exact: c and hi agree to 52 bits, rest fits in 320
  k.lo = mpfr_get_d(rest, MPFR_RNDN);
  mpfr_sub_d(rest, rest, k.lo, MPFR_RNDN);  // exact likewise
  if (third) {
    *third = mpfr_get_d(rest, MPFR_RNDN);
    mpfr_sub_d(rest, rest, *third, MPFR_RNDN);
  }
  mpfr_abs(rest, rest, MPFR_RNDN);
  k.e = mpfr_get_d(rest, MPFR_RNDU) + std::fabs(k.hi) * 0x1p-300;
  mpfr_clear(rest);
  return k;
}

struct trig_constants {
  constant inverse_factorial[32];  // 1/k!
  constant pi_tail;                // P2 + P3 ± e: π − P1
  double pi_head = 0;              // P1, the double nearest π (below it)
  constant degree;                 // π/360
  constant sine[53], cosine[53];   // sin(j/64), cos(j/64), j = 0 … 52 (0.8125 > 0.81)

  trig_constants() {
    mpfr_t x, pi;
    mpfr_init2(x, constant_precision);
    mpfr_init2(pi, constant_precision);
    for (unsigned k = 0; k < 32; ++k) {
      mpfr_fac_ui(x, k, MPFR_RNDN);  // exact: 31! < 2^113
      mpfr_ui_div(x, 1, x, MPFR_RNDN);
      inverse_factorial[k] = split_constant(x);
    }
    mpfr_const_pi(pi, MPFR_RNDN);
    double p3 = 0;
    const constant p = split_constant(pi, &p3);
    pi_head = p.hi;
    pi_tail = {p.lo, p3, p.e};
    mpfr_div_ui(x, pi, 360, MPFR_RNDN);
    degree = split_constant(x);
    mpfr_t y;
    mpfr_init2(y, constant_precision);
    for (unsigned j = 0; j < 53; ++j) {
      mpfr_set_ui(x, j, MPFR_RNDN);
      mpfr_div_2ui(x, x, 6, MPFR_RNDN);  // exact
      mpfr_sin(y, x, MPFR_RNDN);
      sine[j] = split_constant(y);
      mpfr_cos(y, x, MPFR_RNDN);
      cosine[j] = split_constant(y);
    }
    mpfr_clear(y);
    mpfr_clear(x);
    mpfr_clear(pi);
    mpfr_free_cache();  // this thread's π cache; MPFR keeps one per thread
  }
};

const trig_constants& constants() {
  static const trig_constants k;
  return k;
}

// A constant as a filter number: double-double, or its head alone in double.
template <class B>
B constant_of(const constant& c) {
  if constexpr (std::is_same_v<B, bounded_pair>) return bounded_pair(c.hi, c.lo, c.e);
  else return bounded(c.hi, std::fabs(c.lo) + c.e);
}

// The value of a filter number as an exact one (its bound set apart), and its bound.
bounded_pair point_of(const bounded_pair& a) { return bounded_pair(a.hi, a.lo, 0.0); }
bounded point_of(const bounded& a) { return bounded(a.v, 0.0); }
double bound_of(const bounded_pair& a) { return a.e; }
double bound_of(const bounded& a) { return a.e; }
double upper_magnitude(const bounded_pair& a) { return (std::fabs(a.hi) + std::fabs(a.lo)) * (1 + 0x1p-50); }
double upper_magnitude(const bounded& a) { return std::fabs(a.v); }
bounded_pair widened(const bounded_pair& a, double e) { return bounded_pair(a.hi, a.lo, a.e + e); }
bounded widened(const bounded& a, double e) { return bounded(a.v, a.e + e); }

// Terms of the Taylor sums of sin r and cos r, |r| ≤ 1/128 + 2^-60: sin to r^(2K+1), cos to
// r^(2K'). Double-double: K = K' = 5, truncation below 2^-116 of sin r and 2^-112 of cos r;
// double: K = 2, K' = 3, below 2^-54 and 2^-70.
template <class B>
struct taylor_terms {
  static constexpr int sine = std::is_same_v<B, bounded_pair> ? 5 : 2;
  static constexpr int cosine = std::is_same_v<B, bounded_pair> ? 5 : 3;
};

// An upper bound on t^n/n! for 0 ≤ t ≤ t_up: n + 1 roundings to nearest, each within a factor
// (1 + 2^-53), covered by (1 + 2^-40); an underflow by underflow_slack.
double truncation_bound(const trig_constants& k, double t_up, int n) {
  const constant& f = k.inverse_factorial[n];
  double p = f.hi + (std::fabs(f.lo) + f.e);
  for (int i = 0; i < n; ++i) p *= t_up;
  return p * (1 + 0x1p-40) + underflow_slack;
}

// Σ_{k=0..K} (−1)^k y^k c[2k + offset] by Horner's rule (y = r², offset 1: sin r / r; 0: cos r).
template <class B>
B alternating_series(const trig_constants& constants, const B& y, int terms, int offset) {
  const auto& f = constants.inverse_factorial;
  B s = constant_of<B>(f[2 * terms + offset]);
  if (terms % 2) s = -s;
  for (int k = terms - 1; k >= 0; --k) {
    const B c = constant_of<B>(f[2 * k + offset]);
    s = s * y + (k % 2 ? -c : c);
  }
  return s;
}

[[gnu::always_inline]] inline bool exact_zero(const bounded_pair& a) { return a.hi == 0 && a.e == 0; }
[[gnu::always_inline]] inline bool exact_zero(const bounded& a) { return a.v == 0 && a.e == 0; }

// a · b, an exact zero when either factor is one. Inlined: called some thirty times a case.
template <class B>
[[gnu::always_inline]] inline B product(const B& a, const B& b) {
  return exact_zero(a) || exact_zero(b) ? B(0.0) : a * b;
}

// sin t and cos t for the filter number t, 0 < t ≤ 0.81 (see the file's comment): with
// a = j/64 the nearest multiple of 1/64 to t̃ and r = t̃ − a (|r| ≤ 1/128 + 2^-60),
//   sin t̃ = sin a cos r + cos a sin r,   cos t̃ = cos a cos r − sin a sin r,
// sin a and cos a from the table, sin r and cos r by their Taylor sums.
template <class B>
void sine_cosine(const trig_constants& k, const B& t, B& sine, B& cosine) {
  const B at = point_of(t);
  const int j = static_cast<int>(std::nearbyint(first_of(at) * 64));  // exact scaling; 0 ≤ j ≤ 52
  const B reduced = at - B(j / 64.0);
  const B r = point_of(reduced);
  const B y = r * r;
  const double r_up = upper_magnitude(r), e_t = bound_of(t) + bound_of(reduced);
  constexpr int K = taylor_terms<B>::sine, K2 = taylor_terms<B>::cosine;
  const B sin_r = widened(r * alternating_series(k, y, K, 1), truncation_bound(k, r_up, 2 * K + 3));
  const B cos_r = widened(alternating_series(k, y, K2, 0), truncation_bound(k, r_up, 2 * K2 + 2));
  const B sin_a = constant_of<B>(k.sine[j]), cos_a = constant_of<B>(k.cosine[j]);
  sine = widened(product(sin_a, cos_r) + cos_a * sin_r, e_t);
  cosine = widened(cos_a * cos_r - product(sin_a, sin_r), e_t);
}

}  // namespace

bool field_of_view_inside_half_turn(double fovy, angle_unit unit) {
  if (!(fovy > 0)) return false;
  return unit == angle_unit::degrees ? fovy < 180 : fovy <= 0x1.921fb54442d18p+1;
}

namespace {

// cot(fovy/2) = num/den as two filter numbers; false outside the half turn or below the
// evaluation's range.
template <class B>
bool half_angle_ratio(double fovy, angle_unit unit, B& num, B& den) {
  if (!field_of_view_inside_half_turn(fovy, unit)) return false;
  const trig_constants& k = constants();
  B t;
  bool complement;  // t = π/2 − x
  if (unit == angle_unit::radians) {
    if (fovy < 0x1p-400) return false;
    complement = fovy > 1.6;
    if (complement) t = scaled(B(k.pi_head - fovy) + constant_of<B>(k.pi_tail), -1);  // P1 − fovy exact
    else t = B(fovy * 0.5);  // exact: fovy is normal
  } else {
    if (fovy < 0x1p-390) return false;
    complement = fovy > 90;
    t = B(complement ? 180 - fovy : fovy) * constant_of<B>(k.degree);  // 180 − fovy exact
  }
  B s, c;
  sine_cosine(k, t, s, c);
  num = complement ? s : c;
  den = complement ? c : s;
  return true;
}

}  // namespace

bool cot_half_angle_pair(double fovy, angle_unit unit, cot_pair& out) {
  bounded_pair num, den;
  if (!half_angle_ratio(fovy, unit, num, den)) return false;
  const pair_denominator d(den);
  if (!d.usable()) return false;
  double q1, q2, E;
  pair_quotient(num, d, q1, q2, E);
  two_sum(q1, q2, out.hi, out.lo);
  out.e = E;
  return true;
}

namespace {

// ===========================================================================================
// The field-of-view kernels.

template <class F>
using filter_number = std::conditional_t<std::is_same_v<F, float>, bounded, bounded_pair>;

// x correctly rounded to F, +0 for 0.
template <class F>
double rounded(double x) {
  const double r = static_cast<double>(static_cast<F>(x));
  return r == 0 ? 0.0 : r;
}

bool moderate(double x, double smallest, double largest) {
  const double a = std::fabs(x);
  return a >= smallest && a <= largest;
}

template <class F, bool infinite>
bool perspective_fov_kernel(const double* in, const conventions& conv, fast_reference& out) {
  refuse_grading_up_to_scale(conv, infinite ? "perspective-fov-infinite" : "perspective-fov");
  using B = filter_number<F>;
  const double aspect = in[1], n = in[2];
  if (!(aspect > 0) || !moderate(aspect, 0x1p-300, 0x1p300)) return false;  // aspect ≤ 0: the generic oracle
  B num, den;
  if (!half_angle_ratio(in[0], conv.angle, num, den)) return false;
  if constexpr (infinite) {
    if (!(n > 0) || !moderate(n, 0x1p-100, 0x1p100)) return false;
    out = fast_reference{};
    out.count = 16;
    // Rows 2 and 3 with the far plane at infinity (project.h): A = −z_far, B = n (z_near − z_far),
    // exact in double, rounded once to F.
    const depth_ndc z = depth_of(conv);
    out.value[10] = static_cast<double>(-z.far_ndc) + 0.0;
    out.value[11] = rounded<F>(n * (z.near_ndc - z.far_ndc));
    out.value[14] = -1;
    with_convention_handedness(true, conv, out);  // the finite kernel applies it itself
  } else {
    // The depth rows of perspective(c, aspect, n, f) do not depend on c and aspect: the
    // perspective kernel's, at c = aspect = 1 (its entries (0, 0) and (1, 1) replaced below).
    const double box[4] = {1.0, 1.0, n, in[3]};
    const bool decided = std::is_same_v<F, float> ? fast_perspective_f32(box, conv, out) : fast_perspective_f64(box, conv, out);
    if (!decided) return false;
    if (!out.defined) return true;  // n or f ≤ 0: no output exists
  }
  double v[2];
  const bool focal = round_quotient(num, prepare(den), v[0]) && round_quotient(num, prepare(den * B(aspect)), v[1]);
  if (!focal) return false;
  out.value[5] = v[0];  // columns 0 and 1: no handedness to apply
  out.value[0] = v[1];
  return true;
}

// ===========================================================================================
// The look-at kernels: the filter of look_at.h on one case.

template <class F, bool placement>
bool look_at_kernel(const double* in, const conventions& conv, fast_reference& out) {
  refuse_grading_up_to_scale(conv, placement ? "target-to" : "look-at");
  double values[16];
  if (!look_at_filter::frame_lanes<F, placement>(in, conv, values)) return false;
  out = fast_reference{};
  out.count = 16;
  for (int j = 0; j < 16; ++j) out.value[j] = values[j];
  return true;
}

}  // namespace

bool fast_perspective_fov_f32(const double* in, const conventions& conv, fast_reference& out) {
  return perspective_fov_kernel<float, false>(in, conv, out);
}
bool fast_perspective_fov_f64(const double* in, const conventions& conv, fast_reference& out) {
  return perspective_fov_kernel<double, false>(in, conv, out);
}
bool fast_perspective_fov_infinite_f32(const double* in, const conventions& conv, fast_reference& out) {
  return perspective_fov_kernel<float, true>(in, conv, out);
}
bool fast_perspective_fov_infinite_f64(const double* in, const conventions& conv, fast_reference& out) {
  return perspective_fov_kernel<double, true>(in, conv, out);
}
bool fast_look_at_f32(const double* in, const conventions& conv, fast_reference& out) {
  return look_at_kernel<float, false>(in, conv, out);
}
bool fast_look_at_f64(const double* in, const conventions& conv, fast_reference& out) {
  return look_at_kernel<double, false>(in, conv, out);
}
bool fast_target_to_f32(const double* in, const conventions& conv, fast_reference& out) {
  return look_at_kernel<float, true>(in, conv, out);
}
bool fast_target_to_f64(const double* in, const conventions& conv, fast_reference& out) {
  return look_at_kernel<double, true>(in, conv, out);
}

}  // namespace shadowproof::detail
