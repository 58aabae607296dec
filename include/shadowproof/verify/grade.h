#pragma once
/// Grading one case: every output against the exact answer for the very same float inputs.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/constructions/classify.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof {

/// The verdict on an output, a case (its worst output) or an implementation (its worst case),
/// from best to worst (docs/verdicts.md gives the mathematics). With f the exact value, g the
/// output, u the unit roundoff of the type (2^-24, 2^-53), D = Σ_j |∂f/∂x_j| |x_j| the size of
/// what the inputs contribute to f, and η = |g − f| / (|f| + D) the mixed backward error (to
/// first order, g is the exact answer for inputs within a relative η, rounded by at most η):
///   exact      g is f correctly rounded (an overflow to the same infinity included), or a
///              correct rejection: NaN/±Inf (or the declared sentinel) where f does not exist;
///   faithful   g is one ulp from it;
///   stable     η ≤ c·u, c the operation's stable_constant (the roundings of a straightforward
///              evaluation), or g is NaN/±Inf while a divisor of the problem is within c·u of
///              vanishing: the problem is ill-conditioned there, the formula is fine;
///   unstable   c·u < η ≤ √u: more lost than the problem's conditioning explains, yet the output
///              is still the answer for inputs within √u (a formula that loses accuracy it need not);
///   range      not stable, and an intermediate of a straightforward evaluation (or f itself)
///              over- or underflows the type: a limitation of the format, not of the formula;
///   wrong      η > √u with every intermediate in range: no nearby input explains the output;
///              also a declared sentinel where an answer exists and no divisor is near zero;
///   nonfinite  NaN or ±Inf where f exists and nothing above explains it;
///   garbage    a finite number (not the declared sentinel) where f does not exist.
enum class verdict { exact, faithful, stable, unstable, range, wrong, nonfinite, garbage };
/// Stable name: "exact", "faithful", ….
std::string_view to_string(verdict v);
/// Inverse of to_string; nothing for an unknown name.
std::optional<verdict> verdict_from_string(std::string_view name);
/// Every verdict, best first.
const std::vector<verdict>& all_verdicts();

/// Grade of one output number.
struct output_grade {
  bool exact_defined = true;   ///< false when the exact value does not exist (division by 0)
  double reference = 0;        ///< exact value correctly rounded to the output type (+0 for 0)
  double got = 0;              ///< the implementation's output (in the output type)
  std::uint64_t ulps = 0;      ///< distance from reference; valid when counted()
  double bits = 0;             ///< log2(ulps + 1)
  double relative = 0;         ///< |got − reference| / |reference| (0 when both are 0)
  bool nonfinite = false;      ///< exact finite, got NaN or ±inf (not an overflow to that inf,
                               ///< not part of a correct rejection of the whole case)
  bool garbage = false;        ///< exact undefined, got a finite number (not a declared sentinel)
  verdict v = verdict::exact;  ///< see verdict
  /// True when the output contributes to ulps statistics (finite, exact finite).
  bool counted() const { return exact_defined && !nonfinite && !garbage && std::isfinite(got); }
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
  verdict v = verdict::exact;  ///< the worst verdict of the outputs
  std::size_t verdict_output = 0;  ///< an output with that verdict (the first one)
  /// The case has no answer (some output undefined) and the implementation rejected it as a
  /// whole (every output NaN/±Inf, or the declared sentinel); or it returned the sentinel for
  /// a case that has an answer (then graded as described under verdict).
  bool rejected = false;
  /// shadow-point only: exact class of the point, the class implied by the float image, and
  /// the exact plane value P·(image, 1) correctly rounded to double. misclassified: the image
  /// and the correctly rounded exact image lie on different sides (shadow, behind_receiver,
  /// beyond_light), so a correctly rounded answer is never misclassified.
  std::optional<point_class> exact_class;
  std::optional<image_class> got_class;
  std::optional<image_class> reference_class;
  bool misclassified = false;
  std::optional<double> plane_value;
  /// Homogeneous grading: the exact entry whose rounding fixes the scale (largest magnitude,
  /// first on ties; an index into the implementation's outputs), and the scale λ chosen within
  /// the interval its rounding allows (rounded to the output type).
  std::optional<std::size_t> scale_pivot;
  std::optional<double> scale;
};

