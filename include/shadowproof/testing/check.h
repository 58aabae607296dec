#pragma once
/// The property runner: a user's float routine against the exact answer on generated cases,
/// degenerate ones included, failing with the worst case shrunk to a small reproducer.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "shadowproof/testing/failure_policy.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof {

/// How shadowproof::check runs, in the order check(op, f, {cases, seed, classes, fail_on, conv}).
struct check_settings {
  /// Every argument is optional, so {300, 7} is 300 cases from seed 7 (a constructor rather
  /// than an aggregate, so that a partial brace list draws no -Wmissing-field-initializers).
  check_settings(std::size_t cases_ = 1000, std::uint64_t seed_ = 1,
                 std::vector<input_class> classes_ = {input_class::regular, input_class::near_degenerate,
                                                      input_class::degenerate},
                 failure_policy fail_on_ = {}, conventions conv_ = {})
      : cases(cases_), seed(seed_), classes(std::move(classes_)), fail_on(std::move(fail_on_)), conv(conv_) {}

  std::size_t cases;  ///< how many cases (the run takes time in proportion, not memory)
  std::uint64_t seed; ///< the same seed gives the same cases and the same result
  /// Input classes (cases.h), taken in turn; the default has a third exactly degenerate and a
  /// third near a degeneracy.
  std::vector<input_class> classes;
  failure_policy fail_on;  ///< when a case fails (default: anything but correct rounding)
  conventions conv;        ///< the routine's conventions and input restrictions
  std::size_t shrink_budget = 4000;  ///< calls of the routine spent shrinking the worst case
};

/// The outcome of a property check; true when no case failed.
struct check_result {
  std::string routine;             ///< "shadow-matrix (f32)"
  std::size_t cases = 0, failed = 0;
  std::map<std::string, std::size_t> failed_by_verdict;  ///< "ulps", "nonfinite", "garbage", ...
  std::optional<test_case> worst;  ///< the worst failing case as generated
  std::optional<test_case> shrunk; ///< the same failure with the simplest inputs shrinking found
  std::string report;              ///< the failure message (empty when passed)

  explicit operator bool() const { return failed == 0; }
};

/// Writes the report, or "shadow-matrix (f32): 1000 cases pass (ulps>2)" when it passed.
std::ostream& operator<<(std::ostream& out, const check_result& r);

/// A float routine: reads signature(op).input_count inputs (the operation's input groups in
/// order, e.g. plane[4] then light[4]) and writes signature(op).output_count outputs in its
/// declared conventions (e.g. 16 matrix entries row by row).
using float_routine = std::function<void(const float* inputs, float* outputs)>;
/// The same in double.
using double_routine = std::function<void(const double* inputs, double* outputs)>;

/// Runs `routine` on settings.cases generated cases of `op` (verify/cases.h: every input exactly
/// a float, within the input restrictions of settings.conv, the classes in turn) and grades
/// every output against the exact answer for the very same inputs. A case fails as
/// settings.fail_on says, or when the routine throws. The result names how many failed and, for
/// the worst failing case (non-finite or garbage first, then misclassified, then most ulps), its
/// failing entries with the exact values and the reproducer command, before and after
/// shrinking (fuzz/shrink.h: inputs replaced by simpler floats while the routine still fails
/// the same way, by at least as many ulps). Deterministic in (op, settings).
check_result check(operation op, const float_routine& routine, const check_settings& settings = {});
/// The same for a double routine (f64 cases).
check_result check(operation op, const double_routine& routine, const check_settings& settings = {});

}  // namespace shadowproof
