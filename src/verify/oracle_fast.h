#pragma once
// Dedicated kernels of the filtered oracle for float (f32) inputs: shadow matrix, shadow of a
// point and reflection matrix, without any generic matrix or interval type. Every product of two
// floats is exact in a double, so each exact output is a short sum of exact doubles (or a
// quotient of two such sums); error-free transformations (TwoSum, Veltkamp's split) keep the
// sums exact or bound their error tightly, and a value is rounded to float only when both ends
// of that bound round to the same float. Every function returns false when it cannot decide;
// the caller then uses the generic oracle, which falls back to rationals.
#include <array>
#include <optional>

#include "shadowproof/constructions/classify.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"

namespace shadowproof::detail {

/// Canonical exact outputs of a case, already correctly rounded to float (+0 for an exact 0).
struct fast_reference {
  std::array<double, 16> value;    ///< canonical order (row-major for matrices)
  std::size_t count = 0;
  bool defined = true;             ///< false: the image does not exist (P·L − w P·V = 0)
  std::optional<point_class> cls;  ///< shadow-point only
};

/// The canonical exact outputs of an f32 (f64) case of shadow-matrix, shadow-point or
/// reflection-matrix under `conv` (light sign, clamping; not homogeneous grading), correctly
/// rounded to the case's type. False when a rounding or sign is undecided, and for f64 also for
/// inputs of extreme magnitude (beyond 2^±400 for the matrix, 2^±150 for the point) or lights
/// with w ∉ {0, 1}; the caller then uses the generic oracle, which falls back to rationals.
bool fast_shadow_matrix_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_shadow_point_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_reflection_matrix_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_shadow_matrix_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_shadow_point_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_reflection_matrix_f64(const double* inputs, const conventions& conv, fast_reference& out);

/// Class of the float image `got` of a shadow-point f32 case (see image_class); false for a
/// non-float output or an undecided sign.
bool fast_image_class_f32(const double* inputs, const conventions& conv, const double* got, image_class& out);

/// Class of the double image `got` of a shadow-point f64 case (see image_class); false for a
/// light with w ∉ {0, 1}, values beyond 2^±400 in magnitude or an undecided sign.
bool fast_image_class_f64(const double* inputs, const conventions& conv, const double* got, image_class& out);

/// P·(got, 1) correctly rounded to double for f32 inputs and float outputs; false when the
/// outputs are not floats or the rounding is undecided.
bool fast_plane_value_f32(const double* inputs, const double* got, double& out);

/// P·(got, 1) correctly rounded to double for f64 inputs and outputs; false when an input or
/// output is beyond 2^±400 in magnitude or the rounding is undecided.
bool fast_plane_value_f64(const double* inputs, const double* got, double& out);

}  // namespace shadowproof::detail