/// The canonical name of output j of an implementation declaring conv: "(row,col)" of the
/// canonical (row-major, column-vector) matrix whatever the storage order, or the coordinate.
std::string output_name(operation op, std::size_t j, const conventions& conv);

/// True when the sentinel names outputs of op: zero always, identity for matrices only.
bool sentinel_applies(operation op, sentinel_kind s);

/// Which oracle decides the reference values.
enum class oracle_mode {
  filtered,  ///< interval arithmetic first, exact rationals only when an interval is undecided
  naive,     ///< exact rationals throughout
};

/// What grade_case decides besides the values: `verdicts` (the default) also gives every output
/// its verdict, which takes the exact derivatives for outputs more than an ulp off whose relative
/// error alone does not prove them stable; `values_only` leaves every verdict `exact` (to measure
/// what the verdicts cost, bench/bench_oracle --ratio).
enum class grade_depth { verdicts, values_only };

/// Counters of the filtered oracle (how often intervals decided a whole case).
struct oracle_counters {
  std::uint64_t decided_by_intervals = 0;
  std::uint64_t fell_back_to_rationals = 0;
};

/// Grades `outputs` (signature(c.op).output_count numbers, in the implementation's layout)
/// against the exact answer for c.inputs, after mapping `conv` to the canonical form exactly:
/// storage/vectors permute entries, light_sign negates a directional light, clamps_behind_receiver
/// expects the point itself when it is behind the receiver, and a homogeneous result (or a
/// shadow matrix of a routine that normalises the plane) is graded up to a scale λ: starting
/// from the interval of λ for which the pivot k (the entry of largest exact magnitude, first on
/// ties) rounds to the output there, λ is narrowed by every other entry in order of magnitude
/// whose rounding still allows a common λ, and every entry is graded against λ·exact rounded.
/// So if some λ makes every entry the correctly rounded λ·exact, every entry grades 0 ulps.
/// Every output and the case get a verdict (see verdict). Both oracle modes give identical
/// grades.
case_grade grade_case(const test_case& c, const conventions& conv, const double* outputs,
                      oracle_mode mode = oracle_mode::filtered, oracle_counters* counters = nullptr,
                      grade_depth depth = grade_depth::verdicts);

/// The first-order conditioning of one output, from the exact partial derivatives, rounded to
/// double for reports. With f the exact value (times the scale λ when graded up to scale), g the
/// output and D = Σ_j |∂f/∂x_j| |x_j|:
struct output_conditioning {
  bool defined = false;                ///< f exists (the rest is meaningful only then)
  double value = 0;                    ///< f
  double sensitivity = 0;              ///< D
  double condition = 0;                ///< κ = D / |f| (inf when f = 0 < D, 0 when D = 0)
  double relative_error = 0;           ///< |g − f| / |f| (inf when f = 0 ≠ g; NaN when g is NaN/±Inf)
  double backward_error = 0;           ///< η / u with η = |g − f| / (|f| + D) (NaN when g is not finite)
};

/// The conditioning of a case: every output, and the whole vector or matrix (∞-norms over the
/// defined outputs): condition max_i D_i / max_i |f_i|, error max_i |g_i − f_i| / max_i |f_i|,
/// backward error max_i |g_i − f_i| / (max_i |f_i| + max_i D_i), in units of u.
struct case_conditioning {
  std::vector<output_conditioning> outputs;
  double normwise_condition = 0;
  double normwise_error = 0;
  double normwise_backward_error = 0;
  double normwise_ulps = 0;            ///< max_i |g_i − f_i| in ulps of max_i |f_i|
  double unit_roundoff = 0;            ///< u of the type
  int stable_constant = 0;             ///< c of the operation
  bool near_singular = false;          ///< a divisor is within c·u of vanishing
  bool out_of_range = false;           ///< a straightforward evaluation leaves the type's range
};

/// The conditioning of `outputs` for case c (exact rational arithmetic; for reports, slower than
/// grade_case). Outputs that are NaN or ±Inf get NaN errors.
case_conditioning conditioning(const test_case& c, const conventions& conv, const double* outputs);

}  // namespace shadowproof
