#pragma once
/// Test cases for the grader: inputs exactly representable in the implementation's format, in
/// three classes of closeness to the operation's degeneracy, generated deterministically.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof {

/// How close an input is to the operation's degeneracy, or how far out of the type's range.
///   regular: random inputs of moderate size;
///   near_degenerate: within a relative 2^-4 … 2^-(p−1) of the degeneracy (p = 24 or 53), the
///     resolution of the type: closer than that, rounding the inputs cannot tell it apart;
///   degenerate: exactly on it, built exactly in the float type; the only class with inputs
///     whose answer does not exist (a singular matrix, a flat view volume, no shadow);
///   range: a regular configuration scaled by powers of two so that a straightforward
///     evaluation over- or underflows the type (the answer itself stays an ordinary one where the
///     operation allows it).
/// The degeneracies:
///   shadow-matrix: light parallel to (directional) or on (point) the receiver, P·L = 0;
///   shadow-point: also a point on the receiver, or level with a point light (image at infinity);
///   reflection-matrix: none in the geometry; near = mirror far from the origin (|d| ≫ |n|),
///     degenerate = axis-aligned mirrors, whose entries are exactly 0 and ±1;
///   ortho / frustum / perspective: l = r, b = t or n = f (near: nearly so, or far ≫ near);
///   normal-matrix: a singular 3x3 matrix (near: nearly singular).
enum class input_class { regular, near_degenerate, degenerate, range };
/// Every class, in the order generate_cases cycles through them.
const std::vector<input_class>& all_input_classes();
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
  /// closeness_to_degeneracy(inputs) when generated (−inf exactly on the degeneracy); NaN when
  /// not recorded (a case file without it).
  double closeness = std::numeric_limits<double>::quiet_NaN();
};

/// `count` cases, deterministic in (op, type, seed, requirements): std::mt19937_64 with our own
/// mapping to numbers, so the same seed gives the same bits everywhere. `cls` nothing cycles
/// regular, near-degenerate, degenerate, range. Of `requirements` only the input restrictions
/// matter (directional_only, point_light_only, unit_normal, symmetric_view, and
/// clamps_behind_receiver, which orients the receiver so that P·L > 0). Ids run from `first_id`.
/// No input is −0. A near-degenerate case is redrawn while it is exactly degenerate or closer
/// than 2^-(p−1); each case records its closeness.
std::vector<test_case> generate_cases(operation op, scalar_type type, std::size_t count,
                                      std::uint64_t seed, std::optional<input_class> cls = {},
                                      const conventions& requirements = {},
                                      std::uint64_t first_id = 0);

/// The cases of generate_cases(op, type, count, seed, cls, requirements) a chunk at a time, for
/// runs whose memory must not grow with the case count: next(n) returns the next n of that
/// sequence (ids counting on from 0), whatever the chunk sizes asked for.
class case_stream {
 public:
  case_stream(operation op, scalar_type type, std::uint64_t seed, std::optional<input_class> cls = {},
              const conventions& requirements = {});
  ~case_stream();
  case_stream(case_stream&&) noexcept;
  case_stream& operator=(case_stream&&) noexcept;
  /// The next `count` cases of the sequence.
  std::vector<test_case> next(std::size_t count);

 private:
  struct state;
  std::unique_ptr<state> state_;
};

/// The shadowproof command that prints the exact answer for exactly these inputs (as hex
/// floats), in the conventions that matter to it (the depth convention of projections).
std::string reproducer_command(const test_case& c, const conventions& conv);

/// Why c's inputs name no instance of its operation at all (a plane with a zero normal, an
/// all-zero light), or an empty string when they do.
std::string invalid_inputs_reason(const test_case& c);

/// log2(|P·L| / (|P| |L|)) for shadows (for shadow-point the smallest of that, the point's own
/// closeness to the receiver log2(|P·V| / (|P| |(V, 1)|)), and for a point light the closeness
/// of the line from the light through V to parallel with the receiver), log2(|n| / |P|) for
/// reflections, log2 of the flattest relative extent |r − l| / (|l| + |r|) for view volumes, and
/// log2(|det A| / Π |row i|) for normal matrices. −inf exactly when the inputs are exactly
/// degenerate (decided exactly); otherwise rounded (a plot and case-file value, never graded).
double closeness_to_degeneracy(const test_case& c);

}  // namespace shadowproof
