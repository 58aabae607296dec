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
#include "shadowproof/verify/report.h"
#include "verify_print.h"

namespace shadowproof::cli {
namespace {

struct check_options {
  std::string impl;
  std::string op;
  std::size_t cases = 1200;
  std::uint64_t seed = 1;
  bool json = false;
  bool list = false;
  std::string svg;
  std::optional<std::uint64_t> max_ulps;
};

// One implementation's cases and grades.
struct impl_run {
  const implementation* impl;
  std::vector<test_case> cases;
  std::vector<case_grade> grades;
};

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
      const double x = closeness_to_degeneracy(c);
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
      double x = closeness_to_degeneracy(r.cases[k]);
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
  std::vector<const implementation*> chosen;
  for (const auto& impl : all)
    if ((o.impl == "all" || impl.name == o.impl) && (!op_filter || impl.op == *op_filter)) chosen.push_back(&impl);
  if (chosen.empty()) {
    bool known = o.impl == "all";
    for (const auto& impl : all) known = known || impl.name == o.impl;
    if (!known) throw error(errc::verify_unknown_impl, "no implementation named '" + o.impl + "' (see --list)");
    throw error(errc::verify_unknown_impl, "implementation '" + o.impl + "' does not compute --op " + o.op);
  }

  std::vector<impl_run> runs;
  oracle_counters counters;
  {
    progress_bar bar(chosen.size());
    for (const implementation* impl : chosen) {
      impl_run r{impl, generate_cases(impl->op, impl->type, o.cases, o.seed, std::nullopt, impl->conv), {}};
      r.grades = run_and_grade(*impl, r.cases, oracle_mode::filtered, &counters);
      runs.push_back(std::move(r));
      bar.step(impl->name);
    }
  }

  bool exceeded = false;
  std::vector<report_row> rows;
  nlohmann::json doc{{"seed", o.seed}, {"cases_per_impl", o.cases}, {"results", nlohmann::json::array()}};
  for (const auto& r : runs) {
    auto lookup = [&r](std::uint64_t id) -> const test_case& { return r.cases.at(id); };
    for (input_class cls : {input_class::regular, input_class::near_degenerate, input_class::degenerate}) {
      std::vector<case_grade> part;
      for (const auto& g : r.grades)
        if (g.cls == cls) part.push_back(g);
      if (part.empty()) continue;
      report_row row{r.impl->name, r.impl->op, r.impl->type, std::string(to_string(cls)), summarize(part)};
      if (o.max_ulps && (row.summary.max_ulps > *o.max_ulps || row.summary.nonfinite > 0)) exceeded = true;
      if (o.json) {
        nlohmann::json j = summary_json(row.summary, lookup, [&](std::uint64_t) -> const conventions& { return r.impl->conv; });
        j["impl"] = r.impl->name;
        j["op"] = std::string(to_string(r.impl->op));
        j["type"] = std::string(to_string(r.impl->type));
        j["class"] = row.cls;
        j["origin"] = r.impl->origin;
        j["conventions"] = conventions_json(r.impl->conv);
        doc["results"].push_back(j);
      }
      rows.push_back(std::move(row));
    }
  }
  if (!o.svg.empty()) write_svg(o.svg, runs);
  if (o.json) {
    doc["oracle"] = {{"decided_by_intervals", counters.decided_by_intervals},
                     {"fell_back_to_rationals", counters.fell_back_to_rationals}};
    if (o.max_ulps) doc["max_ulps_threshold"] = *o.max_ulps;
    doc["exceeded"] = exceeded;
    std::cout << doc.dump(2) << '\n';
    return exceeded ? 1 : 0;
  }
  std::cout << "Graded " << runs.size() << " implementation(s), " << o.cases
            << " cases each (seed " << o.seed << ") against the exact rational answer.\n"
            << "ulps: distance to the exact value correctly rounded to the output type; bits = log2(ulps + 1).\n\n";
  print_table(std::cout, rows);
  std::cout << "\nWorst case per implementation (bit-exact reproducers):\n";
  for (const auto& r : runs) {
    const grade_summary s = summarize(r.grades, 1);
    if (s.worst.empty()) {
      std::cout << "  " << r.impl->name << ": every output correctly rounded\n";
      continue;
    }
    print_worst(std::cout, r.impl->name, s.worst[0], r.cases.at(s.worst[0].id), r.impl->conv);
  }
  std::cout << "\nOracle: " << counters.decided_by_intervals << " cases decided by interval arithmetic, "
            << counters.fell_back_to_rationals << " by exact rationals.\n";
  if (!o.svg.empty()) std::cout << "Plot written to " << o.svg << '\n';
  if (o.max_ulps)
    std::cout << (exceeded ? "FAIL" : "PASS") << ": threshold --max-ulps " << *o.max_ulps
              << (exceeded ? " exceeded (or non-finite outputs where the exact value is finite)\n" : " held\n");
  return exceeded ? 1 : 0;
}

const command_registration reg{command{
    "check", "grade built-in float implementations (seed formulas, GLM, Eigen, Irrlicht, Ogre) against the exact oracle",
    [](CLI::App& app, const global_options&) {
      auto o = std::make_shared<check_options>();
      app.add_option("--impl", o->impl, "implementation name, or 'all' (see --list)");
      app.add_option("--op", o->op, "only this operation: " + operation_names(", "));
      app.add_option("--cases", o->cases, "cases per implementation (split between regular, near-degenerate, "
                                          "degenerate)")->capture_default_str();
      app.add_option("--seed", o->seed, "case generator seed (same seed, same cases)")->capture_default_str();
      app.add_flag("--json", o->json, "print one JSON document");
      app.add_option("--svg", o->svg, "write a plot of bits of error vs closeness to degeneracy");
      app.add_option("--max-ulps", o->max_ulps,
                     "exit with 1 when an output is more than this many ulps off, or non-finite where the "
                     "exact value is finite");
      app.add_flag("--list", o->list, "print the registered implementation names, one per line");
      return [o] { return run_check(*o); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
