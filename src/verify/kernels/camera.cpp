// The kernels of the camera builders with irrational values: perspective-fov and
// perspective-fov-infinite (cot(fovy/2)), look-at and target-to (q/√s). Each evaluates its
// entries with filter numbers (bounded.h: double for f32 cases, double-double for f64 ones)
// and rounds an entry only where the whole bound rounds to one value; otherwise, or for inputs
// outside the ranges below, it returns false and the generic oracle decides (intervals, then
// the rational oracle's MPFR enclosures). Nothing here has an exact stage: an irrational
// value is never a tie, and the exact zeros and the undefined entries are decided on the
// inputs themselves.
//
// q/√s (look-at, target-to: constructions/look_at.h). The frame W = ±(eye − target) (exact as
// a pair: TwoSum), X = up × W, Y = W × X, the squared lengths and the translations, in filter
// arithmetic; a product with an exact zero factor is an exact zero, so the zero entries of a
// frame with an axis-aligned up stay exact. √s by `root` (its bound below), the quotient by
// the kernels' certified quotient rounding (rounding.h).
#include <mpfr.h>

#include <array>
#include <cmath>
#include <type_traits>

#include "../oracle_fast.h"
#include "../operations/irrational_entries.h"
#include "bounded.h"
#include "cotangent.h"
#include "field_of_view.h"
#include "rounding.h"
#include "view_volume.h"

