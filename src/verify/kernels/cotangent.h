#pragma once
// cot(fovy/2) without MPFR: a double-double value and a rigorous bound on its distance to the
// exact cotangent (the evaluation and its error analysis, over lanes: field_of_view.h). The
// field-of-view kernels and batch filters (perspective-fov, perspective-fov-infinite) decide
// their focal scales with it, and the interval oracle encloses cot(fovy/2) with it; MPFR
// (constructions/irrational.h) remains for the angles it does not cover and for the rational
// oracle's representatives.
#include "shadowproof/constructions/irrational.h"

namespace shadowproof::detail {

/// hi + lo within ± e of cot(fovy/2), |lo| ≤ 2^-53 |hi|.
struct cot_pair {
  double hi = 0, lo = 0, e = 0;
};

/// A constant c of the evaluation: |c − (hi + lo)| ≤ e, hi and lo each rounded to nearest.
struct trig_constant {
  double hi = 0, lo = 0, e = 0;
};

/// The constants of the cotangent's evaluation, from MPFR at 320 bits (within a relative
/// 2^-310 of what they stand for), computed once (camera.cpp). The table of sin(j/64) and
/// cos(j/64), j = 0 … 52, is held as columns, for the batch filters' gathers; `bound` is
/// |lo| + e, the bound of hi alone (the f32 filter's constant).
struct trig_table {
  static constexpr int steps = 53;  ///< j/64 for j < 53 covers t ≤ 0.81
  trig_constant inverse_factorial[32];  ///< 1/k!
  double pi_head = 0;                   ///< P1, the double nearest π (below it)
  trig_constant pi_tail;                ///< P2 + P3 ± e: π − P1 (hi = P2, lo = P3)
  trig_constant degree;                 ///< π/360
  double sine_hi[steps], sine_lo[steps], sine_e[steps], sine_bound[steps];
  double cosine_hi[steps], cosine_lo[steps], cosine_e[steps], cosine_bound[steps];
};

/// The table, computed on first use (thread-safe).
const trig_table& cotangent_constants();

/// Whether 0 < fovy < π (radians) or 0° < fovy < 180° (degrees), exactly as
/// field_of_view_in_range decides it: the double nearest π, 0x1.921fb54442d18p+1, lies below π,
/// so fovy < π exactly when fovy ≤ that double.
bool field_of_view_inside_half_turn(double fovy, angle_unit unit);

/// An enclosure of cot(fovy/2) (fovy in radians, or fovy·π/360 in degrees), false when fovy is
/// outside the half turn or too small for the evaluation's range (fovy < 2^-400 radians,
/// 2^-390 degrees; the caller then asks MPFR). The bound is at most about 2^-100 |cot| (the
/// test `cot(fovy/2) in double-double encloses MPFR's value tightly` measures it).
bool cot_half_angle_pair(double fovy, angle_unit unit, cot_pair& out);

}  // namespace shadowproof::detail
