// case_grade -> case_judgement under a failure policy (see judgement.h).
#include "judgement.h"

#include <algorithm>

namespace shadowproof::detail {

case_judgement judge(const case_grade& g, const failure_policy& policy) {
  case_judgement j;
  j.max_ulps = g.max_ulps;
  j.scale_pivot = g.scale_pivot;
  const auto& verdicts = policy.verdict_names();
  auto named = [&](const char* v) { return std::find(verdicts.begin(), verdicts.end(), v) != verdicts.end(); };
  const bool by_ulps = policy.ulps_threshold().has_value();
  const std::uint64_t limit = policy.ulps_threshold().value_or(0);
  const bool fail_nonfinite = by_ulps || named("nonfinite");
  const bool fail_garbage = by_ulps || named("garbage");

  for (std::size_t i = 0; i < g.outputs.size(); ++i) {
    const output_grade& o = g.outputs[i];
    entry_judgement e{i, entry_failure::ulps, o.got, o.reference, o.exact_defined, o.ulps};
    if (o.nonfinite && fail_nonfinite) e.failure = entry_failure::nonfinite;
    else if (o.garbage && fail_garbage) e.failure = entry_failure::garbage;
    else if (!(by_ulps && o.counted() && o.ulps > limit)) continue;
    j.entries.push_back(e);
  }
  const bool misclassified = by_ulps && g.misclassified;
  if (misclassified && g.exact_class && g.got_class) {
    j.exact_class = std::string(to_string(*g.exact_class));
    j.image_class = std::string(to_string(*g.got_class));
  }
  const bool bad_entry = std::any_of(j.entries.begin(), j.entries.end(),
                                     [](const entry_judgement& e) { return e.failure != entry_failure::ulps; });
  j.fails = !j.entries.empty() || misclassified;
  if (!j.fails) return j;
  if (bad_entry) {
    const auto first = std::find_if(j.entries.begin(), j.entries.end(),
                                    [](const entry_judgement& e) { return e.failure != entry_failure::ulps; });
    j.verdict = first->failure == entry_failure::nonfinite ? "nonfinite" : "garbage";
    j.severity = 3;
  } else if (misclassified) {
    j.verdict = "misclassified";
    j.severity = 2;
  } else {
    j.verdict = "ulps";
    j.severity = 1;
  }
  return j;
}

bool worse(const case_judgement& b, const case_judgement& a) {
  if (b.severity != a.severity) return b.severity > a.severity;
  return b.max_ulps > a.max_ulps;
}

}  // namespace shadowproof::detail
