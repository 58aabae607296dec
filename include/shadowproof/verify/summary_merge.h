#pragma once
/// Summaries of parts of a run (shards) combined into the summary of the whole run, exactly.
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/report.h"

namespace shadowproof {

/// A summary and what combining it with others needs besides: how many counted outputs are
/// off by each number of ulps (the median of a union is not a function of the parts' medians).
struct mergeable_summary {
  grade_summary summary;
  std::map<std::uint64_t, std::uint64_t> ulps_counts;  ///< ulps → counted outputs
};

/// summarize(grades, keep_worst) and the distribution of ulps over its counted outputs.
mergeable_summary summarize_mergeable(const std::vector<case_grade>& grades, std::size_t keep_worst);

/// Every case a summary singles out (worst, examples, worst finite and non-finite), each once,
/// by id: the only cases a merge needs in full.
std::vector<case_grade> singled_out_cases(const grade_summary& s);

/// The summary of the union of disjoint sets of grades from the summaries of the sets:
/// counts, histograms and verdict counts added, maxima taken, the lower median read from the
/// merged distribution of ulps, and every case the summary singles out chosen again among the
/// parts' singled-out cases (`candidates`: those cases graded in full, in any order) by
/// summarize's own order, whose ties go to the lowest id. So for any partition of a set of
/// grades G into parts, merge_summaries(parts, …) equals summarize_mergeable(G, keep_worst).
/// Requires each part to have been summarised with at least `keep_worst` worst cases.
mergeable_summary merge_summaries(const std::vector<mergeable_summary>& parts,
                                  const std::vector<case_grade>& candidates, std::size_t keep_worst);

}  // namespace shadowproof
