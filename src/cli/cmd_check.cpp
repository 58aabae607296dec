// shadowproof check: runs the built-in implementations under test on generated cases and
// grades every output against the exact answer for the very same float inputs.
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <future>
#include <mutex>
#include <set>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <sstream>

#include "command.h"
#include "jobs_option.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/io.h"
#include "shadowproof/core/svg.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/impls/builtin.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/parallel.h"
#include "shadowproof/verify/protocol.h"
#include "shadowproof/verify/report.h"
#include "shadowproof/verify/summary_merge.h"
#include "html_sections.h"
#include "shard_report.h"
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
  unsigned jobs = 0;  // 0: default_jobs()
  std::string shard_spec;
  std::string html;
  std::string command_line;
};

// What makes two check reports shards of one run.
nlohmann::json run_json(const check_options& o) {
  return {{"command", "check"}, {"impl", o.impl}, {"op", o.op}, {"class", o.cls}, {"cases", o.cases},
          {"seed", o.seed}, {"input", o.input}, {"max_ulps", o.max_ulps ? nlohmann::json(*o.max_ulps) : nlohmann::json()},
          {"fail_on", o.fail_on}};
}

// One implementation's run, summarised chunk by chunk as its grades arrive: what the report
// prints (counts, histograms, the distribution of ulps behind the median, the cases the
// summaries single out) and never every case, so memory does not grow with --cases. Only what a
// report prints per case is kept per case, and only for that report: the verdicts of --json and
// the positions of a shard's --json.
struct impl_tally {
  const implementation* impl = nullptr;
  std::optional<mergeable_summary> whole;                                    // 3 worst cases
  std::map<input_class, std::optional<mergeable_summary>> by_class;         // 1 worst case each
  std::map<std::uint64_t, test_case> singled;  // the cases the summaries single out, by id
  std::vector<verdict> verdicts;               // of every case in order (--json only)
  std::vector<std::size_t> positions;          // of each case in the whole run (a shard's --json only)
  point_cloud plot;                            // --svg and --html only
  oracle_counters counters;
  std::size_t graded = 0;
  const test_case& by_id(std::uint64_t id) const {
    const auto it = singled.find(id);
    if (it == singled.end()) throw internal_error("a summary names a case that was not kept");
    return it->second;
  }
};

// What a run keeps of each case besides the summaries.
struct kept_per_case {
  bool verdicts = false, positions = false, plot = false;
  bool class_summaries = false;  // only --json prints the summary of each input class
};

// A chunk of one implementation's cases (a shard's share of them), where each stood in the
// whole run, and their grades.
struct case_chunk {
  std::vector<test_case> cases;
  std::vector<std::size_t> positions;
  std::vector<case_grade> grades;
};

// acc becomes the summary of its grades and `grades`: by merge_summaries, whose result for any
// partition of a set of grades is the summary of the whole set.
void merge_into(std::optional<mergeable_summary>& acc, const std::vector<case_grade>& grades, std::size_t keep_worst) {
  if (grades.empty()) return;
  mergeable_summary part = summarize_mergeable(grades, keep_worst);
  if (!acc) {
    acc = std::move(part);
    return;
  }
  std::vector<case_grade> candidates = singled_out_cases(acc->summary);
  for (auto& g : singled_out_cases(part.summary)) candidates.push_back(std::move(g));
  std::vector<mergeable_summary> parts;
  parts.push_back(std::move(*acc));
  parts.push_back(std::move(part));
  acc = merge_summaries(parts, candidates, keep_worst);
}

