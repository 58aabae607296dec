// The kernels of the camera builders with irrational values: perspective-fov and
// perspective-fov-infinite (cot(fovy/2)), look-at and target-to (q/√s). Each evaluates its
// entries with filter numbers (bounded.h: double for f32 cases, double-double for f64 ones)
// and rounds an entry only where the whole bound rounds to one value; otherwise, or for inputs
// outside the ranges below, it returns false and the generic oracle decides (intervals, then
// the rational oracle's MPFR enclosures). Nothing here has an exact stage: an irrational
// value is never a tie, and the exact zeros and the undefined entries are decided on the
// inputs themselves.
//
// cot(fovy/2) (perspective-fov, perspective-fov-infinite): the evaluation over lanes and its
// error analysis in field_of_view.h; its MPFR constants, computed once, here.
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
#include "field_of_view.h"
#include "look_at.h"
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
