// shadowproof check: runs the built-in implementations under test on generated cases and
// grades every output against the exact answer for the very same float inputs.
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

#include "command.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/io.h"
#include "shadowproof/core/svg.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/impls/builtin.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/protocol.h"
#include "shadowproof/verify/report.h"
#include "verify_print.h"

namespace shadowproof::cli {
namespace {

struct check_options {
  std::string impl;
  std::string op;
  std::string cls;
  std::size_t cases = 1200;
  std::uint64_t seed = 1;
  bool json = false;
  bool wide = false;
  bool list = false;
  std::string svg;
  std::string input;
  std::optional<std::uint64_t> max_ulps;
  std::string fail_on;
};

// One implementation's cases and grades.
struct impl_run {
  const implementation* impl;
  std::vector<test_case> cases;
  std::vector<case_grade> grades;
  const test_case& by_id(std::uint64_t id) const {
    if (id < cases.size() && cases[id].id == id) return cases[id];  // generated cases: id = index
    for (const auto& c : cases)
      if (c.id == id) return c;
    throw internal_error("a grade names a case that was not graded");
  }
};

// The cases of a case file (`shadowproof cases` format), for reproducing a finding with a
// built-in implementation.
std::vector<test_case> read_cases(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw error(errc::grade_file, "cannot read the cases file '" + path + "'");
  std::vector<test_case> cases;
  std::string line;
  for (std::size_t n = 1; std::getline(f, line); ++n)
    if (line.find_first_not_of(" \t\r") != std::string::npos) cases.push_back(parse_case_line(line, n));
  if (cases.empty()) throw error(errc::grade_empty, "the case file '" + path + "' has no case");
  return cases;
}

class progress_bar {
 public:
  explicit progress_bar(std::size_t total) : total_(total), enabled_(isatty(STDERR_FILENO) == 1) {}
  void step(const std::string& label) {
    if (!enabled_) return;
    ++done_;
    const std::size_t width = 30, filled = width * done_ / std::max<std::size_t>(total_, 1);
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] " << done_ << '/'
              << total_ << ' ' << label << "\x1b[K" << std::flush;
  }
  ~progress_bar() {
    if (enabled_) std::cerr << "\r\x1b[K" << std::flush;
  }

 private:
  std::size_t total_, done_ = 0;
  bool enabled_;
};

// Bits of error (max over a case's outputs) against log2 closeness to degeneracy, one colour
// per implementation. Exactly degenerate cases (closeness −inf) sit in a band at the left;
// cases with a non-finite or garbage output sit in a band at the top.
void write_svg(const std::string& path, const std::vector<impl_run>& runs) {
  const double W = 960, left = 70, right = 250, top = 40, bottom = 60;
  const double H = std::max(560.0, top + 14.0 * static_cast<double>(runs.size()) + 30);  // room for the legend
  double xmin = 0, xmax = 0;
  for (const auto& r : runs)
    for (const auto& c : r.cases) {
      const double x = c.closeness;
      if (std::isfinite(x)) { xmin = std::min(xmin, x); xmax = std::max(xmax, x); }
    }
  xmin = std::floor(xmin / 10) * 10 - 10;  // room for the exactly-degenerate band
  xmax = std::max(xmax, 0.0) + 2;
  const double ymax = 70;
  auto sx = [&](double x) { return left + (x - xmin) / (xmax - xmin) * (W - left - right); };
  auto sy = [&](double y) { return H - bottom - y / ymax * (H - top - bottom); };
  static const char* palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                                  "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#393b79", "#637939",
                                  "#8c6d31", "#843c39", "#7b4173", "#3182bd", "#e6550d", "#31a354"};
  svg_document f(W, H);  // a tenth of a pixel is plenty
  f.text(left, 22, "bits of error (max per case) vs closeness to degeneracy (shadows: log2 |P·L| / (|P||L|))", "start",
         "", 14);
  for (int y = 0; y <= 64; y += 8) {
    f.line(left, sy(y), W - right, sy(y), "#ddd");
    f.text(left - 8, sy(y) + 4, std::to_string(y), "end");
  }
  for (double x = std::ceil((xmin + 10) / 20) * 20; x <= xmax; x += 20) {
    f.line(sx(x), top, sx(x), H - bottom, "#eee");
    f.text(sx(x), H - bottom + 16, std::to_string(static_cast<int>(x)), "middle");
  }
  f.text(sx(xmin + 4), H - bottom + 16, "exact 0", "middle");
  f.text(W - right, sy(66), "non-finite / garbage", "end");
  f.text((left + W - right) / 2, H - 18, "log2 closeness (0 = far from degenerate; more negative = closer)", "middle");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const char* colour = palette[i % (sizeof palette / sizeof *palette)];
    const auto& r = runs[i];
    for (std::size_t k = 0; k < r.cases.size(); ++k) {
      const auto& g = r.grades[k];
      double x = r.cases[k].closeness;
      if (!std::isfinite(x)) x = xmin + 4;
      const double y = (g.nonfinite || g.garbage) ? 66 : std::min(g.max_bits, 64.0);
      f.circle(sx(x), sy(y), 1.6, colour, 0.55);
    }
    f.rect(W - right + 12, top + 14 * i, 9, 9, colour);
    f.text(W - right + 26, top + 14 * i + 9, r.impl->name);
  }
  // Written atomically: a killed run leaves the old file.
  write_file_atomically(path, f.str());
}

