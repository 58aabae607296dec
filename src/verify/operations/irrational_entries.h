#pragma once
// What the operations with irrational exact values share (perspective-fov, look-at,
// target-to). Over rationals their exact outputs are correctly rounding representatives
// (constructions/irrational.h): the lower end of the first MPFR enclosure, at 64, 128, … bits,
// whose ends round alike, decided by Ziv's strategy. Their kernels (kernels/camera.cpp) decide
// the rounding of nearly every case in double or double-double; over intervals (the cases the
// kernels decline, and the verdicts' sensitivities) they are enclosures of the exact values
// themselves (√ of an interval, cot(fovy/2) from the double-double enclosure of
// kernels/cotangent.h or, outside its range, a 64-bit MPFR one); an interval that does not
// decide throws `undecided`, and the rational oracle decides.
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "../operation_table.h"
#include "shadowproof/constructions/irrational.h"
#include "shadowproof/core/error.h"

namespace shadowproof::detail {

/// Throws verify.irrational_scale when the case is graded up to scale: that would scale the
/// representatives, not the exact values, and could misjudge a rounding.
inline void refuse_grading_up_to_scale(const conventions& conv, const char* op) {
  if (conv.homogeneous)
    throw error(errc::verify_irrational_scale,
                std::string(op) + ": its exact values are irrational, so it cannot be graded up to scale "
                                  "(--homogeneous); grade the matrix as it is");
}

/// Every input finite, or throws `undecided` (the rational oracle says what the others mean).
inline void require_finite_inputs(const double* in, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i)
    if (!std::isfinite(in[i])) throw undecided{};
}

}  // namespace shadowproof::detail
