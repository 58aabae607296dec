#pragma once
// cot(fovy/2) without MPFR: a double-double value and a rigorous bound on its distance to the
// exact cotangent (the evaluation and its error analysis: camera.cpp). The camera kernels
// (perspective-fov, perspective-fov-infinite) decide their focal scales with it, and the
// interval oracle encloses cot(fovy/2) with it; MPFR (constructions/irrational.h) remains for
// the angles it does not cover and for the rational oracle's representatives.
#include "shadowproof/constructions/irrational.h"

namespace shadowproof::detail {

/// hi + lo within ± e of cot(fovy/2), |lo| ≤ 2^-53 |hi|.
struct cot_pair {
  double hi = 0, lo = 0, e = 0;
};

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