// The gates of --max-ulps (an output more ulps off, or any NaN/Inf where the exact value exists,
// garbage or misclassified case) and --fail-on (a case at or past the verdict).
struct gates {
  std::optional<std::uint64_t> max_ulps;
  std::optional<verdict> fail_on;
  bool ulps_exceeded(const grade_summary& s) const {
    return max_ulps && (s.max_ulps > *max_ulps || s.nonfinite > 0 || s.garbage > 0 || s.misclassified > 0);
  }
  bool verdict_reached(const grade_summary& s) const { return fail_on && reaches(s, *fail_on); }
};

std::optional<verdict> parse_fail_on(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const auto v = verdict_from_string(text);
  if (!v) {
    std::string names;
    for (verdict x : all_verdicts()) names += (names.empty() ? "" : ", ") + std::string(to_string(x));
    throw error(errc::verify_unknown_verdict, "unknown --fail-on '" + text + "'; expected one of " + names);
  }
  return v;
}

int run_check(const check_options& o) {
  const auto& all = builtin_implementations();
  if (o.list) {
    for (const auto& impl : all) std::cout << impl.name << '\n';
    return 0;
  }
  if (o.impl.empty()) throw error(errc::check_no_impl, "give --impl NAME (or --impl all); --list shows the names");
  std::optional<operation> op_filter;
  if (!o.op.empty()) {
    op_filter = operation_from_string(o.op);
    if (!op_filter)
      throw error(errc::verify_unknown_op, "unknown --op '" + o.op + "'; expected one of " + operation_names(", "));
  }
  if (o.cases == 0) throw error(errc::check_cases, "--cases must be at least 1");
  std::optional<input_class> class_filter;
  if (!o.cls.empty()) {
    class_filter = input_class_from_string(o.cls);
    if (!class_filter)
      throw error(errc::verify_unknown_class,
                  "unknown --class '" + o.cls + "'; expected regular, near-degenerate, degenerate or range");
  }
  const gates gate{o.max_ulps, parse_fail_on(o.fail_on)};
  std::vector<const implementation*> chosen;
  for (const auto& impl : all)
    if ((o.impl == "all" || impl.name == o.impl) && (!op_filter || impl.op == *op_filter)) chosen.push_back(&impl);
  if (chosen.empty()) {
    bool known = o.impl == "all";
    for (const auto& impl : all) known = known || impl.name == o.impl;
    if (!known) throw error(errc::verify_unknown_impl, "no implementation named '" + o.impl + "' (see --list)");
    throw error(errc::verify_unknown_impl, "implementation '" + o.impl + "' does not compute --op " + o.op);
  }

  std::vector<test_case> given;
  if (!o.input.empty()) {
    given = read_cases(o.input);
    std::vector<const implementation*> matching;
    for (const implementation* impl : chosen)
      if (impl->op == given.front().op && impl->type == given.front().type) matching.push_back(impl);
    if (matching.empty())
      throw error(errc::verify_unknown_impl, "no chosen implementation computes " + std::string(to_string(given.front().op)) +
                                             " in " + std::string(to_string(given.front().type)) + " as " + o.input +
                                             "'s cases need");
    for (const auto& c : given)
      if (c.op != given.front().op || c.type != given.front().type)
        throw error(errc::protocol_case, o.input + ": case " + std::to_string(c.id) + " is not a " +
                                         std::string(to_string(given.front().op)) + " " +
                                         std::string(to_string(given.front().type)) + " case like the first");
    chosen = matching;
  }
  std::vector<impl_run> runs;
  oracle_counters counters;
  {
    progress_bar bar(chosen.size());
    for (const implementation* impl : chosen) {
      impl_run r{impl, given.empty() ? generate_cases(impl->op, impl->type, o.cases, o.seed, class_filter, impl->conv)
                                     : given, {}};
      r.grades = run_and_grade(*impl, r.cases, oracle_mode::filtered, &counters);
      runs.push_back(std::move(r));
      bar.step(impl->name);
    }
  }

  bool ulps_failed = false, verdict_failed = false;
  std::vector<verdict_row> rows;
  std::vector<grade_summary> summaries;
  for (const auto& r : runs) {
    summaries.push_back(summarize(r.grades, 3));
    ulps_failed = ulps_failed || gate.ulps_exceeded(summaries.back());
    verdict_failed = verdict_failed || gate.verdict_reached(summaries.back());
    rows.push_back({r.impl->name, summaries.back()});
  }
  const bool failed = ulps_failed || verdict_failed;
  if (!o.svg.empty()) write_svg(o.svg, runs);
  if (o.json) {
    nlohmann::json doc{{"seed", o.seed}, {"cases_per_impl", o.cases}, {"results", nlohmann::json::array()}};
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const auto& r = runs[i];
      auto lookup = [&r](std::uint64_t id) -> const test_case& { return r.by_id(id); };
      auto conv_of = [&r](std::uint64_t) -> const conventions& { return r.impl->conv; };
      nlohmann::json j = summary_json(summaries[i], lookup, conv_of);
      j["impl"] = r.impl->name;
      j["op"] = std::string(to_string(r.impl->op));
      j["type"] = std::string(to_string(r.impl->type));
      j["origin"] = r.impl->origin;
      j["conventions"] = conventions_json(r.impl->conv);
      nlohmann::json by_class = nlohmann::json::object();
      for (input_class cls : all_input_classes()) {
        std::vector<case_grade> part;
        for (const auto& g : r.grades)
          if (g.cls == cls) part.push_back(g);
        if (part.empty()) continue;
        const grade_summary s = summarize(part, 1);
        nlohmann::json c = summary_json(s, lookup, conv_of);
        c.erase("examples");
        by_class[std::string(to_string(cls))] = c;
      }
      j["by_class"] = by_class;
      nlohmann::json verdicts = nlohmann::json::array();
      for (const auto& g : r.grades) verdicts.push_back(std::string(to_string(g.v)));
      j["case_verdicts"] = verdicts;  // by case id
      doc["results"].push_back(j);
    }
    doc["oracle"] = {{"decided_by_intervals", counters.decided_by_intervals},
                     {"fell_back_to_rationals", counters.fell_back_to_rationals}};
    if (o.max_ulps) doc["max_ulps_threshold"] = *o.max_ulps;
    if (gate.fail_on) doc["fail_on"] = std::string(to_string(*gate.fail_on));
    doc["exceeded"] = failed;
    std::cout << doc.dump(2) << '\n';
    return failed ? 1 : 0;
  }
  const report_style style{o.wide, 100};
  std::cout << "Graded " << runs.size() << " implementation" << (runs.size() == 1 ? "" : "s") << ", "
            << (given.empty() ? std::to_string(o.cases) + " cases each (seed " + std::to_string(o.seed) + ")"
                              : std::to_string(given.size()) + " cases of " + o.input)
            << ", against the exact rational answer.\n"
            << "A case's verdict is that of its worst output, an implementation's that of its worst case\n"
            << "(docs/verdicts.md); the table counts cases.\n\n";
  print_verdict_table(std::cout, rows, style);
  bool first = true;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (summaries[i].worst_verdict <= verdict::faithful && !summaries[i].misclassified) continue;
    if (first) std::cout << "\nWorst cases (bit-exact; each command prints the exact answer):\n";
    first = false;
    const auto& r = runs[i];
    auto lookup = [&r](std::uint64_t id) -> const test_case& { return r.by_id(id); };
    auto conv_of = [&r](std::uint64_t) -> const conventions& { return r.impl->conv; };
    print_examples(std::cout, r.impl->name, summaries[i], lookup, conv_of, style);
  }
  std::cout << "\nOracle: " << counters.decided_by_intervals << " cases decided by interval arithmetic, "
            << counters.fell_back_to_rationals << " by exact rationals.\n";
  if (!o.svg.empty()) std::cout << "Plot written to " << o.svg << '\n';
  if (o.max_ulps)
    std::cout << (ulps_failed ? "FAIL" : "PASS") << ": --max-ulps " << *o.max_ulps
              << (ulps_failed ? " exceeded, or NaN/Inf, garbage or misclassified cases\n" : " held\n");
  if (gate.fail_on)
    std::cout << (verdict_failed ? "FAIL" : "PASS") << ": --fail-on " << to_string(*gate.fail_on)
              << (verdict_failed ? ": some case is at or past it\n" : ": every case is better\n");
  return failed ? 1 : 0;
}

