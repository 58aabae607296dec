#pragma once
// The one place that reads the grader's fields (verify/grade.h): a case_grade and a
// failure_policy become a judgement the matchers, the property runner and their messages use.
// When the grader gives verdicts (exact, faithful, stable, unstable, wrong, range, nonfinite,
// garbage), judge() maps them instead and nothing else changes.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "shadowproof/testing/failure_policy.h"
#include "shadowproof/verify/grade.h"

namespace shadowproof::detail {

/// Why one output fails.
enum class entry_failure { ulps, nonfinite, garbage };

/// One failing output, in the routine's memory order.
struct entry_judgement {
  std::size_t output = 0;
  entry_failure failure = entry_failure::ulps;
  double got = 0;
  double rounded = 0;          ///< the exact value correctly rounded (times λ up to scale)
  bool exact_exists = true;
  std::uint64_t ulps = 0;      ///< for entry_failure::ulps
};

/// What a test makes of one graded case.
struct case_judgement {
  bool fails = false;
  /// The failure's name, one of the verdict scale's where it has one: "nonfinite",
  /// "garbage", "misclassified" (a shadow-point image on the wrong side), "ulps".
  std::string verdict;
  /// Orders failing cases, worst first: non-finite or garbage (3), misclassified (2), ulps (1)
  /// with more ulps worse.
  int severity = 0;
  std::uint64_t max_ulps = 0;
  std::vector<entry_judgement> entries;  ///< the failing outputs
  /// shadow-point misclassification: the exact class of the point and the class the float
  /// image implies.
  std::optional<std::string> exact_class, image_class;
  /// Up to scale: the routine's output index that fixed λ.
  std::optional<std::size_t> scale_pivot;
};

/// Judges a grade under a policy.
case_judgement judge(const case_grade& g, const failure_policy& policy);

/// True when b is a worse failure than a (by severity, then ulps).
bool worse(const case_judgement& b, const case_judgement& a);

}  // namespace shadowproof::detail
