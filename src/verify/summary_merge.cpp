// Combining summaries of disjoint sets of grades into the summary of their union.
#include "shadowproof/verify/summary_merge.h"

#include <algorithm>
#include <set>

#include "shadowproof/core/error.h"
#include "shadowproof/core/ulp.h"

namespace shadowproof {

mergeable_summary summarize_mergeable(const std::vector<case_grade>& grades, std::size_t keep_worst) {
  mergeable_summary m;
  m.summary = summarize(grades, keep_worst);
  for (const auto& g : grades)
    for (const auto& o : g.outputs)
      if (o.counted()) ++m.ulps_counts[o.ulps];
  return m;
}

std::vector<case_grade> singled_out_cases(const grade_summary& s) {
  std::vector<case_grade> cases;
  std::set<std::uint64_t> ids;
  auto add = [&](const case_grade& g) {
    if (ids.insert(g.id).second) cases.push_back(g);
  };
  for (const auto& g : s.worst) add(g);
  for (const auto& g : s.examples) add(g);
  if (s.worst_finite) add(*s.worst_finite);
  if (s.worst_nonfinite) add(*s.worst_nonfinite);
  return cases;
}

mergeable_summary merge_summaries(const std::vector<mergeable_summary>& parts,
                                  const std::vector<case_grade>& candidates, std::size_t keep_worst) {
  // The choices first: summarize's order over the candidates picks what it picks over the
  // union, because each part's choices are among the candidates and the union's best of a
  // kind is the best of its part.
  std::vector<case_grade> sorted(candidates);
  std::sort(sorted.begin(), sorted.end(), [](const case_grade& a, const case_grade& b) { return a.id < b.id; });
  mergeable_summary m;
  m.summary = summarize(sorted, keep_worst);
  grade_summary& s = m.summary;
  // Then the statistics, from every part.
  s.cases = s.outputs = 0;
  s.nonfinite = s.garbage = s.misclassified = 0;
  s.max_ulps = 0;
  std::fill(s.bits_histogram.begin(), s.bits_histogram.end(), 0);
  std::fill(s.verdicts.begin(), s.verdicts.end(), 0);
  s.worst_verdict = verdict::exact;
  for (const auto& part : parts) {
    const grade_summary& p = part.summary;
    if (p.bits_histogram.size() != s.bits_histogram.size() || p.verdicts.size() != s.verdicts.size())
      throw internal_error("summaries of different shapes merged");
    s.cases += p.cases;
    s.outputs += p.outputs;
    s.nonfinite += p.nonfinite;
    s.garbage += p.garbage;
    s.misclassified += p.misclassified;
    s.max_ulps = std::max(s.max_ulps, p.max_ulps);
    for (std::size_t i = 0; i < s.bits_histogram.size(); ++i) s.bits_histogram[i] += p.bits_histogram[i];
    for (std::size_t i = 0; i < s.verdicts.size(); ++i) s.verdicts[i] += p.verdicts[i];
    s.worst_verdict = std::max(s.worst_verdict, p.worst_verdict);
    for (const auto& [ulps, n] : part.ulps_counts) m.ulps_counts[ulps] += n;
  }
  s.max_bits = bits_of_error(s.max_ulps);
  // The lower median: element (n − 1) / 2 of the sorted ulps.
  std::uint64_t n = 0;
  for (const auto& [ulps, k] : m.ulps_counts) n += k;
  s.median_ulps = 0;
  if (n > 0) {
    const std::uint64_t rank = (n - 1) / 2;
    std::uint64_t seen = 0;
    for (const auto& [ulps, k] : m.ulps_counts) {
      seen += k;
      if (seen > rank) {
        s.median_ulps = ulps;
        break;
      }
    }
  }
  return m;
}

}  // namespace shadowproof
