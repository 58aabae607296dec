// Running an implementation on its cases and summarising the grades.
#include <algorithm>
#include <cmath>

#include "shadowproof/core/ulp.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/report.h"

namespace shadowproof {

const std::vector<double>& bits_histogram_edges() {
  static const std::vector<double> edges{0, 1, 4, 8, 16, 24, 53};
  return edges;
}

namespace {

// Orders cases from worst to best: by verdict, then misclassified, then ulps, then id.
bool worse(const case_grade& a, const case_grade& b) {
  if (a.v != b.v) return a.v > b.v;
  if (a.misclassified != b.misclassified) return a.misclassified;
  if (a.max_ulps != b.max_ulps) return a.max_ulps > b.max_ulps;
  return a.id < b.id;
}

bool has_nonfinite_output(const case_grade& g) {
  if (g.rejected && g.v == verdict::exact) return false;  // a correct rejection
  for (const auto& o : g.outputs)
    if (!std::isfinite(o.got)) return true;
  return false;
}

}  // namespace

grade_summary summarize(const std::vector<case_grade>& grades, std::size_t keep_worst) {
  grade_summary s;
  const auto& edges = bits_histogram_edges();
  s.bits_histogram.assign(edges.size() + 1, 0);
  s.verdicts.assign(all_verdicts().size(), 0);
  std::vector<std::uint64_t> ulps;
  std::vector<const case_grade*> example_finite(all_verdicts().size(), nullptr);
  std::vector<const case_grade*> example_nonfinite(all_verdicts().size(), nullptr);
  const case_grade* worst_finite = nullptr;
  const case_grade* worst_nonfinite = nullptr;
  for (const auto& g : grades) {
    ++s.cases;
    s.nonfinite += g.nonfinite;
    s.garbage += g.garbage;
    s.misclassified += g.misclassified ? 1 : 0;
    ++s.verdicts[static_cast<std::size_t>(g.v)];
    if (g.v > s.worst_verdict) s.worst_verdict = g.v;
    const bool nonfinite = has_nonfinite_output(g);
    const case_grade*& e = (nonfinite ? example_nonfinite : example_finite)[static_cast<std::size_t>(g.v)];
    if (!e || worse(g, *e)) e = &g;
    if (g.v > verdict::faithful || g.misclassified) {
      const case_grade*& w = nonfinite ? worst_nonfinite : worst_finite;
      if (!w || worse(g, *w)) w = &g;
    }
    for (const auto& o : g.outputs) {
      ++s.outputs;
      if (!o.counted()) continue;
      ulps.push_back(o.ulps);
      s.max_ulps = std::max(s.max_ulps, o.ulps);
      std::size_t bucket = 0;
      while (bucket < edges.size() && o.bits > edges[bucket]) ++bucket;
      ++s.bits_histogram[bucket];
    }
  }
  s.max_bits = bits_of_error(s.max_ulps);
  if (!ulps.empty()) {
    auto mid = ulps.begin() + static_cast<std::ptrdiff_t>((ulps.size() - 1) / 2);
    std::nth_element(ulps.begin(), mid, ulps.end());
    s.median_ulps = *mid;
  }
  std::vector<const case_grade*> order;
  for (const auto& g : grades)
    if (g.max_ulps > 0 || g.v > verdict::faithful || g.misclassified) order.push_back(&g);
  const std::size_t keep = std::min(keep_worst, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(keep), order.end(),
                    [](const case_grade* a, const case_grade* b) { return worse(*a, *b); });
  for (std::size_t i = 0; i < keep; ++i) s.worst.push_back(*order[i]);
  for (std::size_t v = all_verdicts().size(); v-- > static_cast<std::size_t>(verdict::stable);) {
    if (example_finite[v]) s.examples.push_back(*example_finite[v]);
    if (example_nonfinite[v]) s.examples.push_back(*example_nonfinite[v]);
  }
  if (worst_finite) s.worst_finite = *worst_finite;
  if (worst_nonfinite) s.worst_nonfinite = *worst_nonfinite;
  return s;
}

bool reaches(const grade_summary& s, verdict threshold) {
  for (std::size_t v = static_cast<std::size_t>(threshold); v < s.verdicts.size(); ++v)
    if (s.verdicts[v] > 0) return true;
  return false;
}

std::vector<case_grade> run_and_grade(const implementation& impl, const std::vector<test_case>& cases,
                                      oracle_mode mode, oracle_counters* counters) {
  std::vector<case_grade> grades;
  grades.reserve(cases.size());
  std::vector<double> out(signature(impl.op).output_count);
  for (const auto& c : cases) {
    std::fill(out.begin(), out.end(), 0.0);
    impl.run(c.inputs.data(), out.data());
    grades.push_back(grade_case(c, impl.conv, out.data(), mode, counters));
  }
  return grades;
}

}  // namespace shadowproof
