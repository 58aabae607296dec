#pragma once
/// Statistics over many case grades, and running an implementation on its cases.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/implementation.h"

namespace shadowproof {

/// Statistics over a set of case grades (one implementation, one operation, one input class).
struct grade_summary {
  std::size_t cases = 0, outputs = 0;
  std::uint64_t max_ulps = 0;     ///< over finite outputs whose exact value is finite
  std::uint64_t median_ulps = 0;  ///< over the same outputs (lower median)
  double max_bits = 0;
  /// Outputs by bits of error: [0], (0,1], (1,4], (4,8], (8,16], (16,24], (24,53], >53.
  std::vector<std::size_t> bits_histogram;
  /// Outputs NaN/±Inf where the exact value exists, outputs finite where it does not, and cases
  /// whose image lies on another side than the correctly rounded exact image.
  std::size_t nonfinite = 0, garbage = 0, misclassified = 0;
  /// Cases by verdict, indexed by the verdict (all_verdicts() order).
  std::vector<std::size_t> verdicts;
  verdict worst_verdict = verdict::exact;  ///< of every case
  /// The worst cases: by verdict, then by max ulps (`keep_worst` of them).
  std::vector<case_grade> worst;
  /// For each verdict worse than faithful that occurs, its worst case whose outputs are all
  /// finite and its worst case with a NaN/±Inf output (most ulps first), worst verdict first:
  /// the examples a report shows.
  std::vector<case_grade> examples;
  /// The worst case whose outputs are all finite, and the worst case with a NaN/±Inf output that
  /// is not a correct rejection (by verdict, then ulps), when there is one.
  std::optional<case_grade> worst_finite, worst_nonfinite;
};

/// Upper edges of the bits histogram buckets (the last bucket is open).
const std::vector<double>& bits_histogram_edges();

/// Aggregates grades: counts, verdicts, max and median ulps over counted outputs, the bits
/// histogram, the `keep_worst` worst cases, the examples per verdict, the worst finite and the
/// worst non-finite case.
grade_summary summarize(const std::vector<case_grade>& grades, std::size_t keep_worst = 3);

/// True when any case of the summary is at or past `threshold` (verdict order).
bool reaches(const grade_summary& s, verdict threshold);

/// Runs `impl` on its cases and grades them.
std::vector<case_grade> run_and_grade(const implementation& impl, const std::vector<test_case>& cases,
                                      oracle_mode mode = oracle_mode::filtered,
                                      oracle_counters* counters = nullptr);

}  // namespace shadowproof
