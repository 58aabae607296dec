#pragma once
// The dedicated kernels of the filtered oracle: for each operation and each input type, the
// canonical exact outputs correctly rounded to that type, without any generic matrix, interval
// or rational. Each kernel evaluates its formula first with a filter number (a value and a
// rigorous error bound: kernels/bounded.h), and rounds an output only when its whole bound
// rounds to one value; when a sign or a rounding is undecided (near a degeneracy, at a tie) it
// redoes the case with exact expansions of doubles (kernels/expansion.h), which decide every
// sign and every rounding, ties included. A kernel returns false only for inputs outside its
// range (f64 values beyond 2^±120, non-float f32 inputs) or an exhausted expansion; the caller
// then uses the generic oracle (intervals, then rationals). The camera builders with irrational
// values have no exact stage (an irrational value is never a tie) and return false also where
// their bounds do not decide (kernels/camera.cpp).
//
// One file per operation under kernels/ (kernels/README.md); each operation's spec
// (operations/<op>.cpp) points at its two kernels.
#include <array>
#include <cstdint>
#include <optional>

#include "shadowproof/constructions/classify.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof::detail {

/// Canonical exact outputs of a case, already correctly rounded to the case's type (+0 for an
/// exact 0).
struct fast_reference {
  std::array<double, 16> value{};  ///< canonical order (row-major for matrices); 0 where undefined
  std::size_t count = 0;
  bool defined = true;             ///< false: no output exists (an undefined image, a singular matrix)
  std::uint32_t undefined = 0;     ///< when defined: bit j set when output j alone does not exist
                                   ///< (the entries of a flat view volume's row)
  std::optional<point_class> cls;  ///< shadow-point only
};

/// A kernel: the canonical outputs of one case under `conv` (light sign, clamping, depth
/// convention, symmetric volumes; not storage order or grading up to scale, which the grader
/// applies), or false when the case must go to the generic oracle.
using fast_kernel = bool (*)(const double* inputs, const conventions& conv, fast_reference& out);

// One pair per operation (kernels/<op>.cpp).
bool fast_shadow_matrix_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_shadow_matrix_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_shadow_point_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_shadow_point_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_reflection_matrix_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_reflection_matrix_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_ortho_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_ortho_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_frustum_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_frustum_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_normal_matrix_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_normal_matrix_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_perspective_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_perspective_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_ortho_size_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_ortho_size_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_perspective_size_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_perspective_size_f64(const double* inputs, const conventions& conv, fast_reference& out);
// The camera builders with irrational values (kernels/camera.cpp): no exact stage, they return
// false where their bounds do not decide, and the generic oracle decides.
bool fast_perspective_fov_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_perspective_fov_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_perspective_fov_infinite_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_perspective_fov_infinite_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_look_at_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_look_at_f64(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_target_to_f32(const double* inputs, const conventions& conv, fast_reference& out);
bool fast_target_to_f64(const double* inputs, const conventions& conv, fast_reference& out);

/// For tests: when true, every kernel skips its filter stage and decides with exact expansions
/// alone, so that the exact stage is checked on every case, not only where the filter gives up.
/// Set only while no other thread runs a kernel.
extern bool kernels_exact_only;

// Shadow-point grading beyond the values (kernels/shadow_point.cpp).

/// Class of the float image `got` of a shadow-point f32 (f64) case (see image_class); false
/// for an output that is not a float (f32), values outside the kernels' range (f64), or an
/// exhausted expansion.
bool fast_image_class_f32(const double* inputs, const conventions& conv, const double* got, image_class& out);
bool fast_image_class_f64(const double* inputs, const conventions& conv, const double* got, image_class& out);

/// P·(got, 1) correctly rounded to double for an f32 (f64) case's outputs; false as above.
bool fast_plane_value_f32(const double* inputs, const double* got, double& out);
bool fast_plane_value_f64(const double* inputs, const double* got, double& out);

}  // namespace shadowproof::detail
