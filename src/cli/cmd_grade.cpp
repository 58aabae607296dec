// shadowproof grade: grades a program's outputs (JSON lines) against the exact answers for the
// cases it was given (JSON lines from `shadowproof cases`).
#include <fstream>
#include <iostream>
#include <map>

#include "command.h"
#include "shadowproof/core/error.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/report.h"
#include "shadowproof/verify/protocol.h"
#include "verify_print.h"

namespace shadowproof::cli {
namespace {

struct grade_options {
  std::string cases_path, outputs_path;
  std::string layout = "row-major";
  std::string vectors = "column";
  std::string light = "towards-light";
  std::string depth = "gl";
  bool homogeneous = false;
  bool json = false;
  std::optional<std::uint64_t> max_ulps;
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

int run_grade(const grade_options& o) {
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
  conv.homogeneous = o.homogeneous;
  conv.depth = parse_depth_convention(o.depth);
  for (const auto& t : o.conventions) {
    const auto eq = t.find('=');
    if (eq == std::string::npos)
      throw error(errc::protocol_convention, "--convention '" + t + "' must read name=value, e.g. depth=d3d");
    set_convention(conv, t.substr(0, eq), t.substr(eq + 1));
  }

  const auto case_lines = read_lines(o.cases_path, "cases");
  std::vector<test_case> cases;
  std::vector<conventions> case_conv;  // the command line's, overridden by the line's own
  std::map<std::uint64_t, std::size_t> index;
  for (std::size_t i = 0; i < case_lines.size(); ++i) {
    case_conv.push_back(conv);
    cases.push_back(parse_case_line(case_lines[i], i + 1, case_conv.back()));
    if (!index.emplace(cases.back().id, i).second)
      throw error(errc::grade_duplicate_id, o.cases_path + " line " + std::to_string(i + 1) + ": case id " +
                                            std::to_string(cases.back().id) + " appears twice");
  }
  const auto output_lines = read_lines(o.outputs_path, "outputs");
  std::vector<case_grade> grades;
  std::map<std::uint64_t, bool> seen;
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
    if (seen[id])
      throw error(errc::grade_duplicate_id, o.outputs_path + " line " + std::to_string(i + 1) + ": id " +
                                            std::to_string(id) + " graded twice");
    seen[id] = true;
    const test_case& c = cases[it->second];
    const conventions& cc = case_conv[it->second];
    const output_line out = parse_output_line(output_lines[i], i + 1, c, cc);
    grades.push_back(grade_case(c, cc, out.values.data(), oracle_mode::filtered, &counters));
  }
  const std::size_t missing = cases.size() - grades.size();

  auto lookup = [&](std::uint64_t id) -> const test_case& { return cases[index.at(id)]; };
  auto conv_of = [&](std::uint64_t id) -> const conventions& { return case_conv[index.at(id)]; };
  const grade_summary all = summarize(grades, 5);
  const bool exceeded = o.max_ulps && (all.max_ulps > *o.max_ulps || all.nonfinite > 0);
  if (o.json) {
    nlohmann::json doc = summary_json(all, lookup, conv_of);
    doc["missing"] = missing;
    nlohmann::json by_class = nlohmann::json::object();
    for (input_class cls : {input_class::regular, input_class::near_degenerate, input_class::degenerate}) {
      std::vector<case_grade> part;
      for (const auto& g : grades)
        if (g.cls == cls) part.push_back(g);
      if (!part.empty()) by_class[std::string(to_string(cls))] = summary_json(summarize(part, 1), lookup, conv_of);
    }
    doc["by_class"] = by_class;
    if (o.max_ulps) doc["exceeded"] = exceeded;
    std::cout << doc.dump(2) << '\n';
    return exceeded ? 1 : 0;
  }
  std::vector<report_row> rows;
  const std::string name = o.outputs_path;
  const operation op = cases.empty() ? operation::shadow_matrix : cases.front().op;
  const scalar_type type = cases.empty() ? scalar_type::f32 : cases.front().type;
  for (input_class cls : {input_class::regular, input_class::near_degenerate, input_class::degenerate}) {
    std::vector<case_grade> part;
    for (const auto& g : grades)
      if (g.cls == cls) part.push_back(g);
    if (!part.empty()) rows.push_back({name, op, type, std::string(to_string(cls)), summarize(part)});
  }
  rows.push_back({name, op, type, "all", all});
  std::cout << "Graded " << grades.size() << " of " << cases.size() << " cases against the exact answer"
            << (missing ? " (" + std::to_string(missing) + " without an output line)" : std::string()) << ".\n\n";
  print_table(std::cout, rows);
  if (!all.worst.empty()) {
    std::cout << "\nWorst cases:\n";
    for (const auto& g : all.worst) print_worst(std::cout, "case", g, lookup(g.id), conv_of(g.id));
  }
  if (o.max_ulps)
    std::cout << '\n' << (exceeded ? "FAIL" : "PASS") << ": threshold --max-ulps " << *o.max_ulps
              << (exceeded ? " exceeded\n" : " held\n");
  return exceeded ? 1 : 0;
}

const command_registration reg{command{
    "grade", "grade a program's outputs (JSON lines) against the exact answers for `shadowproof cases` input",
    [](CLI::App& app, const global_options&) {
      auto o = std::make_shared<grade_options>();
      app.add_option("cases", o->cases_path, "cases file written by `shadowproof cases`")->required();
      app.add_option("outputs", o->outputs_path, "outputs file: one {\"id\": n, \"output\": [...]} per line")
          ->required();
      app.add_option("--layout", o->layout, "matrix storage: row-major or column-major")->capture_default_str();
      app.add_option("--vectors", o->vectors, "column (M v) or row (v M) vectors")->capture_default_str();
      app.add_option("--light", o->light, "directional light vector: towards-light or along-rays")
          ->capture_default_str();
      app.add_option("--depth", o->depth, "projections: NDC depth convention gl, d3d or reverse-z")
          ->capture_default_str();
      app.add_flag("--homogeneous", o->homogeneous, "matrices are correct up to a non-zero scale");
      app.add_option("--convention", o->conventions,
                     "name=value, repeatable (docs/protocol.md): handedness=left, angle=degrees, matrix3=mat4, ...; "
                     "a case line's own \"conventions\" override the command line's for that case");
      app.add_flag("--json", o->json, "print one JSON object");
      app.add_option("--max-ulps", o->max_ulps, "exit with 1 when an output is more than this many ulps off, "
                                                "or non-finite where the exact value is finite");
      return [o] { return run_grade(*o); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
