// shadowproof fuzz: differential fuzzing of a registered implementation against the exact
// oracle, with every failure shrunk to a minimal reproducer.
#include <unistd.h>

#include <iostream>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "command.h"
#include "jobs_option.h"
#include "html_report.h"
#include "shard_report.h"
#include "verify_print.h"
#include "shadowproof/fuzz/differential.h"
#include "shadowproof/core/error.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/impls/builtin.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/protocol.h"
#include "shadowproof/core/io.h"
#include "shadowproof/core/number.h"
#include "shadowproof/core/ulp.h"

namespace shadowproof::cli {
namespace {

struct fuzz_options {
  std::string impl;
  double seconds = 0;
  std::size_t cases = 0;
  std::uint64_t seed = 1;
  std::uint64_t max_ulps = 1u << 20;
  std::string out_dir;
  bool json = false;
  bool no_metamorphic = false;
  unsigned jobs = 0;  // 0: default_jobs()
  std::string shard_spec;
  std::string html;
  std::string command_line;
};

// What makes two fuzz reports shards of one run.
nlohmann::json run_json(const fuzz_options& o) {
  return {{"command", "fuzz"}, {"impl", o.impl}, {"seed", o.seed}, {"cases", o.cases}, {"seconds", o.seconds},
          {"max_ulps", o.max_ulps}, {"metamorphic", !o.no_metamorphic}};
}


nlohmann::json case_object(const test_case& c) { return nlohmann::json::parse(case_json_line(c)); }

nlohmann::json report_json(const fuzz_report& r) {
  nlohmann::json doc;
  doc["impl"] = r.impl;
  doc["cases"] = r.cases;
  doc["failing_cases"] = r.failing_cases;
  doc["metamorphic_max_ulps"] = r.metamorphic_max_ulps;
  doc["failures"] = nlohmann::json::array();
  for (const auto& f : r.failures) {
    nlohmann::json j{{"kind", std::string(to_string(f.kind))},
                     {"family", f.family},
                     {"bits", f.bits},
                     {"original", case_object(f.original)},
                     {"shrunk", case_object(f.shrunk)},
                     {"bits_before", f.bits_before},
                     {"bits_after", f.bits_after}};
    if (!f.relation.empty()) j["relation"] = f.relation;
    if (f.kind == failure_kind::misclassified && f.original_grade.exact_class && f.original_grade.got_class) {
      j["exact_class"] = std::string(to_string(*f.original_grade.exact_class));
      j["got_class"] = std::string(to_string(*f.original_grade.got_class));
    }
    doc["failures"].push_back(j);
  }
  return doc;
}

// One input number as a reader takes it in at a glance: a short decimal when it is exactly the
// number (3, -0.5, 6.0000005), otherwise the bit-exact hex float (0x1p-149).
std::string readable_number(double x) {
  std::ostringstream decimal;
  decimal.precision(17);
  decimal << x;
  const std::string text = decimal.str();
  if (text.size() <= 12 && text.find('e') == std::string::npos && parse_number(text) == exact_value(x)) return text;
  return hex_string(x);
}

// "plane (0, 4, 0x1p-22, 8)  light (0, -2, -1, 1)  point (0, 0, 0)": the groups of the case's
// signature with their values.
std::string readable_inputs(const test_case& c) {
  std::string out;
  std::size_t k = 0;
  for (const input_group& g : signature(c.op).inputs) {
    if (!out.empty()) out += "  ";
    out += g.name + " (";
    for (std::size_t i = 0; i < g.size; ++i) out += (i ? ", " : "") + readable_number(c.inputs[k++]);
    out += ")";
  }
  return out;
}

template <class Enum, class Names>
std::optional<Enum> enum_from_string(const std::string& name, const Names& all) {
  for (Enum e : all)
    if (to_string(e) == name) return e;
  return std::nullopt;
}

// A case object of report_json read back: parse_case_line reads the exact decimals, which do
// not tell −0 from +0; the hex strings beside them do.
test_case case_from_json(const nlohmann::json& j, std::size_t line) {
  test_case c = parse_case_line(j.dump(), line);
  std::size_t k = 0;
  for (const auto& group : signature(c.op).inputs) {
    const auto it = j.find(group.name);
    for (std::size_t i = 0; i < group.size; ++i, ++k)
      if (it != j.end() && it->is_array() && i < it->size() && (*it)[i].is_string() &&
          (*it)[i].get<std::string>() == "-0x0p+0")
        c.inputs[k] = -0.0;
  }
  return c;
}

// A report printed by report_json, read back exactly (cases as case lines, doubles as JSON
// numbers, which nlohmann prints and reads back bit for bit).
fuzz_report report_from_json(const shard_report& shard) {
  const nlohmann::json& doc = shard.doc;
  auto bad = [&](const std::string& what) { return error(errc::merge_input, shard.path + ": " + what); };
  try {
    fuzz_report r;
    r.impl = member(shard, doc, "impl").get<std::string>();
    r.cases = member(shard, doc, "cases").get<std::size_t>();
    r.failing_cases = member(shard, doc, "failing_cases").get<std::map<std::string, std::size_t>>();
    r.metamorphic_max_ulps = member(shard, doc, "metamorphic_max_ulps").get<std::map<std::string, std::uint64_t>>();
    std::size_t line = 0;
    for (const auto& j : member(shard, doc, "failures")) {
      fuzz_failure f;
      const auto kind = enum_from_string<failure_kind>(j.at("kind").get<std::string>(),
          std::initializer_list<failure_kind>{failure_kind::nonfinite, failure_kind::garbage,
                                              failure_kind::misclassified, failure_kind::ulps, failure_kind::metamorphic});
      if (!kind) throw bad("unknown failure kind " + j.at("kind").dump());
      f.kind = *kind;
      f.family = j.at("family").get<std::string>();
      f.relation = j.value("relation", std::string());
      f.bits = j.at("bits").get<double>();
      f.bits_before = j.at("bits_before").get<std::size_t>();
      f.bits_after = j.at("bits_after").get<std::size_t>();
      f.original = case_from_json(j.at("original"), ++line);
      f.shrunk = case_from_json(j.at("shrunk"), line);
      if (j.contains("exact_class")) {
        f.original_grade.exact_class = enum_from_string<point_class>(j["exact_class"].get<std::string>(),
            std::initializer_list<point_class>{point_class::on_receiver, point_class::shadow, point_class::behind_receiver,
                                               point_class::beyond_light, point_class::at_infinity, point_class::at_light,
                                               point_class::light_on_plane, point_class::light_parallel,
                                               point_class::line_in_plane});
        f.original_grade.got_class = enum_from_string<image_class>(j.at("got_class").get<std::string>(),
            std::initializer_list<image_class>{image_class::on_receiver, image_class::shadow, image_class::behind_receiver,
                                               image_class::beyond_light, image_class::nonfinite, image_class::other});
        if (!f.original_grade.exact_class || !f.original_grade.got_class) throw bad("unknown point or image class");
      }
      r.failures.push_back(std::move(f));
    }
    return r;
  } catch (const nlohmann::json::exception& e) {
    throw bad(std::string("not a fuzz report: ") + e.what());
  }
}

void print_text(std::ostream& out, const fuzz_report& r, const implementation& impl) {
  out << "fuzz " << r.impl << ": " << r.cases << " cases";
  for (const auto& [kind, n] : r.failing_cases) out << ", " << n << " " << kind;
  out << "\n";
  for (const auto& [relation, ulps] : r.metamorphic_max_ulps)
    out << "  metamorphic " << relation << ": up to "
        << (ulps == UINT64_MAX ? std::string("non-finite vs finite") : std::to_string(ulps) + " ulps") << "\n";
  for (const auto& f : r.failures) {
    std::string what = f.relation.empty() ? "" : " (" + f.relation + ")";
    if (f.kind == failure_kind::misclassified && f.original_grade.exact_class && f.original_grade.got_class)
      what = " (exact " + std::string(to_string(*f.original_grade.exact_class)) + ", float image " +
             std::string(to_string(*f.original_grade.got_class)) + ")";
    std::ostringstream bits;
    bits.precision(3);
    bits << f.bits;
    out << "\n" << to_string(f.kind) << what << " on " << f.family << ", " << bits.str()
        << " bits of error; shrunk from " << f.bits_before << " to " << f.bits_after << " bits\n";
    out << "  original: " << readable_inputs(f.original) << "\n";
    out << "  shrunk:   " << readable_inputs(f.shrunk) << "\n";
    out << "  exact:    " << reproducer_command(f.shrunk, impl.conv) << "\n";
  }
  if (!r.failures.empty())
    out << "\nEach shrunk case, as a case line and a Catch2 test: --out DIR (docs/tutorial-fuzz.md).\n";
}

std::string bits_text(double bits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << bits;
  return s.str();
}

html_page fuzz_page(const fuzz_options& o, const implementation& impl, const fuzz_report& r,
                    std::vector<html_point> points) {
  html_page page;
  page.title = "shadowproof fuzz: " + impl.name;
  page.command = o.command_line;
  page.summary.push_back(std::to_string(r.cases) + " cases from seed " + std::to_string(o.seed) +
                         "; an output " + std::to_string(o.max_ulps) +
                         " or more ulps off the correctly rounded exact value fails, and so does a NaN/Inf "
                         "where the answer exists, a finite number where it does not, a shadow on the wrong "
                         "side, or a metamorphic relation broken by that many ulps.");
  html_section s;
  s.name = impl.name;
  s.verdict = r.failures.empty() ? "pass" : "fail";
  s.counts_label = "failing cases by kind";
  s.failed = !r.failures.empty();
  s.facts = {{"cases", std::to_string(r.cases)}, {"operation", std::string(to_string(impl.op))},
             {"type", std::string(to_string(impl.type))}, {"distinct failures", std::to_string(r.failures.size())}};
  for (const auto& [kind, n] : r.failing_cases) s.counts.emplace_back(kind, n);
  for (const auto& [relation, ulps] : r.metamorphic_max_ulps)
    s.facts.emplace_back("metamorphic " + relation,
                         ulps == UINT64_MAX ? std::string("non-finite vs finite") : std::to_string(ulps) + " ulps");
  const nlohmann::json declared = conventions_json(impl.conv);  // items() refers to it
  for (const auto& [key, value] : declared.items())
    s.conventions.emplace_back(key, value.is_string() ? value.get<std::string>() : value.dump());
  s.points = std::move(points);
  for (const auto& f : r.failures) {
    html_case c;
    c.title = std::string(to_string(f.kind)) + (f.relation.empty() ? "" : " (" + f.relation + ")") + " on " +
              f.family + ": case " + std::to_string(f.original.id) + ", " + bits_text(f.bits) +
              " bits of error; inputs shrunk from " + std::to_string(f.bits_before) + " to " +
              std::to_string(f.bits_after) + " bits";
    c.details = {"original: " + case_json_line(f.original), "shrunk:   " + case_json_line(f.shrunk)};
    c.reproducer = reproducer_command(f.shrunk, impl.conv);
    s.worst.push_back(std::move(c));
  }
  page.sections.push_back(std::move(s));
  return page;
}

int run_fuzz_command(const fuzz_options& o) {
  const implementation& impl = find_builtin_implementation(o.impl);
  fuzz_settings s;
  if (o.seconds > 0) s.seconds = o.seconds;
  if (o.cases > 0) s.cases = o.cases;
  if (!s.seconds && !s.cases) throw error(errc::fuzz_no_budget, "give --seconds S or --cases N");
  s.seed = o.seed;
  s.ulps_threshold = o.max_ulps;
  s.metamorphic = !o.no_metamorphic;
  s.jobs = o.jobs;
  if (!o.shard_spec.empty()) s.part = parse_shard(o.shard_spec);
  point_cloud points;  // bounded, however many cases run
  if (!o.html.empty())
    s.on_case = [&](const test_case& c, const case_grade& g) {
      points.add(closeness_to_degeneracy(c), g.max_bits, g.nonfinite > 0 || g.garbage > 0);
    };
  if (!o.out_dir.empty()) {  // fail before a long run, not after it
    std::error_code ec;
    std::filesystem::create_directories(o.out_dir, ec);
    if (ec) throw error(errc::io_cannot_write, "cannot create the directory " + o.out_dir + ": " + ec.message());
  }
  const bool terminal = isatty(STDERR_FILENO) == 1;
  const fuzz_report r = run_fuzz(impl, s, [&](std::size_t cases, std::size_t failures) {
    std::cerr << (terminal ? "\r" : "") << "fuzz " << impl.name << ": " << cases << " cases, " << failures
              << " failures" << (terminal ? "\x1b[K" : "\n") << std::flush;
  });
  if (terminal) std::cerr << "\n";

  if (!o.out_dir.empty()) {
    const std::filesystem::path dir = o.out_dir;
    for (std::size_t k = 0; k < r.failures.size(); ++k) {
      const auto& f = r.failures[k];
      const std::string stem = impl.name + "-" + std::to_string(k) + "-" + std::string(to_string(f.kind));
      write_file_atomically(dir / (stem + ".jsonl"), case_json_line(f.shrunk) + "\n");
      write_file_atomically(dir / (stem + ".cpp"), catch2_regression_test(impl, f));
    }
    write_file_atomically(dir / "report.json", report_json(r).dump(2) + "\n");
  }
  if (!o.html.empty()) write_html(o.html, fuzz_page(o, impl, r, points.points()));
  if (o.json) {
    nlohmann::json doc = report_json(r);
    if (!o.shard_spec.empty()) doc["shard"] = shard_json(s.part, run_json(o));
    std::cout << doc.dump(2) << "\n";
  } else {
    print_text(std::cout, r, impl);
  }
  return r.failures.empty() ? 0 : 1;
}

const command_registration fuzz_registration{command{
    "fuzz", "differential fuzzing of an implementation against the exact oracle, failures shrunk",
    [](CLI::App& app, const global_options& globals) -> std::function<int()> {
      auto o = std::make_shared<fuzz_options>();
      app.add_option("--impl", o->impl, "implementation name (shadowproof check --list)")->required();
      auto seconds = app.add_option("--seconds", o->seconds, "run for this many seconds");
      auto cases = app.add_option("--cases", o->cases, "run this many cases (output is then byte-identical per seed)");
      seconds->excludes(cases);
      app.add_option("--seed", o->seed, "seed of the case generator")->capture_default_str();
      app.add_option("--max-ulps", o->max_ulps, "an output at least this many ulps off fails")->capture_default_str();
      app.add_option("--out", o->out_dir, "write each shrunk case (.jsonl) and Catch2 test (.cpp) here");
      app.add_flag("--json", o->json, "print the report as JSON");
      app.add_flag("--no-metamorphic", o->no_metamorphic, "skip the metamorphic relations");
      add_jobs_option(app, o->jobs);
      app.add_option("--shard", o->shard_spec, "run only shard i of N (cases n with n mod N = i); merge the "
                                               "--json reports with `shadowproof merge`");
      app.add_option("--html", o->html, "write a self-contained HTML report to this file");
      o->command_line = globals.command_line;
      return [o] { return run_fuzz_command(*o); };
    }}};

}  // namespace

int merge_fuzz_shards(const std::vector<shard_report>& shards, const merge_options& o) {
  std::vector<fuzz_report> reports;
  for (const auto& s : shards) reports.push_back(report_from_json(s));
  const implementation& impl = find_builtin_implementation(reports.front().impl);
  const fuzz_report r = merge_fuzz_reports(reports, impl.op);
  if (o.json) std::cout << report_json(r).dump(2) << "\n";
  else print_text(std::cout, r, find_builtin_implementation(r.impl));
  return r.failures.empty() ? 0 : 1;
}

namespace {

}  // namespace
}  // namespace shadowproof::cli