// Adds a graded chunk to the tally, then keeps only the cases the summaries now single out.
void add_chunk(impl_tally& t, const case_chunk& chunk, const kept_per_case& keep) {
  t.graded += chunk.grades.size();
  merge_into(t.whole, chunk.grades, 3);
  if (keep.class_summaries) {
    for (input_class cls : all_input_classes()) {
      std::vector<case_grade> of_class;
      for (const auto& g : chunk.grades)
        if (g.cls == cls) of_class.push_back(g);
      if (!of_class.empty()) merge_into(t.by_class[cls], of_class, 1);
    }
  }
  std::set<std::uint64_t> ids;
  auto note = [&](const std::optional<mergeable_summary>& m) {
    if (m)
      for (const auto& g : singled_out_cases(m->summary)) ids.insert(g.id);
  };
  note(t.whole);
  for (const auto& [cls, m] : t.by_class) note(m);
  for (auto it = t.singled.begin(); it != t.singled.end();) it = ids.count(it->first) ? std::next(it) : t.singled.erase(it);
  for (const auto& c : chunk.cases)
    if (ids.count(c.id)) t.singled.emplace(c.id, c);
  for (std::size_t k = 0; k < chunk.grades.size(); ++k) {
    if (keep.verdicts) t.verdicts.push_back(chunk.grades[k].v);
    if (keep.positions) t.positions.push_back(chunk.positions[k]);
    if (keep.plot) add_to_plot(t.plot, chunk.cases[k], chunk.grades[k]);
  }
}

// Cases are generated, graded and summarised this many at a time.
constexpr std::size_t chunk_size = 8192;

// Runs and grades one implementation on `total` cases (generated from the seed, or `given`),
// chunk by chunk: while `jobs` threads run and grade a chunk, one more thread summarises the
// previous chunk and generates the next, so neither waits on the other. The tally is the same
// for any jobs: chunks are generated from the one stream in order and summarised in order.
impl_tally tally_implementation(const implementation& impl, const check_options& o, const std::vector<test_case>& given,
                                std::optional<input_class> class_filter, const shard& part, unsigned jobs,
                                const kept_per_case& keep) {
  impl_tally t;
  t.impl = &impl;
  std::optional<case_stream> stream;
  if (given.empty()) stream.emplace(impl.op, impl.type, o.seed, class_filter, impl.conv);
  const std::size_t total = given.empty() ? o.cases : given.size();
  auto chunk_at = [&](std::size_t first) {
    case_chunk chunk;
    const std::size_t n = std::min(chunk_size, total - first);
    std::vector<test_case> cases =
        stream ? stream->next(n)
               : std::vector<test_case>(given.begin() + static_cast<std::ptrdiff_t>(first),
                                        given.begin() + static_cast<std::ptrdiff_t>(first + n));
    for (std::size_t k = 0; k < n; ++k)
      if (part.contains(cases[k].id)) {  // a shard keeps its own cases
        chunk.cases.push_back(std::move(cases[k]));
        chunk.positions.push_back(first + k);
      }
    return chunk;
  };
  const bool helper = jobs > 1;  // with one job, everything on the one thread, in order
  case_chunk current = chunk_at(0), previous;
  bool have_previous = false;
  for (std::size_t first = 0; first < total; first += chunk_size) {
    const std::size_t next_first = first + chunk_size;
    auto prepare = [&, next_first, summarise = have_previous] {
      if (summarise) add_chunk(t, previous, keep);
      return next_first < total ? chunk_at(next_first) : case_chunk{};
    };
    std::future<case_chunk> upcoming;
    if (helper)
      upcoming = std::async(std::launch::async, [&prepare] {
        case_chunk chunk = prepare();
        release_thread_caches();
        return chunk;
      });
    // The helper touches neither the current chunk nor the counters.
    current.grades = run_and_grade_in_parallel(impl, current.cases, jobs, oracle_mode::filtered, &t.counters);
    case_chunk next = helper ? upcoming.get() : prepare();
    previous = std::move(current);
    have_previous = true;
    current = std::move(next);
  }
  if (have_previous) add_chunk(t, previous, keep);
  // The distribution of ulps behind the medians (one entry per distinct number of ulps) is
  // printed only in a shard's report; the others need only the medians taken from it.
  if (!keep.positions) {
    if (t.whole) t.whole->ulps_counts.clear();
    for (auto& [cls, m] : t.by_class)
      if (m) m->ulps_counts.clear();
  }
  return t;
}