const command_registration reg{command{
    "check", "grade built-in float implementations (seed formulas, GLM, Eigen, Irrlicht, Ogre) against the exact oracle",
    [](CLI::App& app, const global_options&) {
      auto o = std::make_shared<check_options>();
      app.add_option("--impl", o->impl, "implementation name, or 'all' (see --list)");
      app.add_option("--op", o->op, "only this operation: " + operation_names(", "));
      app.add_option("--cases", o->cases, "cases per implementation (cycling regular, near-degenerate, "
                                          "degenerate, range)")->capture_default_str();
      app.add_option("--class", o->cls, "only regular, near-degenerate, degenerate or range cases (default: cycle)");
      app.add_option("--seed", o->seed, "case generator seed (same seed, same cases)")->capture_default_str();
      app.add_flag("--json", o->json, "print one JSON document (every field, every case's verdict)");
      app.add_flag("--wide", o->wide, "show a worst case per verdict, with every output and the inputs");
      app.add_option("--svg", o->svg, "write a plot of bits of error vs closeness to degeneracy");
      app.add_option("--input", o->input,
                     "grade on the cases of this file (the `shadowproof cases` format) instead of generated ones");
      app.add_option("--max-ulps", o->max_ulps,
                     "exit with 1 when an output is more than this many ulps off, or NaN/Inf where the exact "
                     "value exists, or a case is garbage or misclassified");
      app.add_option("--fail-on", o->fail_on,
                     "exit with 1 when a case is at or past this verdict: exact, faithful, stable, unstable, "
                     "range, wrong, nonfinite, garbage");
      app.add_flag("--list", o->list, "print the registered implementation names, one per line");
      return [o] { return run_check(*o); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
