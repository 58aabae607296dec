// shadowproof grade: grades a program's outputs (JSON lines) against the exact answers for the
// cases it was given (JSON lines from `shadowproof cases`).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>

#include "command.h"
#include "shadowproof/core/error.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/protocol.h"
#include "shadowproof/verify/report.h"
#include "verify_print.h"

namespace shadowproof::cli {
namespace {

struct grade_options {
  std::string cases_path, outputs_path;
  std::string name;
  std::string layout = "row-major";
  std::string vectors = "column";
  std::string light = "towards-light";
  std::string depth = "gl";
  std::string sentinel = "none";
  bool homogeneous = false;
  bool clamps = false;
  bool symmetric = false;
  bool json = false;
  bool wide = false;
  std::optional<std::uint64_t> max_ulps;
  std::string fail_on;
  std::vector<std::string> conventions;  // name=value
};

std::vector<std::string> read_lines(const std::string& path, const char* what) {
  std::ifstream f(path);
  if (!f) throw error(errc::grade_file, std::string("cannot read the ") + what + " file '" + path + "'");
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(f, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  return lines;
}

// "ids 3, 7 and 12" / "ids 3, 7, 12, 15, … and 40 more".
std::string id_list(const std::vector<std::uint64_t>& ids) {
  std::string s = ids.size() == 1 ? "id " : "ids ";
  const std::size_t shown = std::min<std::size_t>(ids.size(), 10);
  for (std::size_t i = 0; i < shown; ++i) {
    if (i) s += (i + 1 == shown && shown == ids.size()) ? " and " : ", ";
    s += std::to_string(ids[i]);
  }
  if (shown < ids.size()) s += " and " + std::to_string(ids.size() - shown) + " more";
  return s;
}

conventions conventions_of(const grade_options& o) {
  conventions conv;
  if (o.layout == "row-major") conv.storage = storage_order::row_major;
  else if (o.layout == "column-major") conv.storage = storage_order::column_major;
  else throw error(errc::grade_layout, "unknown --layout '" + o.layout + "'; expected row-major or column-major");
  if (o.vectors == "column") conv.vectors = vector_side::column;
  else if (o.vectors == "row") conv.vectors = vector_side::row;
  else throw error(errc::grade_vectors, "unknown --vectors '" + o.vectors + "'; expected column or row");
  if (o.light == "towards-light") conv.light = light_sign::towards_light;
  else if (o.light == "along-rays") conv.light = light_sign::along_rays;
  else throw error(errc::grade_light, "unknown --light '" + o.light + "'; expected towards-light or along-rays");
  const auto sentinel = sentinel_from_string(o.sentinel);
  if (!sentinel) throw error(errc::verify_sentinel, "unknown --sentinel '" + o.sentinel + "'; expected none, zero or identity");
  conv.sentinel = *sentinel;
  conv.homogeneous = o.homogeneous;
  conv.clamps_behind_receiver = o.clamps;
  conv.symmetric_view = o.symmetric;
  conv.depth = parse_depth_convention(o.depth);
  for (const auto& t : o.conventions) {
    const auto eq = t.find('=');
    if (eq == std::string::npos)
      throw error(errc::protocol_convention, "--convention '" + t + "' must read name=value, e.g. depth=d3d");
    set_convention(conv, t.substr(0, eq), t.substr(eq + 1));
  }
  return conv;
}

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

int run_grade(const grade_options& o) {
  const conventions conv = conventions_of(o);
  const std::optional<verdict> fail_on = parse_fail_on(o.fail_on);

  const auto case_lines = read_lines(o.cases_path, "cases");
  if (case_lines.empty()) throw error(errc::grade_empty, "the case file '" + o.cases_path + "' has no case");
  std::vector<test_case> cases;
  std::vector<conventions> case_conv;  // the command line's, overridden by the line's own
  std::map<std::uint64_t, std::size_t> index;
  for (std::size_t i = 0; i < case_lines.size(); ++i) {
    case_conv.push_back(conv);
    cases.push_back(parse_case_line(case_lines[i], i + 1, case_conv.back()));
    if (!index.emplace(cases.back().id, i).second)
      throw error(errc::grade_duplicate_id, o.cases_path + " line " + std::to_string(i + 1) + ": case id " +
                                            std::to_string(cases.back().id) + " appears twice");
    if (!sentinel_applies(cases.back().op, case_conv.back().sentinel))
      throw error(errc::verify_sentinel, "--sentinel " + std::string(to_string(case_conv.back().sentinel)) +
                                         " means nothing for " +
                                         std::string(to_string(cases.back().op)) + " outputs");
  }
  const auto output_lines = read_lines(o.outputs_path, "outputs");
  if (output_lines.empty())
    throw error(errc::grade_empty, "the outputs file '" + o.outputs_path + "' has no line: none of the " +
                                   std::to_string(cases.size()) + " cases was answered");
  std::vector<case_grade> grades;
  std::vector<bool> seen(cases.size(), false);
  oracle_counters counters;
  for (std::size_t i = 0; i < output_lines.size(); ++i) {
    // The id decides which case (and so which type and output count) the line belongs to.
    std::uint64_t id = 0;
    {
      const auto probe = nlohmann::json::parse(output_lines[i], nullptr, false);
      if (probe.is_discarded() || !probe.is_object() || !probe.contains("id") || !probe["id"].is_number_unsigned())
        throw error(errc::protocol_output, o.outputs_path + " line " + std::to_string(i + 1) +
                                           ": expected {\"id\": <case id>, \"output\": [...]}");
      id = probe["id"].get<std::uint64_t>();
    }
    const auto it = index.find(id);
    if (it == index.end())
      throw error(errc::grade_unknown_id, o.outputs_path + " line " + std::to_string(i + 1) + ": no case with id " +
                                          std::to_string(id) + " in " + o.cases_path);
    if (seen[it->second])
      throw error(errc::grade_duplicate_id, o.outputs_path + " line " + std::to_string(i + 1) + ": id " +
                                            std::to_string(id) + " graded twice");
    seen[it->second] = true;
    const test_case& c = cases[it->second];
    const conventions& cc = case_conv[it->second];
    const output_line out = parse_output_line(output_lines[i], i + 1, c, cc);
    grades.push_back(grade_case(c, cc, out.values.data(), oracle_mode::filtered, &counters));
  }
  std::vector<std::uint64_t> missing;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (!seen[i]) missing.push_back(cases[i].id);
  if (!missing.empty())
    throw error(errc::grade_missing_id, o.outputs_path + " answers " + std::to_string(grades.size()) + " of the " +
                                        std::to_string(cases.size()) + " cases; no output line for " + id_list(missing));

  const std::string name = o.name.empty() ? std::filesystem::path(o.outputs_path).stem().string() : o.name;
  auto lookup = [&](std::uint64_t id) -> const test_case& { return cases[index.at(id)]; };
  auto conv_of = [&](std::uint64_t id) -> const conventions& { return case_conv[index.at(id)]; };
  const grade_summary all = summarize(grades, 5);
  const bool ulps_failed = o.max_ulps && (all.max_ulps > *o.max_ulps || all.nonfinite > 0 || all.garbage > 0 ||
                                          all.misclassified > 0);
  const bool verdict_failed = fail_on && reaches(all, *fail_on);
  const bool failed = ulps_failed || verdict_failed;
  if (o.json) {
    nlohmann::json doc = summary_json(all, lookup, conv_of);
    doc["name"] = name;
    doc["conventions"] = conventions_json(conv);
    nlohmann::json by_class = nlohmann::json::object();
    for (input_class cls : all_input_classes()) {
      std::vector<case_grade> part;
      for (const auto& g : grades)
        if (g.cls == cls) part.push_back(g);
      if (part.empty()) continue;
      nlohmann::json c = summary_json(summarize(part, 1), lookup, conv_of);
      c.erase("examples");
      by_class[std::string(to_string(cls))] = c;
    }
    doc["by_class"] = by_class;
    nlohmann::json each = nlohmann::json::array();
    for (const auto& g : grades)
      each.push_back({{"id", g.id}, {"class", std::string(to_string(g.cls))}, {"verdict", std::string(to_string(g.v))},
                      {"max_ulps", g.max_ulps}, {"misclassified", g.misclassified}});
    doc["case_verdicts"] = each;
    doc["oracle"] = {{"decided_by_intervals", counters.decided_by_intervals},
                     {"fell_back_to_rationals", counters.fell_back_to_rationals}};
    if (o.max_ulps) doc["max_ulps_threshold"] = *o.max_ulps;
    if (fail_on) doc["fail_on"] = std::string(to_string(*fail_on));
    doc["exceeded"] = failed;
    std::cout << doc.dump(2) << '\n';
    return failed ? 1 : 0;
  }
  const report_style style{o.wide, 100};
  std::cout << "Graded " << grades.size() << " cases of " << to_string(cases.front().op) << " ("
            << to_string(cases.front().type) << ") against the exact answer: " << name << " is "
            << to_string(all.worst_verdict) << ".\n\n";
  std::vector<verdict_row> rows;
  for (input_class cls : all_input_classes()) {
    std::vector<case_grade> part;
    for (const auto& g : grades)
      if (g.cls == cls) part.push_back(g);
    if (!part.empty()) rows.push_back({name + " " + std::string(to_string(cls)), summarize(part, 0)});
  }
  rows.push_back({name, all});
  print_verdict_table(std::cout, rows, style);
  if (all.worst_verdict > verdict::faithful || all.misclassified) {
    std::cout << "\nWorst cases (bit-exact; each command prints the exact answer):\n";
    print_examples(std::cout, name, all, lookup, conv_of, style);
  }
  if (o.max_ulps)
    std::cout << '\n' << (ulps_failed ? "FAIL" : "PASS") << ": --max-ulps " << *o.max_ulps
              << (ulps_failed ? " exceeded, or NaN/Inf, garbage or misclassified cases\n" : " held\n");
  if (fail_on)
    std::cout << (o.max_ulps ? "" : "\n") << (verdict_failed ? "FAIL" : "PASS") << ": --fail-on " << to_string(*fail_on)
              << (verdict_failed ? ": some case is at or past it\n" : ": every case is better\n");
  return failed ? 1 : 0;
}

const command_registration reg{command{
    "grade", "grade a program's outputs (JSON lines) against the exact answers for `shadowproof cases` input",
    [](CLI::App& app, const global_options&) {
      auto o = std::make_shared<grade_options>();
      app.add_option("cases", o->cases_path, "cases file written by `shadowproof cases`")->required();
      app.add_option("outputs", o->outputs_path, "outputs file: one {\"id\": n, \"output\": [...]} per line, one per case")
          ->required();
      app.add_option("--name", o->name, "the label of the report's rows (default: the outputs file's name)");
      app.add_option("--layout", o->layout, "matrix storage: row-major or column-major")->capture_default_str();
      app.add_option("--vectors", o->vectors, "column (M v) or row (v M) vectors")->capture_default_str();
      app.add_option("--light", o->light, "directional light vector: towards-light or along-rays")
          ->capture_default_str();
      app.add_option("--depth", o->depth, "projections: NDC depth convention gl, d3d or reverse-z")
          ->capture_default_str();
      app.add_flag("--homogeneous", o->homogeneous, "matrices are correct up to a non-zero scale");
      app.add_option("--sentinel", o->sentinel,
                     "what the program returns, by its documentation, where there is no answer: none, zero "
                     "(every output 0) or identity (the identity matrix); NaN/Inf is always accepted")
          ->capture_default_str();
      app.add_flag("--clamps-behind-receiver", o->clamps, "shadow-point: a point behind the receiver stays in place");
      app.add_flag("--symmetric", o->symmetric, "view volumes are symmetric (l = −r, b = −t)");
      app.add_option("--convention", o->conventions,
                     "name=value, repeatable (docs/protocol.md): handedness=left, angle=degrees, matrix3=mat4, ...; "
                     "a case line's own \"conventions\" override the command line's for that case");
      app.add_flag("--json", o->json, "print one JSON object (every field, every case's verdict)");
      app.add_flag("--wide", o->wide, "show a worst case per verdict, with every output and the inputs");
      app.add_option("--max-ulps", o->max_ulps, "exit with 1 when an output is more than this many ulps off, or NaN/Inf "
                                                "where the exact value exists, or a case is garbage or misclassified");
      app.add_option("--fail-on", o->fail_on,
                     "exit with 1 when a case is at or past this verdict: exact, faithful, stable, unstable, "
                     "range, wrong, nonfinite, garbage");
      return [o] { return run_grade(*o); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