// Thread CPU time in seconds (load on the machine does not count).
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The order in which threads that take whole implementations take them: costliest first, so
// that the last implementation a thread takes is a short one and no thread waits long for
// another at the end (the cost of an implementation varies a hundredfold: a look-at builder's
// near-degenerate cases go to MPFR, an orthographic matrix's to a few double operations). The
// cost of each is estimated from the thread CPU time of grading its first `pilot` generated
// cases. Only the order changes: each tally depends on its implementation alone.
std::vector<std::size_t> costliest_first(const std::vector<const implementation*>& chosen, const check_options& o,
                                         std::optional<input_class> class_filter, unsigned jobs) {
  constexpr std::size_t pilot = 32;
  std::vector<double> cost(chosen.size());
  for_each_slice(chosen.size(), jobs, 1, [&](std::size_t first, std::size_t end) {
    for (std::size_t i = first; i < end; ++i) {
      const implementation& impl = *chosen[i];
      case_stream stream(impl.op, impl.type, o.seed, class_filter, impl.conv);
      const std::vector<test_case> cases = stream.next(pilot);
      const double start = thread_seconds();
      run_and_grade_in_parallel(impl, cases, 1, oracle_mode::filtered, nullptr);
      cost[i] = thread_seconds() - start;
    }
  });
  std::vector<std::size_t> order(chosen.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  return order;
}

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
void write_svg(const std::string& path, const std::vector<impl_tally>& runs) {
  const double W = 960, left = 70, right = 250, top = 40, bottom = 60;
  const double H = std::max(560.0, top + 14.0 * static_cast<double>(runs.size()) + 30);  // room for the legend
  double xmin = 0, xmax = 0;
  std::vector<std::vector<html_point>> points;
  for (const auto& r : runs) {
    points.push_back(r.plot.points());
    for (const auto& p : points.back())
      if (std::isfinite(p.closeness)) {
        xmin = std::min(xmin, p.closeness);
        xmax = std::max(xmax, p.closeness);
      }
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
    // Cases in one cell of the plot's grid are drawn once, darker the more there are.
    for (const auto& p : points[i]) {
      if (std::isnan(p.closeness)) continue;
      const double x = std::isfinite(p.closeness) ? p.closeness : xmin + 4;
      const double y = p.nonfinite ? 66 : std::min(p.bits, 64.0);
      const double opacity = std::min(1.0, 0.55 + 0.13 * std::log2(static_cast<double>(p.count)));
      f.circle(sx(x), sy(y), 1.6, colour, opacity);
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


// What a check report shows of one implementation, from its grades or merged from shards.
struct check_result {
  const implementation* impl = nullptr;
  grade_summary summary;                                      // 3 worst cases
  std::vector<std::pair<input_class, grade_summary>> by_class;  // 1 worst case each
  std::vector<std::string> case_verdicts;                     // in the order of the run's cases
  case_lookup lookup;                                         // the cases the summaries single out
};

struct check_report {
  std::vector<check_result> results;
  oracle_counters counters;
  double grading_seconds = 0;  ///< running and grading, this process only (0 after a merge)
  std::size_t graded = 0;      ///< cases graded in that time
  std::size_t given_cases = 0;  // cases of --input (all of them, not a shard's)
};

bool gates_failed(const check_options& o, const check_report& report, bool* ulps = nullptr, bool* verdicts = nullptr) {
  const gates gate{o.max_ulps, parse_fail_on(o.fail_on)};
  bool ulps_failed = false, verdict_failed = false;
  for (const auto& x : report.results) {
    ulps_failed = ulps_failed || gate.ulps_exceeded(x.summary);
    verdict_failed = verdict_failed || gate.verdict_reached(x.summary);
  }
  if (ulps) *ulps = ulps_failed;
  if (verdicts) *verdicts = verdict_failed;
  return ulps_failed || verdict_failed;
}

nlohmann::json check_json(const check_options& o, const check_report& report) {
  const gates gate{o.max_ulps, parse_fail_on(o.fail_on)};
  nlohmann::json doc{{"seed", o.seed}, {"cases_per_impl", o.cases}, {"results", nlohmann::json::array()}};
  for (const auto& x : report.results) {
    const implementation* impl = x.impl;
    auto conv_of = [impl](std::uint64_t) -> const conventions& { return impl->conv; };
    nlohmann::json j = summary_json(x.summary, x.lookup, conv_of);
    j["impl"] = impl->name;
    j["op"] = std::string(to_string(impl->op));
    j["type"] = std::string(to_string(impl->type));
    j["origin"] = impl->origin;
    j["conventions"] = conventions_json(impl->conv);
    nlohmann::json by_class = nlohmann::json::object();
    for (const auto& [cls, s] : x.by_class) {
      nlohmann::json c = summary_json(s, x.lookup, conv_of);
      c.erase("examples");
      by_class[std::string(to_string(cls))] = c;
    }
    j["by_class"] = by_class;
    j["case_verdicts"] = x.case_verdicts;  // by case id
    doc["results"].push_back(j);
  }
  doc["oracle"] = {{"decided_by_intervals", report.counters.decided_by_intervals},
                   {"fell_back_to_rationals", report.counters.fell_back_to_rationals}};
  if (o.max_ulps) doc["max_ulps_threshold"] = *o.max_ulps;
  if (gate.fail_on) doc["fail_on"] = std::string(to_string(*gate.fail_on));
  doc["exceeded"] = gates_failed(o, report);
  return doc;
}

// Prints the report (text, or JSON with --json) and returns the exit code.
int print_check_report(const check_options& o, const check_report& report) {
  const gates gate{o.max_ulps, parse_fail_on(o.fail_on)};
  bool ulps_failed = false, verdict_failed = false;
  const bool failed = gates_failed(o, report, &ulps_failed, &verdict_failed);
  if (o.json) {
    std::cout << check_json(o, report).dump(2) << '\n';
    return failed ? 1 : 0;
  }
  std::vector<verdict_row> rows;
  for (const auto& x : report.results) rows.push_back({x.impl->name, x.summary});
  const report_style style{o.wide, 100};
  const std::size_t n = report.results.size();
  std::cout << "Graded " << n << " implementation" << (n == 1 ? "" : "s") << ", "
            << (o.input.empty() ? std::to_string(o.cases) + " cases each (seed " + std::to_string(o.seed) + ")"
                                : std::to_string(report.given_cases) + " cases of " + o.input)
            << ", against the exact rational answer.\n"
            << "A case's verdict is that of its worst output, an implementation's that of its worst case\n"
            << "(docs/verdicts.md); the table counts cases. Verdicts, best first: exact, faithful (1 ulp),\n"
            << "stable (the problem's conditioning), unstable (the formula loses accuracy), range (over- or\n"
            << "underflow), wrong, nonfinite, garbage.\n\n";
  print_verdict_table(std::cout, rows, style);
  bool first = true;
  for (const auto& x : report.results) {
    if (x.summary.worst_verdict <= verdict::faithful && !x.summary.misclassified) continue;
    if (first) std::cout << "\nWorst cases (bit-exact; each command prints the exact answer):\n";
    first = false;
    const implementation* impl = x.impl;
    auto conv_of = [impl](std::uint64_t) -> const conventions& { return impl->conv; };
    print_examples(std::cout, impl->name, x.summary, x.lookup, conv_of, style);
  }
  std::cout << "\nOracle: " << report.counters.decided_by_intervals << " cases decided by interval arithmetic, "
            << report.counters.fell_back_to_rationals << " by exact rationals";
  // The rate is a measurement of this run (a merge of shards has none): reports compared byte
  // for byte mask it.
  if (report.grading_seconds > 0)
    std::cout << "; graded at " << throughput_text(static_cast<double>(report.graded), report.grading_seconds);
  std::cout << ".\n";
  if (!o.svg.empty()) std::cout << "Plot written to " << o.svg << '\n';
  if (o.max_ulps)
    std::cout << (ulps_failed ? "FAIL" : "PASS") << ": --max-ulps " << *o.max_ulps
              << (ulps_failed ? " exceeded, or NaN/Inf, garbage or misclassified cases\n" : " held\n");
  if (gate.fail_on)
    std::cout << (verdict_failed ? "FAIL" : "PASS") << ": --fail-on " << to_string(*gate.fail_on)
              << (verdict_failed ? ": some case is at or past it\n" : ": every case is better\n");
  std::cout << "\nNext: docs/tutorial-read-report.md reads this report line by line;\n"
               "docs/tutorial-grade-cpp.md grades your own code.\n";
  return failed ? 1 : 0;
}

// What merge needs of one implementation's shard besides its report: the statistics of each
// summary, where each case stood in the whole run, and the singled-out cases with the
// implementation's outputs for them.
nlohmann::json shard_payload(const impl_tally& r, const check_result& x) {
  nlohmann::json j;
  j["summary"] = mergeable_json(r.whole ? *r.whole : summarize_mergeable({}, 3));
  nlohmann::json by_class = nlohmann::json::object();
  std::map<std::uint64_t, const case_grade*> singled;
  for (const auto& g : singled_out_cases(x.summary)) singled[g.id] = nullptr;
  for (input_class cls : all_input_classes()) {
    const auto it = r.by_class.find(cls);
    if (it == r.by_class.end() || !it->second) continue;
    by_class[std::string(to_string(cls))] = mergeable_json(*it->second);
    for (const auto& g : singled_out_cases(it->second->summary)) singled[g.id] = nullptr;
  }
  j["by_class"] = by_class;
  j["positions"] = r.positions;
  nlohmann::json candidates = nlohmann::json::array();
  std::vector<double> out(signature(r.impl->op).output_count);
  for (const auto& [id, unused] : singled) {
    const test_case& c = r.by_id(id);
    std::fill(out.begin(), out.end(), 0.0);  // as run_and_grade
    r.impl->run(c.inputs.data(), out.data());
    candidates.push_back(candidate_json({c, out}));
  }
  j["candidates"] = candidates;
  return j;
}

html_page check_page(const check_options& o, const check_report& report, const std::vector<impl_tally>& runs) {
  html_page page;
  page.title = "shadowproof check";
  page.command = o.command_line;
  const std::size_t n = report.results.size();
  page.summary.push_back(
      "Graded " + std::to_string(n) + " implementation" + (n == 1 ? "" : "s") + ", " +
      (o.input.empty() ? std::to_string(o.cases) + " cases each (seed " + std::to_string(o.seed) + ")"
                       : std::to_string(report.given_cases) + " cases of " + o.input) +
      ", against the exact rational answer. A case's verdict is that of its worst output, an implementation's "
      "that of its worst case (docs/verdicts.md).");
  page.summary.push_back("Oracle: " + std::to_string(report.counters.decided_by_intervals) +
                         " cases decided by interval arithmetic, " +
                         std::to_string(report.counters.fell_back_to_rationals) + " by exact rationals.");
  const gates gate{o.max_ulps, parse_fail_on(o.fail_on)};
  for (std::size_t i = 0; i < n; ++i) {
    const auto& x = report.results[i];
    graded_run g;
    g.name = x.impl->name;
    g.origin = x.impl->origin;
    g.op = x.impl->op;
    g.type = x.impl->type;
    g.conv = &x.impl->conv;
    g.summary = &x.summary;
    g.plot = &runs[i].plot;
    g.lookup = x.lookup;
    g.failed = gate.ulps_exceeded(x.summary) || gate.verdict_reached(x.summary);
    page.sections.push_back(graded_section(g));
  }
  return page;
}

// The implementations `--impl` names: 'all', or names separated by commas, each known. They are
// graded in the built-in list's order, each once, whatever order the names come in: a report
// depends on the set chosen only.
std::vector<const implementation*> chosen_implementations(const std::string& names,
                                                          const std::optional<operation>& op_filter,
                                                          const std::string& op_name) {
  const auto& all = builtin_implementations();
  std::vector<std::string> wanted;
  if (names != "all") {
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = names.find(',', start);
      wanted.push_back(names.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    for (const std::string& name : wanted) {
      const bool known = std::any_of(all.begin(), all.end(), [&](const implementation& i) { return i.name == name; });
      if (!known) throw error(errc::verify_unknown_impl, "no implementation named '" + name + "' (see --list)");
    }
  }
  const auto is_wanted = [&](const implementation& impl) {
    return names == "all" || std::find(wanted.begin(), wanted.end(), impl.name) != wanted.end();
  };
  std::vector<const implementation*> chosen;
  for (const auto& impl : all)
    if (is_wanted(impl) && (!op_filter || impl.op == *op_filter)) chosen.push_back(&impl);
  if (chosen.empty())
    throw error(errc::verify_unknown_impl, (wanted.size() == 1 ? "implementation '" + names + "' does not"
                                                               : "none of the implementations '" + names + "'") +
                                           " compute --op " + op_name);
  return chosen;
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
  (void)parse_fail_on(o.fail_on);  // a bad --fail-on fails before any grading
  std::vector<const implementation*> chosen = chosen_implementations(o.impl, op_filter, o.op);

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
  const shard part = o.shard_spec.empty() ? shard{} : parse_shard(o.shard_spec);
  kept_per_case keep;
  keep.verdicts = o.json;
  keep.positions = o.json && !o.shard_spec.empty();
  keep.plot = !o.svg.empty() || !o.html.empty();
  keep.class_summaries = o.json;
  const unsigned jobs = o.jobs == 0 ? default_jobs() : o.jobs;
  std::vector<impl_tally> runs;
  // Generating, running, grading and summarising, wall-clock.
  const auto start = std::chrono::steady_clock::now();
  {
    progress_bar bar(chosen.size());
    std::mutex bar_lock;
    // Many implementations: each thread takes whole implementations in turn, generating,
    // grading and summarising its cases alone, so no thread ever waits for another. Few: the
    // threads share each implementation's chunks. Each tally depends on its implementation
    // alone, so the report is the same either way.
    const bool across = jobs > 1 && chosen.size() >= 4 * static_cast<std::size_t>(jobs);
    runs.resize(chosen.size());
    // Long runs take the costliest implementations first; a pilot of 32 cases each costs under
    // 1% of a run of 4,096 cases per implementation.
    std::vector<std::size_t> order(chosen.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    if (across && given.empty() && o.cases >= 4096) order = costliest_first(chosen, o, class_filter, jobs);
    for_each_slice(chosen.size(), across ? jobs : 1, 1, [&](std::size_t first, std::size_t end) {
      for (std::size_t k = first; k < end; ++k) {
        const std::size_t i = order[k];
        runs[i] = tally_implementation(*chosen[i], o, given, class_filter, part, across ? 1 : jobs, keep);
        const std::lock_guard<std::mutex> guard(bar_lock);
        bar.step(chosen[i]->name);
      }
    });
  }

  check_report report;
  for (const auto& r : runs) {
    report.counters.decided_by_intervals += r.counters.decided_by_intervals;
    report.counters.fell_back_to_rationals += r.counters.fell_back_to_rationals;
    report.graded += r.graded;
  }
  report.grading_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  report.given_cases = given.size();
  for (const auto& r : runs) {
    check_result x;
    x.impl = r.impl;
    if (r.whole) x.summary = r.whole->summary;
    else x.summary = summarize({}, 3);
    for (input_class cls : all_input_classes()) {
      const auto it = r.by_class.find(cls);
      if (it != r.by_class.end() && it->second) x.by_class.emplace_back(cls, it->second->summary);
    }
    for (verdict v : r.verdicts) x.case_verdicts.push_back(std::string(to_string(v)));
    const impl_tally* run = &r;
    x.lookup = [run](std::uint64_t id) -> const test_case& { return run->by_id(id); };
    report.results.push_back(std::move(x));
  }
  if (!o.svg.empty()) write_svg(o.svg, runs);
  if (!o.html.empty()) write_html(o.html, check_page(o, report, runs));
  if (!o.shard_spec.empty() && o.json) {
    // A shard's report: the run's JSON, the shard block, and what merge needs besides.
    nlohmann::json doc = check_json(o, report);
    doc["shard"] = shard_json(part, run_json(o));
    for (std::size_t i = 0; i < runs.size(); ++i) {
      doc["results"][i]["merge"] = shard_payload(runs[i], report.results[i]);
      doc["results"][i]["merge"]["given_cases"] = given.size();
    }
    std::cout << doc.dump(2) << '\n';
    return gates_failed(o, report) ? 1 : 0;
  }
  return print_check_report(o, report);
}

const command_registration check_registration{command{
    "check", "grade built-in float implementations (seed formulas, GLM, Eigen, Irrlicht, Ogre) against the exact oracle",
    [](CLI::App& app, const global_options& globals) {
      auto o = std::make_shared<check_options>();
      app.add_option("--impl", o->impl, "implementation names separated by commas, or 'all' (see --list)");
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
      add_jobs_option(app, o->jobs);
      app.add_flag("--list", o->list, "print the registered implementation names, one per line");
      app.add_option("--shard", o->shard_spec, "grade only shard i of N (the cases whose id mod N is i); merge the "
                                               "--json reports with `shadowproof merge`");
      app.add_option("--html", o->html, "write a self-contained HTML report to this file");
      o->command_line = globals.command_line;
      return [o] { return run_check(*o); };
    }}};


}  // namespace

int merge_check_shards(const std::vector<shard_report>& shards, const merge_options& m) {
  const nlohmann::json& run = shards.front().run;
  check_options o;
  try {
    o.impl = run.at("impl").get<std::string>();
    o.op = run.at("op").get<std::string>();
    o.cls = run.at("class").get<std::string>();
    o.cases = run.at("cases").get<std::size_t>();
    o.seed = run.at("seed").get<std::uint64_t>();
    o.input = run.at("input").get<std::string>();
    if (!run.at("max_ulps").is_null()) o.max_ulps = run.at("max_ulps").get<std::uint64_t>();
    o.fail_on = run.at("fail_on").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw error(errc::merge_input, shards.front().path + ": the run of the shard is malformed: " + e.what());
  }
  o.json = m.json;
  o.wide = m.wide;
  check_report report;
  // The cases singled out, kept for the lookups of the merged report.
  auto store = std::make_shared<std::vector<std::map<std::uint64_t, test_case>>>();
  try {
    for (const auto& s : shards) {
      const auto& oracle = member(s, s.doc, "oracle");
      report.counters.decided_by_intervals += oracle.at("decided_by_intervals").get<std::uint64_t>();
      report.counters.fell_back_to_rationals += oracle.at("fell_back_to_rationals").get<std::uint64_t>();
    }
    const std::size_t n = member(shards.front(), shards.front().doc, "results").size();
    store->resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      check_result x;
      x.impl = &find_builtin_implementation(shards.front().doc["results"][i].at("impl").get<std::string>());
      std::vector<mergeable_summary> parts;
      std::map<std::string, std::vector<mergeable_summary>> class_parts;
      std::vector<case_grade> candidates;
      std::vector<std::pair<std::size_t, std::string>> verdicts;
      for (const auto& s : shards) {
        const auto& results = member(s, s.doc, "results");
        if (results.size() != n || results[i].at("impl") != x.impl->name)
          throw error(errc::merge_input, s.path + ": its results are not those of " + shards.front().path);
        const auto& payload = member(s, results[i], "merge");
        parts.push_back(mergeable_from_json(s, payload.at("summary")));
        for (const auto& [cls, j] : payload.at("by_class").items()) class_parts[cls].push_back(mergeable_from_json(s, j));
        for (const auto& c : payload.at("candidates")) {
          const candidate k = candidate_from_json(s, c, x.impl->op, x.impl->type);
          candidates.push_back(grade_case(k.c, x.impl->conv, k.outputs.data()));
          (*store)[i][k.c.id] = k.c;
        }
        const auto positions = payload.at("positions").get<std::vector<std::size_t>>();
        const auto& each = results[i].at("case_verdicts");
        if (positions.size() != each.size()) throw error(errc::merge_input, s.path + ": case_verdicts and positions differ in length");
        for (std::size_t k = 0; k < positions.size(); ++k) verdicts.emplace_back(positions[k], each[k].get<std::string>());
        report.given_cases = payload.at("given_cases").get<std::size_t>();
      }
      x.summary = merge_summaries(parts, candidates, 3).summary;
      for (input_class cls : all_input_classes()) {
        const auto it = class_parts.find(std::string(to_string(cls)));
        if (it == class_parts.end()) continue;
        std::vector<case_grade> of_class;
        for (const auto& g : candidates)
          if (g.cls == cls) of_class.push_back(g);
        x.by_class.emplace_back(cls, merge_summaries(it->second, of_class, 1).summary);
      }
      std::sort(verdicts.begin(), verdicts.end());
      for (auto& [position, v] : verdicts) x.case_verdicts.push_back(std::move(v));
      x.lookup = [store, i](std::uint64_t id) -> const test_case& { return (*store)[i].at(id); };
      report.results.push_back(std::move(x));
    }
  } catch (const nlohmann::json::exception& e) {
    throw error(errc::merge_input, "a check shard report is malformed: " + std::string(e.what()));
  }
  return print_check_report(o, report);
}

}  // namespace shadowproof::cli
