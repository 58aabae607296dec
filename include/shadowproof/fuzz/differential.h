#pragma once
/// Differential fuzzing of a registered implementation against the exact oracle, with
/// shrinking of every failure and metamorphic checks that need no oracle.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "shadowproof/fuzz/generate.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/shard.h"

namespace shadowproof {

/// How a case fails. `metamorphic`: the implementation's outputs for a transformed input are
/// not the transformed outputs (no oracle involved).
enum class failure_kind { nonfinite, garbage, misclassified, ulps, metamorphic };
std::string_view to_string(failure_kind k);

struct fuzz_settings {
  std::optional<double> seconds;        ///< stop after this long (the case count then varies)
  std::optional<std::size_t> cases;     ///< or after this many cases (byte-identical reruns)
  std::uint64_t seed = 1;
  std::uint64_t ulps_threshold = 1u << 20;  ///< an output this many ulps off (or more) fails
  bool metamorphic = true;
  std::size_t shrink_budget = 4000;     ///< predicate calls per shrink
  /// Threads that run and grade the cases (0: default_jobs()); the report is the same for
  /// any number. More than 1 calls impl.run from several threads at once.
  unsigned jobs = 1;
  /// Only the cases of this shard are run (case n of the stream is drawn by every shard, so
  /// each case is the same whatever the shard count; see shard).
  shard part;
  /// Called with every case run and its grade (for plots); may be empty.
  std::function<void(const test_case&, const case_grade&)> on_case;
};

struct fuzz_failure {
  failure_kind kind = failure_kind::ulps;
  std::string family;     ///< generator family of the original case
  std::string relation;   ///< metamorphic relation ("scale_plane", ...), else empty
  test_case original, shrunk;
  case_grade original_grade, shrunk_grade;  ///< metamorphic: grades of the untransformed case
  double bits = 0;        ///< bits of error of the original (metamorphic: of the disagreement)
  std::size_t bits_before = 0, bits_after = 0;
  std::uint64_t threshold = 0;  ///< the ulps threshold the failure was found with
};

struct fuzz_report {
  std::string impl;
  std::size_t cases = 0;
  std::map<std::string, std::size_t> failing_cases;  ///< by kind, before de-duplication
  std::map<std::string, std::uint64_t> metamorphic_max_ulps;  ///< by relation
  /// The first failure of each (kind, family[, relation]), shrunk; in the order found.
  std::vector<fuzz_failure> failures;
};

/// The generated configuration as a case of `impl`'s operation and type, within its declared
/// requirements. Exact families become `degenerate`, their ulp/2^-k neighbours
/// `near_degenerate`, the rest `regular`.
test_case make_fuzz_case(const generated_case<double>& g, const implementation& impl, std::uint64_t id);

/// What makes failures the same bug: the kind and the base family of the original case (for a
/// misclassification the pair of classes, for a metamorphic failure also the relation). A report
/// keeps the first failure of each key.
std::string failure_key(const fuzz_failure& f);

/// The report of the whole run from the reports of its shards (any order): case and failure
/// counts added, metamorphic maxima taken, and of each failure key the failure of the lowest
/// case id kept, in the order of the unsharded run (by case id, then kind, then relation in
/// metamorphic_relations order). Equal to the unsharded report for a run of a case count.
fuzz_report merge_fuzz_reports(const std::vector<fuzz_report>& shards, operation op);

/// Runs the campaign. `progress(cases, failures)` is called about once a second.
fuzz_report run_fuzz(const implementation& impl, const fuzz_settings& settings,
                     const std::function<void(std::size_t, std::size_t)>& progress = {});

/// The metamorphic relations that apply to `op` (names as in the report).
std::vector<std::string> metamorphic_relations(operation op);

/// Checks one relation on one case: nothing when it holds (or does not apply to the case),
/// otherwise the disagreement in ulps (UINT64_MAX when one side is non-finite and the other not).
/// A disagreement past `threshold` counts only when the oracle blames the formula on one of the
/// two cases; `original_grade`, when the caller already holds the grade of `c`, spares grading
/// it again.
std::optional<std::uint64_t> metamorphic_violation(const implementation& impl, const test_case& c,
                                                   const std::string& relation, std::uint64_t threshold,
                                                   const case_grade* original_grade = nullptr);

/// A ready-to-paste Catch2 test that reproduces the (shrunk) failure through the registry.
std::string catch2_regression_test(const implementation& impl, const fuzz_failure& f);

}  // namespace shadowproof
