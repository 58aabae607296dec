// shadowproof fuzz: differential fuzzing of a registered implementation against the exact
// oracle, with every failure shrunk to a minimal reproducer.
#include <unistd.h>

#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "command.h"
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
};


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

int run_fuzz_command(const fuzz_options& o) {
  const implementation& impl = find_builtin_implementation(o.impl);
  fuzz_settings s;
  if (o.seconds > 0) s.seconds = o.seconds;
  if (o.cases > 0) s.cases = o.cases;
  if (!s.seconds && !s.cases) throw error(errc::fuzz_no_budget, "give --seconds S or --cases N");
  s.seed = o.seed;
  s.ulps_threshold = o.max_ulps;
  s.metamorphic = !o.no_metamorphic;
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
  if (o.json) std::cout << report_json(r).dump(2) << "\n";
  else print_text(std::cout, r, impl);
  return r.failures.empty() ? 0 : 1;
}

const command_registration registration{command{
    "fuzz", "differential fuzzing of an implementation against the exact oracle, failures shrunk",
    [](CLI::App& app, const global_options&) -> std::function<int()> {
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
      return [o] { return run_fuzz_command(*o); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
