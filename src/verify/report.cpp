// Running an implementation on its cases and summarising the grades.
#include <algorithm>

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

// Orders cases from worst to best: non-finite and garbage first, then misclassified, then ulps.
bool worse(const case_grade& a, const case_grade& b) {
  const auto bad = [](const case_grade& g) { return g.nonfinite + g.garbage; };
  if (bad(a) != bad(b)) return bad(a) > bad(b);
  if (a.misclassified != b.misclassified) return a.misclassified;
  if (a.max_ulps != b.max_ulps) return a.max_ulps > b.max_ulps;
  return a.id < b.id;
}

}  // namespace

grade_summary summarize(const std::vector<case_grade>& grades, std::size_t keep_worst) {
  grade_summary s;
  const auto& edges = bits_histogram_edges();
  s.bits_histogram.assign(edges.size() + 1, 0);
  std::vector<std::uint64_t> ulps;
  for (const auto& g : grades) {
    ++s.cases;
    s.nonfinite += g.nonfinite;
    s.garbage += g.garbage;
    s.misclassified += g.misclassified ? 1 : 0;
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
    if (g.max_ulps > 0 || g.nonfinite || g.garbage || g.misclassified) order.push_back(&g);
  const std::size_t keep = std::min(keep_worst, order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(keep), order.end(),
                    [](const case_grade* a, const case_grade* b) { return worse(*a, *b); });
  for (std::size_t i = 0; i < keep; ++i) s.worst.push_back(*order[i]);
  return s;
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
