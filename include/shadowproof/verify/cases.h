#pragma once
/// Test cases for the grader: inputs exactly representable in the implementation's format, in
/// three classes of closeness to the operation's degeneracy, generated deterministically.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof {

/// How close an input is to the operation's degeneracy. near_degenerate: within a relative
/// 2^-4 … 2^-p of it; degenerate: exactly on it, built exactly in the float type.
///   shadow-matrix: light parallel to (directional) or on (point) the receiver, P·L = 0;
///   shadow-point: also a point on the receiver or level with a point light (image at infinity);
///   reflection-matrix: near = mirror far from the origin (|d| ≫ |n|), degenerate = a normal
///     whose |n|² over- or underflows the type (the mirror itself is an ordinary plane);
///   ortho / frustum: l = r, b = t or n = f (near: nearly so, or far ≫ near);
///   normal-matrix: a singular 3x3 matrix (near: nearly singular).
enum class input_class { regular, near_degenerate, degenerate };
/// Stable name: "regular", "near-degenerate", "degenerate".
std::string_view to_string(input_class c);
/// Inverse of to_string; nothing for an unknown name.
std::optional<input_class> input_class_from_string(std::string_view name);

/// One set of inputs, every number exactly representable in `type`.
struct test_case {
  std::uint64_t id = 0;
  operation op = operation::shadow_matrix;
  scalar_type type = scalar_type::f32;
  input_class cls = input_class::regular;
  std::vector<double> inputs;  ///< signature(op).input_count numbers
};

/// `count` cases, deterministic in (op, type, seed, requirements): std::mt19937_64 with our own
/// mapping to numbers, so the same seed gives the same bits everywhere. `cls` nothing cycles
/// regular, near-degenerate, degenerate. Of `requirements` only the input restrictions matter
/// (directional_only, point_light_only, unit_normal, symmetric_view, and clamps_behind_receiver,
/// which orients the receiver so that P·L > 0). Ids run from `first_id`. No input is −0.
std::vector<test_case> generate_cases(operation op, scalar_type type, std::size_t count,
                                      std::uint64_t seed, std::optional<input_class> cls = {},
                                      const conventions& requirements = {},
                                      std::uint64_t first_id = 0);

/// The shadowproof command that prints the exact answer for exactly these inputs (as hex
/// floats), in the conventions that matter to it (the depth convention of projections).
std::string reproducer_command(const test_case& c, const conventions& conv);

/// Why c's inputs name no instance of its operation at all (a plane with a zero normal, an
/// all-zero light), or an empty string when they do.
std::string invalid_inputs_reason(const test_case& c);

/// log2(|P·L| / (|P| |L|)) for shadows (for shadow-point the smaller of that and the point's
/// own closeness to the receiver, log2(|P·V| / (|P| |V|))), log2(|n| / |P|) for reflections,
/// log2 of the flattest relative extent |r − l| / (|l| + |r|) for view volumes, and
/// log2(|det A| / Π |row i|) for normal matrices; −inf when exactly degenerate. The x axis of
/// the SVG plot. Computed in long double and rounded (a plot value, not a graded one).
double closeness_to_degeneracy(const test_case& c);

}  // namespace shadowproof
