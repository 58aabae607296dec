#pragma once
/// Grading one case: every output against the exact answer for the very same float inputs.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "shadowproof/constructions/classify.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof {

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

}  // namespace shadowproof
