// Sections of the HTML report for graded implementations.
#include "html_sections.h"

#include <cmath>
#include <set>
#include <sstream>

#include "shadowproof/verify/cases.h"

namespace shadowproof::cli {
namespace {

bool has_nonfinite_output(const case_grade& g) {
  for (const auto& o : g.outputs)
    if (!std::isfinite(o.got)) return true;
  return false;
}

std::string number_text(double x) {
  if (std::isnan(x)) return "NaN";
  if (std::isinf(x)) return x > 0 ? "+Inf" : "-Inf";
  std::ostringstream s;
  s.precision(9);
  s << x;
  return s.str();
}

html_case case_entry(const graded_run& run, const case_grade& g, const std::string& kind) {
  const test_case& c = run.lookup(g.id);
  html_case h;
  h.title = std::string(to_string(g.v)) + (kind.empty() ? "" : ", " + kind) + ": case " + std::to_string(g.id) + " (" +
            std::string(to_string(g.cls)) + "), max " + ulps_text(g.max_ulps) + " ulps" +
            (g.misclassified ? ", misclassified" : "");
  std::string inputs = "inputs:";
  for (double x : c.inputs) inputs += " " + number_text(x);
  h.details.push_back(inputs);
  const std::size_t j = g.verdict_output < g.outputs.size() ? g.verdict_output : 0;
  if (!g.outputs.empty()) {
    const output_grade& o = g.outputs[j];
    h.details.push_back("output " + output_name(run.op, j, *run.conv) + ": got " + number_text(o.got) +
                        (o.exact_defined ? ", exact correctly rounded " + number_text(o.reference) : ", exact: none") +
                        (o.counted() ? ", " + ulps_text(o.ulps) + " ulps" : "") + ", " + std::string(to_string(o.v)));
  }
  if (g.exact_class && g.got_class)
    h.details.push_back("exact class " + std::string(to_string(*g.exact_class)) + ", float image " +
                        std::string(to_string(*g.got_class)));
  h.reproducer = reproducer_command(c, *run.conv);
  return h;
}

}  // namespace

void add_to_plot(point_cloud& plot, const test_case& c, const case_grade& g) {
  const double x = std::isnan(c.closeness) ? closeness_to_degeneracy(c) : c.closeness;
  plot.add(x, g.max_bits, g.nonfinite > 0 || g.garbage > 0);
}

html_section graded_section(const graded_run& run) {
  const grade_summary& s = *run.summary;
  html_section h;
  h.name = run.name;
  h.verdict = std::string(to_string(s.worst_verdict));
  h.failed = run.failed;
  h.facts = {{"cases", std::to_string(s.cases)},
             {"operation", std::string(to_string(run.op))},
             {"type", std::string(to_string(run.type))},
             {"max ulps", ulps_text(s.max_ulps)},
             {"median ulps", ulps_text(s.median_ulps)}};
  if (s.nonfinite) h.facts.emplace_back("NaN/Inf outputs", std::to_string(s.nonfinite));
  if (s.garbage) h.facts.emplace_back("garbage outputs", std::to_string(s.garbage));
  if (s.misclassified) h.facts.emplace_back("misclassified", std::to_string(s.misclassified));
  if (!run.origin.empty()) h.facts.emplace_back("from", run.origin);
  for (std::size_t v = 0; v < s.verdicts.size(); ++v)
    if (s.verdicts[v]) h.counts.emplace_back(std::string(to_string(all_verdicts()[v])), s.verdicts[v]);
  const nlohmann::json declared = conventions_json(*run.conv);  // items() refers to it
  for (const auto& [key, value] : declared.items())
    h.conventions.emplace_back(key, value.is_string() ? value.get<std::string>() : value.dump());
  if (run.plot) h.points = run.plot->points();
  // Per verdict worse than faithful, its worst finite and its worst non-finite case; a
  // misclassified case when nothing else shows.
  std::set<std::uint64_t> shown;
  for (const auto& g : s.examples)
    if (g.v > verdict::faithful && shown.insert(g.id).second)
      h.worst.push_back(case_entry(run, g, has_nonfinite_output(g) ? "non-finite" : "finite"));
  for (const auto* g : {s.worst_finite ? &*s.worst_finite : nullptr, s.worst_nonfinite ? &*s.worst_nonfinite : nullptr})
    if (g && shown.insert(g->id).second) h.worst.push_back(case_entry(run, *g, "worst"));
  return h;
}

}  // namespace shadowproof::cli