namespace shadowproof::detail {
namespace {

// ===========================================================================================
// The cotangent's constants from MPFR, computed once: each c as hi + lo within ± e.

constexpr long constant_precision = 320;

// c (within a relative 2^-310 of the constant it stands for: one or two MPFR roundings at 320
// bits) split into hi + lo + rest, each part rounded to nearest; e bounds |rest| and the 2^-310.
trig_constant split_constant(mpfr_t c, double* third = nullptr) {
  trig_constant k;
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

// Entry j of a column pair of the table (sine or cosine).
void set_table_entry(const trig_constant& c, int j, double* hi, double* lo, double* e, double* bound) {
  hi[j] = c.hi;
  lo[j] = c.lo;
  e[j] = c.e;
  bound[j] = std::fabs(c.lo) + c.e;
}

trig_table make_trig_table() {
  trig_table k;
  mpfr_t x, pi;
  mpfr_init2(x, constant_precision);
  mpfr_init2(pi, constant_precision);
  for (unsigned i = 0; i < 32; ++i) {
    mpfr_fac_ui(x, i, MPFR_RNDN);  // exact: 31! < 2^113
    mpfr_ui_div(x, 1, x, MPFR_RNDN);
    k.inverse_factorial[i] = split_constant(x);
  }
  mpfr_const_pi(pi, MPFR_RNDN);
  double p3 = 0;
  const trig_constant p = split_constant(pi, &p3);
  k.pi_head = p.hi;
  k.pi_tail = {p.lo, p3, p.e};
  mpfr_div_ui(x, pi, 360, MPFR_RNDN);
  k.degree = split_constant(x);
  mpfr_t y;
  mpfr_init2(y, constant_precision);
  for (int j = 0; j < trig_table::steps; ++j) {
    mpfr_set_ui(x, static_cast<unsigned>(j), MPFR_RNDN);
    mpfr_div_2ui(x, x, 6, MPFR_RNDN);  // exact
    mpfr_sin(y, x, MPFR_RNDN);
    set_table_entry(split_constant(y), j, k.sine_hi, k.sine_lo, k.sine_e, k.sine_bound);
    mpfr_cos(y, x, MPFR_RNDN);
    set_table_entry(split_constant(y), j, k.cosine_hi, k.cosine_lo, k.cosine_e, k.cosine_bound);
  }
  mpfr_clear(y);
  mpfr_clear(x);
  mpfr_clear(pi);
  mpfr_free_cache();  // this thread's π cache; MPFR keeps one per thread
  return k;
}

}  // namespace

const trig_table& cotangent_constants() {
  static const trig_table k = make_trig_table();
  return k;
}

namespace {

[[gnu::always_inline]] inline bool exact_zero(const bounded_pair& a) { return a.hi == 0 && a.e == 0; }
[[gnu::always_inline]] inline bool exact_zero(const bounded& a) { return a.v == 0 && a.e == 0; }

// a · b, an exact zero when either factor is one. Inlined: called some thirty times a case.
template <class B>
[[gnu::always_inline]] inline B product(const B& a, const B& b) {
  return exact_zero(a) || exact_zero(b) ? B(0.0) : a * b;
}

}  // namespace

bool field_of_view_inside_half_turn(double fovy, angle_unit unit) {
  if (!(fovy > 0)) return false;
  return unit == angle_unit::degrees ? fovy < 180 : fovy <= 0x1.921fb54442d18p+1;
}

bool cot_half_angle_pair(double fovy, angle_unit unit, cot_pair& out) {
  bounded_pair num, den;
  if (!field_of_view_lanes::half_angle_ratio(fovy, unit, num, den)) return false;
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

// The focal scales by field_of_view.h's code over one lane (the batch filters' too), the depth
// rows by the perspective kernel (with its exact stage) or the infinite far plane's constants.
template <class F, bool infinite>
bool perspective_fov_kernel(const double* in, const conventions& conv, fast_reference& out) {
  refuse_grading_up_to_scale(conv, infinite ? "perspective-fov-infinite" : "perspective-fov");
  using B = filter_number<F>;
  const double n = in[2];
  double aspect = in[1];
  B num, den;
  if (!field_of_view_lanes::focal_ratio(in[0], aspect, conv.angle, num, den)) return false;  // aspect ≤ 0: the generic oracle
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
  double x_scale, y_scale;
  if (!field_of_view_lanes::round_focal_scales(num, den, aspect, x_scale, y_scale)) return false;
  out.value[0] = x_scale;  // columns 0 and 1: no handedness to apply
  out.value[5] = y_scale;
  return true;
}

// ===========================================================================================
// The look-at kernels.

// a − b for two inputs: exact as a pair; in double within u |a − b| (0 exactly when a = b).
bounded_pair difference(double a, double b, const bounded_pair&) {
  bounded_pair r;
  two_sum(a, -b, r.hi, r.lo);
  return r;
}
bounded difference(double a, double b, const bounded&) { return bounded(a) - bounded(b); }

template <class B>
[[gnu::always_inline]] inline std::array<B, 3> cross(const std::array<B, 3>& a, const std::array<B, 3>& b) {
  return {product(a[1], b[2]) - product(a[2], b[1]), product(a[2], b[0]) - product(a[0], b[2]),
          product(a[0], b[1]) - product(a[1], b[0])};
}

template <class B>
[[gnu::always_inline]] inline B dot(const std::array<B, 3>& a, const std::array<B, 3>& b) {
  return product(a[0], b[0]) + product(a[1], b[1]) + product(a[2], b[2]);
}

// √S for every S within s ± s.e, when that range is positive (false otherwise).
//  double: r = fl(√s), |√s − r| ≤ u r; |√S − √s| = |S − s|/(√S + √s) ≤ e/(2L) for any
//  L ≤ √(s − e) (both roots are at least L).
//  double-double: r1 = fl(√hi), D = s − r1² = (hi − p) − p' + lo with r1² = p + p' exactly
//  (TwoProduct; hi − p exact by Sterbenz), d = D rounded twice, |D − d| ≤ u (|t1| + |d|);
//  r2 = fl(d/(2 r1)). Since √s = r1 + D/(√s + r1),
//    |√s − r1 − D/(2 r1)| = D² / ((√s + r1)² 2 r1) ≤ (|D|/L)² / (8 L)   (L ≤ √s, L ≤ r1),
//  then |D − d|/(2 r1) and |r2 − d/(2 r1)| ≤ u |r2|, and e/(2L) for the range of S. The bound's
//  own dozen roundings on non-negative terms are covered by (1 + 2^-45).
bool root(const bounded& s, bounded& r) {
  const double lower = (s.v - s.e * inflate) * (1 - 0x1p-50);
  if (!(lower > 0)) return false;
  const double L = std::sqrt(lower) * (1 - 0x1p-50);
  r.v = std::sqrt(s.v);
  r.e = (s.e * inflate / (2 * L) + unit_roundoff * r.v) * (1 + 0x1p-45);
  return true;
}
bool root(const bounded_pair& s, bounded_pair& r) {
  const double lower = (s.hi - std::fabs(s.lo) - s.e * inflate) * (1 - 0x1p-50);
  if (!(lower > 0)) return false;
  const double r1 = std::sqrt(s.hi);
  const double L = std::min(std::sqrt(lower), r1) * (1 - 0x1p-50);
  double p, p_low;
  two_product(r1, r1, p, p_low);
  const double t1 = (s.hi - p) - p_low;
  const double d = t1 + s.lo;
  const double d_error = unit_roundoff * (std::fabs(t1) + std::fabs(d));
  const double r2 = d / (2 * r1);
  const double q = (std::fabs(d) + d_error) / L;
  two_sum(r1, r2, r.hi, r.lo);
  r.e = (s.e * inflate / (2 * L) + q * q / (8 * L) + d_error / (2 * r1) + unit_roundoff * std::fabs(r2)) *
            (1 + 0x1p-45) +
        underflow_slack;
  return true;
}

// The range of the inputs, 0 or a magnitude within [2^-60, 2^60] (f32) or [2^-100, 2^100]
// (f64): every product of up to six of them and of their differences stays far above underflow
// and below overflow in the filter arithmetic.
template <class F>
bool frame_inputs_in_range(const double* in) {
  constexpr double smallest = std::is_same_v<F, float> ? 0x1p-60 : 0x1p-100;
  constexpr double largest = std::is_same_v<F, float> ? 0x1p60 : 0x1p100;
  for (int i = 0; i < 9; ++i)
    if (in[i] != 0 && !moderate(in[i], smallest, largest)) return false;
  return true;
}

// Σ t[0..n) of n exact doubles as a pair within a bound: three sweeps of TwoSum along the terms
// (Ogita, Rump and Oishi's VecSum, each an error-free transformation: the exact sum does not
// change) leave the recursive sum in the last term and its errors, of the order u³ Σ|t|, in
// the others; then hi + lo = TwoSum(last, fl(Σ others)), within (n − 1) u Σ|others| (recursive
// summation, Higham §4.2) of the exact sum. All zero: an exact zero.
template <int n>
bounded_pair exact_sum(double* t) {
  for (int sweep = 0; sweep < 3; ++sweep)
    for (int i = 1; i < n; ++i) {
      double s, e;
      two_sum(t[i], t[i - 1], s, e);
      t[i] = s;
      t[i - 1] = e;
    }
  double rest = t[0], mass = std::fabs(t[0]);
  for (int i = 1; i < n - 1; ++i) {
    rest += t[i];
    mass += std::fabs(t[i]);
  }
  bounded_pair r;
  two_sum(t[n - 1], rest, r.hi, r.lo);
  r.e = mass * ((n - 1) * unit_roundoff * inflate);
  return r;
}

// up × W with every component accurate to about 2^-106 of itself however much it cancels (up
// near the view direction): a_i b_j − a_j b_i as the exact sum of eight TwoProducts (a = up is
// exact, b = W an exact pair: their bounds are 0).
std::array<bounded_pair, 3> accurate_cross(const std::array<bounded_pair, 3>& a, const std::array<bounded_pair, 3>& b) {
  std::array<bounded_pair, 3> r;
  for (int c = 0; c < 3; ++c) {
    const int i = (c + 1) % 3, j = (c + 2) % 3;
    double t[8];
    two_product(a[i].hi, b[j].hi, t[0], t[1]);
    two_product(a[i].hi, b[j].lo, t[2], t[3]);
    two_product(-a[j].hi, b[i].hi, t[4], t[5]);
    two_product(-a[j].hi, b[i].lo, t[6], t[7]);
    r[c] = exact_sum<8>(t);
  }
  return r;
}

// The entries of the view matrix (m, row-major, rows 0 to 2; the translations only when
// `translations`) from the frame's W and X; false where a bound does not decide.
template <class B>
bool frame_entries(const std::array<B, 3>& W, const std::array<B, 3>& X, const std::array<B, 3>& at,
                   bool translations, double* m) {
  const std::array<B, 3> Y = cross(W, X);
  const B ww = dot(W, W), xx = dot(X, X);
  // |W|² and |X|² certainly positive (otherwise rows or columns are undefined, or it is not
  // decided: the generic oracle says which).
  B lengths[3];
  if (!root(xx, lengths[0]) || !root(product(ww, xx), lengths[1]) || !root(ww, lengths[2])) return false;
  const std::array<B, 3>* axes[3] = {&X, &Y, &W};
  for (int r = 0; r < 3; ++r) {
    const auto d = prepare(lengths[r]);
    for (int c = 0; c < (translations ? 4 : 3); ++c) {
      const B q = c < 3 ? (*axes[r])[c] : -dot(*axes[r], at);
      if (!round_quotient(q, d, m[r * 4 + c])) return false;
    }
  }
  return true;
}

template <class F, bool placement>
bool look_at_kernel(const double* in, const conventions& conv, fast_reference& out) {
  refuse_grading_up_to_scale(conv, placement ? "target-to" : "look-at");
  using B = filter_number<F>;
  if (!frame_inputs_in_range<F>(in)) return false;
  const double* eye = in;
  const double* target = in + 3;
  const bool right = conv.hand == handedness::right;
  std::array<B, 3> W, up, at;
  for (int i = 0; i < 3; ++i) {
    W[i] = right ? difference(eye[i], target[i], B()) : difference(target[i], eye[i], B());
    up[i] = B(in[6 + i]);
    at[i] = B(eye[i]);
  }
  double m[16];
  if (!frame_entries(W, cross(up, W), at, !placement, m)) {
    // Near up ∥ w the components of X cancel: in double-double, once more with them accurate.
    if constexpr (std::is_same_v<B, bounded_pair>) {
      if (!frame_entries(W, accurate_cross(up, W), at, !placement, m)) return false;
    } else {
      return false;
    }
  }
  out = fast_reference{};
  out.count = 16;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out.value[r * 4 + c] = placement ? m[c * 4 + r] : m[r * 4 + c];
    out.value[r * 4 + 3] = placement ? rounded<F>(eye[r]) : m[r * 4 + 3];
  }
  out.value[15] = 1;
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
