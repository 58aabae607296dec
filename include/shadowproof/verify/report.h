#pragma once
/// Statistics over many case grades, and running an implementation on its cases.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/implementation.h"

namespace shadowproof {

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

}  // namespace shadowproof
