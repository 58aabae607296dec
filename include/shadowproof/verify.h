#pragma once
/// Grading float implementations against the exact answer for the very same float inputs.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/classify.h"
#include "shadowproof/impl_registry.h"

namespace shadowproof {

// ===========================================================================================
// Cases

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

/// log2(|P·L| / (|P| |L|)) for shadows (for shadow-point the smaller of that and the point's
/// own closeness to the receiver, log2(|P·V| / (|P| |V|))), log2(|n| / |P|) for reflections,
/// log2 of the flattest relative extent |r − l| / (|l| + |r|) for view volumes, and
/// log2(|det A| / Π |row i|) for normal matrices; −inf when exactly degenerate. The x axis of
/// the SVG plot. Computed in long double and rounded (a plot value, not a graded one).
double closeness_to_degeneracy(const test_case& c);

// ===========================================================================================
// Grades

/// Grade of one output number.
struct output_grade {
  bool exact_defined = true;   ///< false when the exact value does not exist (division by 0)
  double reference = 0;        ///< exact value correctly rounded to the output type (+0 for 0)
  double got = 0;              ///< the implementation's output (in the output type)
  std::uint64_t ulps = 0;      ///< distance from reference; valid when counted()
  double bits = 0;             ///< log2(ulps + 1)
  double relative = 0;         ///< |got − reference| / |reference| (0 when both are 0)
  bool nonfinite = false;      ///< exact finite, got NaN or ±inf (not an overflow to that inf)
  bool garbage = false;        ///< exact undefined, got a finite number
  /// True when the output contributes to ulps statistics (finite, exact finite).
  bool counted() const { return exact_defined && !nonfinite && !garbage; }
};

/// Where the float image of a point lies, derived from the image itself.
/// On the line through the light and the point V, the image G beyond V (shadow), between the
/// light and V (behind_receiver), behind the light (beyond_light), G = V exactly (on_receiver);
/// nonfinite when a coordinate is NaN/Inf, other for positions that fit none (G at the light,
/// or off V although level with it).
enum class image_class { on_receiver, shadow, behind_receiver, beyond_light, nonfinite, other };
/// Stable name ("shadow", "behind_receiver", …).
std::string_view to_string(image_class c);

/// Grade of one case.
struct case_grade {
  std::uint64_t id = 0;
  input_class cls = input_class::regular;
  std::vector<output_grade> outputs;
  std::uint64_t max_ulps = 0;  ///< over counted outputs
  double max_bits = 0;
  std::size_t worst_output = 0;
  std::size_t nonfinite = 0, garbage = 0;
  /// shadow-point only: exact class of the point, the class implied by the float image, and
  /// the exact plane value P·(image, 1) correctly rounded to double.
  std::optional<point_class> exact_class;
  std::optional<image_class> got_class;
  bool misclassified = false;
  std::optional<double> plane_value;
  /// Homogeneous grading: index of the exact entry used to fix the scale (largest magnitude).
  std::optional<std::size_t> scale_pivot;
};

/// Which oracle decides the reference values.
enum class oracle_mode {
  filtered,  ///< interval arithmetic first, exact rationals only when an interval is undecided
  naive,     ///< exact rationals throughout
};

/// Counters of the filtered oracle (how often intervals decided a whole case).
struct oracle_counters {
  std::uint64_t decided_by_intervals = 0;
  std::uint64_t fell_back_to_rationals = 0;
};

/// Grades `outputs` (signature(c.op).output_count numbers, in the implementation's layout)
/// against the exact answer for c.inputs, after mapping `conv` to the canonical form exactly:
/// storage/vectors permute entries, light_sign negates a directional light, homogeneous (or
/// normalises_plane on shadow-matrix) grades up to the scale λ = got[k] / exact[k] where k is
/// the entry of largest exact magnitude (first one on ties), clamps_behind_receiver expects
/// the point itself when it is behind the receiver. Both oracle modes give identical grades.
case_grade grade_case(const test_case& c, const conventions& conv, const double* outputs,
                      oracle_mode mode = oracle_mode::filtered, oracle_counters* counters = nullptr);

// ===========================================================================================
// Reports

/// Statistics over a set of case grades (one implementation, one operation, one input class).
struct grade_summary {
  std::size_t cases = 0, outputs = 0;
  std::uint64_t max_ulps = 0;
  std::uint64_t median_ulps = 0;  ///< over counted outputs (lower median)
  double max_bits = 0;
  /// Outputs by bits of error: [0], (0,1], (1,4], (4,8], (8,16], (16,24], (24,53], >53.
  std::vector<std::size_t> bits_histogram;
  std::size_t nonfinite = 0, garbage = 0, misclassified = 0;
  std::vector<case_grade> worst;  ///< worst first: non-finite/garbage, misclassified, max ulps
};

/// Upper edges of the bits histogram buckets (the last bucket is open).
const std::vector<double>& bits_histogram_edges();

/// Aggregates grades: counts, max and median ulps over counted outputs, the bits histogram, and
/// the `keep_worst` worst cases (non-finite/garbage first, then misclassified, then max ulps).
grade_summary summarize(const std::vector<case_grade>& grades, std::size_t keep_worst = 3);

/// Runs `impl` on its cases and grades them.
std::vector<case_grade> run_and_grade(const implementation& impl, const std::vector<test_case>& cases,
                                      oracle_mode mode = oracle_mode::filtered,
                                      oracle_counters* counters = nullptr);

/// Writes the case as the JSON object of the case-file protocol (one line, no newline):
/// {"id": 0, "op": "shadow-matrix", "type": "f32", "class": "regular", "plane": [hex...],
///  "light": [hex...], "exact": {"plane": [decimal...], ...}}.
std::string case_json_line(const test_case& c);

/// Exact decimal expansion of a finite double ("0.100000001490116119384765625").
std::string exact_decimal(double x);

/// Reads one line of a case file (case_json_line's format; "class" and "exact" optional).
/// Every input must be a hex-float or exact string (or a JSON number) exactly representable
/// in the case's type. Throws error "protocol.case" naming the line and field otherwise, and
/// for a plane with a zero normal or an all-zero light.
test_case parse_case_line(std::string_view line, std::size_t line_number);

/// One line of an implementation's outputs: {"id": 0, "output": [numbers]}.
struct output_line {
  std::uint64_t id = 0;
  std::vector<double> values;
};

/// Reads one line of outputs for a case of type `type` with `count` outputs. Numbers are JSON
/// numbers or strings (hex float "0x1.8p+0", decimal, "nan", "inf", "-inf"), null means NaN;
/// each finite value must be exactly representable in `type` (never rounded silently).
/// Throws error "protocol.output" naming the line and the entry otherwise.
output_line parse_output_line(std::string_view line, std::size_t line_number, scalar_type type,
                              std::size_t count);

}  // namespace shadowproof
