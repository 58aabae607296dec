// shadowproof grade: grades a program's outputs (JSON lines) against the exact answers for the
// cases it was given (JSON lines from `shadowproof cases`).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "command.h"
#include "jobs_option.h"
#include "shadowproof/core/error.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/parallel.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/protocol.h"
#include "shadowproof/verify/report.h"
#include "html_sections.h"
#include "shard_report.h"
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
  unsigned jobs = 0;  // 0: default_jobs()
  std::size_t max_cases = 1000000;
  std::string shard_spec;
  std::string html;
  std::string command_line;
};

// The non-blank lines of a case or outputs file, at most max_lines of them: grade holds every
// case and output in memory, about 2 kB per case.
std::vector<std::string> read_lines(const std::string& path, const char* what, std::size_t max_lines) {
  std::ifstream f(path);
  if (!f) throw error(errc::grade_file, std::string("cannot read the ") + what + " file '" + path + "'");
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(f, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) {
      if (lines.size() == max_lines)
        throw error(errc::io_too_large, path + " has more than " + std::to_string(max_lines) +
                                        " lines (raise the limit with --max-cases, or grade the cases in parts)");
      lines.push_back(line);
    }
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


// What a grade report shows, from the grades or merged from shards.
struct grade_report {
  std::size_t graded = 0;
  operation op = operation::shadow_matrix;
  scalar_type type = scalar_type::f32;
  bool one_kind = true;  // every case of op and type
  std::string name;
  conventions conv;                                                // the command line's
  grade_summary all;                                               // 5 worst cases
  std::vector<std::pair<input_class, grade_summary>> by_class;     // 1 worst case each (JSON)
  std::vector<std::pair<input_class, grade_summary>> class_rows;   // no worst case (the table)
  nlohmann::json case_verdicts = nlohmann::json::array();          // in the order of the outputs file
  oracle_counters counters;
  case_lookup lookup;
  conventions_lookup conv_of;
};

// What makes two grade reports shards of one run: the options that change a grade, and the
// two files by content (FNV-1a of their bytes), not by path, so shards can run anywhere.
std::uint64_t fnv1a(const std::vector<std::string>& lines) {
  std::uint64_t h = 14695981039346656037ull;
  for (const auto& line : lines) {
    for (unsigned char ch : line) h = (h ^ ch) * 1099511628211ull;
    h = (h ^ '\n') * 1099511628211ull;
  }
  return h;
}

nlohmann::json run_json(const grade_options& o, const std::string& name, const std::vector<std::string>& case_lines,
                        const std::vector<std::string>& output_lines) {
  return {{"command", "grade"}, {"name", name}, {"layout", o.layout}, {"vectors", o.vectors}, {"light", o.light},
          {"depth", o.depth}, {"sentinel", o.sentinel}, {"homogeneous", o.homogeneous},
          {"clamps_behind_receiver", o.clamps}, {"symmetric", o.symmetric}, {"conventions", o.conventions},
          {"max_ulps", o.max_ulps ? nlohmann::json(*o.max_ulps) : nlohmann::json()}, {"fail_on", o.fail_on},
          {"cases_file", {{"lines", case_lines.size()}, {"fnv1a", fnv1a(case_lines)}}},
          {"outputs_file", {{"lines", output_lines.size()}, {"fnv1a", fnv1a(output_lines)}}}};
}

bool grade_failed(const grade_options& o, const grade_summary& all, bool* ulps = nullptr, bool* verdicts = nullptr) {
  const std::optional<verdict> fail_on = parse_fail_on(o.fail_on);
  const bool ulps_failed = o.max_ulps && (all.max_ulps > *o.max_ulps || all.nonfinite > 0 || all.garbage > 0 ||
                                          all.misclassified > 0);
  const bool verdict_failed = fail_on && reaches(all, *fail_on);
  if (ulps) *ulps = ulps_failed;
  if (verdicts) *verdicts = verdict_failed;
  return ulps_failed || verdict_failed;
}

nlohmann::json grade_json(const grade_options& o, const grade_report& r) {
  const std::optional<verdict> fail_on = parse_fail_on(o.fail_on);
  nlohmann::json doc = summary_json(r.all, r.lookup, r.conv_of);
  doc["name"] = r.name;
  doc["conventions"] = conventions_json(r.conv);
  nlohmann::json by_class = nlohmann::json::object();
  for (const auto& [cls, s] : r.by_class) {
    nlohmann::json c = summary_json(s, r.lookup, r.conv_of);
    c.erase("examples");
    by_class[std::string(to_string(cls))] = c;
  }
  doc["by_class"] = by_class;
  doc["case_verdicts"] = r.case_verdicts;
  doc["oracle"] = {{"decided_by_intervals", r.counters.decided_by_intervals},
                   {"fell_back_to_rationals", r.counters.fell_back_to_rationals}};
  if (o.max_ulps) doc["max_ulps_threshold"] = *o.max_ulps;
  if (fail_on) doc["fail_on"] = std::string(to_string(*fail_on));
  doc["exceeded"] = grade_failed(o, r.all);
  return doc;
}

int print_grade_report(const grade_options& o, const grade_report& r) {
  const std::optional<verdict> fail_on = parse_fail_on(o.fail_on);
  bool ulps_failed = false, verdict_failed = false;
  const bool failed = grade_failed(o, r.all, &ulps_failed, &verdict_failed);
  if (o.json) {
    std::cout << grade_json(o, r).dump(2) << '\n';
    return failed ? 1 : 0;
  }
  const report_style style{o.wide, 100};
  std::cout << "Graded " << r.graded << " cases of "
            << (r.one_kind ? std::string(to_string(r.op)) + " (" + std::string(to_string(r.type)) + ")"
                           : std::string("several operations"))
            << " against the exact answer: " << r.name << " is " << to_string(r.all.worst_verdict) << ".\n\n";
  std::vector<verdict_row> rows;
  for (const auto& [cls, s] : r.class_rows) rows.push_back({r.name + " " + std::string(to_string(cls)), s});
  rows.push_back({r.name, r.all});
  print_verdict_table(std::cout, rows, style);
  if (r.all.worst_verdict > verdict::faithful || r.all.misclassified) {
    std::cout << "\nWorst cases (bit-exact; each command prints the exact answer):\n";
    print_examples(std::cout, r.name, r.all, r.lookup, r.conv_of, style);
  }
  if (o.max_ulps)
    std::cout << '\n' << (ulps_failed ? "FAIL" : "PASS") << ": --max-ulps " << *o.max_ulps
              << (ulps_failed ? " exceeded, or NaN/Inf, garbage or misclassified cases\n" : " held\n");
  if (fail_on)
    std::cout << (o.max_ulps ? "" : "\n") << (verdict_failed ? "FAIL" : "PASS") << ": --fail-on " << to_string(*fail_on)
              << (verdict_failed ? ": some case is at or past it\n" : ": every case is better\n");
  return failed ? 1 : 0;
}

std::vector<case_grade> of_class(const std::vector<case_grade>& grades, input_class cls) {
  std::vector<case_grade> part;
  for (const auto& g : grades)
    if (g.cls == cls) part.push_back(g);
  return part;
}

html_page grade_page(const grade_options& o, const grade_report& r, const std::vector<case_grade>& grades) {
  html_page page;
  page.title = "shadowproof grade: " + r.name;
  page.command = o.command_line;
  page.summary.push_back("Graded " + std::to_string(r.graded) + " cases of " + std::string(to_string(r.op)) + " (" +
                         std::string(to_string(r.type)) + ") from " + o.cases_path + " against the exact answer: " +
                         r.name + " is " + std::string(to_string(r.all.worst_verdict)) +
                         ". A case's verdict is that of its worst output (docs/verdicts.md).");
  graded_run g;
  g.name = r.name;
  g.op = r.op;
  g.type = r.type;
  g.conv = &r.conv;
  g.summary = &r.all;
  point_cloud plot;
  for (const auto& x : grades) add_to_plot(plot, r.lookup(x.id), x);
  g.plot = &plot;
  g.lookup = r.lookup;
  g.failed = grade_failed(o, r.all);
  page.sections.push_back(graded_section(g));
  return page;
}

int run_grade(const grade_options& o) {
  const conventions conv = conventions_of(o);
  (void)parse_fail_on(o.fail_on);  // a bad --fail-on fails before any grading
  const shard part = o.shard_spec.empty() ? shard{} : parse_shard(o.shard_spec);

  const auto case_lines = read_lines(o.cases_path, "cases", o.max_cases);
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
  const auto output_lines = read_lines(o.outputs_path, "outputs", o.max_cases);
  if (output_lines.empty())
    throw error(errc::grade_empty, "the outputs file '" + o.outputs_path + "' has no line: none of the " +
                                   std::to_string(cases.size()) + " cases was answered");
  std::vector<std::size_t> graded_case;  // per output line, the index of its case
  std::vector<output_line> outputs;
  std::vector<std::size_t> positions;               // the outputs line of each grade
  std::map<std::uint64_t, std::vector<double>> answered;  // outputs of each graded case, for a shard's report
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
    if (!part.contains(id)) continue;  // another shard's case
    graded_case.push_back(it->second);
    outputs.push_back(parse_output_line(output_lines[i], i + 1, cases[it->second], case_conv[it->second]));
    positions.push_back(i);
    if (!o.shard_spec.empty()) answered[id] = outputs.back().values;
  }
  // Every line read and checked first (a bad line is reported the same way for any --jobs),
  // then graded on several threads, each grade in its line's place and each slice's counters
  // in the slice's own place, summed in order.
  std::vector<case_grade> grades(outputs.size());
  const std::size_t slice = 256;
  std::vector<oracle_counters> slice_counters((grades.size() + slice - 1) / slice);
  for_each_slice(grades.size(), o.jobs, slice, [&](std::size_t first, std::size_t end) {
    for (std::size_t i = first; i < end; ++i) {
      const std::size_t k = graded_case[i];
      grades[i] = grade_case(cases[k], case_conv[k], outputs[i].values.data(), oracle_mode::filtered,
                             &slice_counters[first / slice]);
    }
  });
  for (const oracle_counters& c : slice_counters) {
    counters.decided_by_intervals += c.decided_by_intervals;
    counters.fell_back_to_rationals += c.fell_back_to_rationals;
  }
  std::vector<std::uint64_t> missing;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (!seen[i]) missing.push_back(cases[i].id);
  if (!missing.empty())
    throw error(errc::grade_missing_id, o.outputs_path + " answers " + std::to_string(output_lines.size()) +
                                        " of the " + std::to_string(cases.size()) + " cases; no output line for " +
                                        id_list(missing));

  grade_report r;
  r.graded = grades.size();
  r.op = cases.front().op;
  r.type = cases.front().type;
  for (const auto& c : cases) r.one_kind = r.one_kind && c.op == r.op && c.type == r.type;
  r.name = o.name.empty() ? std::filesystem::path(o.outputs_path).stem().string() : o.name;
  r.conv = conv;
  r.all = summarize(grades, 5);
  for (input_class cls : all_input_classes()) {
    const auto p = of_class(grades, cls);
    if (p.empty()) continue;
    r.by_class.emplace_back(cls, summarize(p, 1));
    r.class_rows.emplace_back(cls, summarize(p, 0));
  }
  if (o.json)  // printed only there
    for (const auto& g : grades)
      r.case_verdicts.push_back({{"id", g.id}, {"class", std::string(to_string(g.cls))},
                               {"verdict", std::string(to_string(g.v))}, {"max_ulps", g.max_ulps},
                               {"misclassified", g.misclassified}});
  r.counters = counters;
  r.lookup = [&](std::uint64_t id) -> const test_case& { return cases[index.at(id)]; };
  r.conv_of = [&](std::uint64_t id) -> const conventions& { return case_conv[index.at(id)]; };
  if (!o.html.empty()) write_html(o.html, grade_page(o, r, grades));
  if (!o.shard_spec.empty() && o.json) {
    // A shard's report: the run's JSON, the shard block, and what merge needs besides: the
    // statistics, where each graded line stood, and the singled-out cases as their case lines
    // with the outputs read for them.
    nlohmann::json doc = grade_json(o, r);
    doc["shard"] = shard_json(part, run_json(o, r.name, case_lines, output_lines));
    nlohmann::json m;
    m["graded"] = grades.size();
    m["op"] = std::string(to_string(r.op));
    m["type"] = std::string(to_string(r.type));
    m["one_kind"] = r.one_kind;
    m["summary"] = mergeable_json(summarize_mergeable(grades, 5));
    std::set<std::uint64_t> singled;
    for (const auto& g : singled_out_cases(r.all)) singled.insert(g.id);
    nlohmann::json by_class = nlohmann::json::object();
    for (const auto& [cls, s] : r.by_class) {
      by_class[std::string(to_string(cls))] = mergeable_json(summarize_mergeable(of_class(grades, cls), 1));
      for (const auto& g : singled_out_cases(s)) singled.insert(g.id);
    }
    m["by_class"] = by_class;
    m["positions"] = positions;
    nlohmann::json candidates = nlohmann::json::array();
    for (std::uint64_t id : singled) {
      const std::size_t line = index.at(id);
      candidates.push_back({{"line", line + 1}, {"case", case_lines[line]},
                            {"outputs", bits_json(answered.at(id))}});
    }
    m["candidates"] = candidates;
    doc["merge"] = m;
    std::cout << doc.dump(2) << '\n';
    return grade_failed(o, r.all) ? 1 : 0;
  }
  return print_grade_report(o, r);
}

const command_registration grade_registration{command{
    "grade", "grade a program's outputs (JSON lines) against the exact answers for `shadowproof cases` input",
    [](CLI::App& app, const global_options& globals) {
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
      add_jobs_option(app, o->jobs);
      app.add_option("--max-cases", o->max_cases, "refuse case and outputs files of more lines than this (every case is "
                                                  "held in memory, about 2 kB each)")->capture_default_str();
      app.add_flag("--wide", o->wide, "show a worst case per verdict, with every output and the inputs");
      app.add_option("--max-ulps", o->max_ulps, "exit with 1 when an output is more than this many ulps off, or NaN/Inf "
                                                "where the exact value exists, or a case is garbage or misclassified");
      app.add_option("--fail-on", o->fail_on,
                     "exit with 1 when a case is at or past this verdict: exact, faithful, stable, unstable, "
                     "range, wrong, nonfinite, garbage");
      app.add_option("--shard", o->shard_spec, "grade only shard i of N (the cases whose id mod N is i); merge the "
                                               "--json reports with `shadowproof merge`");
      app.add_option("--html", o->html, "write a self-contained HTML report to this file");
      o->command_line = globals.command_line;
      return [o] { return run_grade(*o); };
    }}};

}  // namespace

int merge_grade_shards(const std::vector<shard_report>& shards, const merge_options& m) {
  const nlohmann::json& run = shards.front().run;
  grade_options o;
  try {
    o.name = run.at("name").get<std::string>();
    o.layout = run.at("layout").get<std::string>();
    o.vectors = run.at("vectors").get<std::string>();
    o.light = run.at("light").get<std::string>();
    o.depth = run.at("depth").get<std::string>();
    o.sentinel = run.at("sentinel").get<std::string>();
    o.homogeneous = run.at("homogeneous").get<bool>();
    o.clamps = run.at("clamps_behind_receiver").get<bool>();
    o.symmetric = run.at("symmetric").get<bool>();
    o.conventions = run.at("conventions").get<std::vector<std::string>>();
    if (!run.at("max_ulps").is_null()) o.max_ulps = run.at("max_ulps").get<std::uint64_t>();
    o.fail_on = run.at("fail_on").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw error(errc::merge_input, shards.front().path + ": the run of the shard is malformed: " + e.what());
  }
  o.json = m.json;
  o.wide = m.wide;
  grade_report r;
  r.name = o.name;
  r.conv = conventions_of(o);
  std::map<std::uint64_t, test_case> cases;
  std::map<std::uint64_t, conventions> case_conv;
  std::vector<mergeable_summary> parts;
  std::map<std::string, std::vector<mergeable_summary>> class_parts;
  std::vector<case_grade> candidates;
  std::vector<std::pair<std::size_t, nlohmann::json>> verdicts;
  try {
    for (const auto& s : shards) {
      const auto& payload = member(s, s.doc, "merge");
      const auto op = operation_from_string(payload.at("op").get<std::string>());
      const auto type = scalar_type_from_string(payload.at("type").get<std::string>());
      if (!op || !type) throw error(errc::merge_input, s.path + ": unknown operation or type");
      r.op = *op;
      r.type = *type;
      r.graded += payload.at("graded").get<std::size_t>();
      r.one_kind = payload.at("one_kind").get<bool>();
      const auto& oracle = member(s, s.doc, "oracle");
      r.counters.decided_by_intervals += oracle.at("decided_by_intervals").get<std::uint64_t>();
      r.counters.fell_back_to_rationals += oracle.at("fell_back_to_rationals").get<std::uint64_t>();
      parts.push_back(mergeable_from_json(s, payload.at("summary")));
      for (const auto& [cls, j] : payload.at("by_class").items()) class_parts[cls].push_back(mergeable_from_json(s, j));
      for (const auto& c : payload.at("candidates")) {
        // The case line read as the shard read it, the outputs as the shard parsed them.
        conventions cc = r.conv;
        const test_case t = parse_case_line(c.at("case").get<std::string>(), c.at("line").get<std::size_t>(), cc);
        const std::vector<double> outputs = doubles_from_bits(s, c.at("outputs"));
        if (outputs.size() != signature(t.op).output_count)
          throw error(errc::merge_input, s.path + ": case " + std::to_string(t.id) + " has the wrong number of outputs");
        candidates.push_back(grade_case(t, cc, outputs.data()));
        cases[t.id] = t;
        case_conv[t.id] = cc;
      }
      const auto positions = payload.at("positions").get<std::vector<std::size_t>>();
      const auto& each = member(s, s.doc, "case_verdicts");
      if (positions.size() != each.size()) throw error(errc::merge_input, s.path + ": case_verdicts and positions differ in length");
      for (std::size_t k = 0; k < positions.size(); ++k) verdicts.emplace_back(positions[k], each[k]);
    }
  } catch (const nlohmann::json::exception& e) {
    throw error(errc::merge_input, "a grade shard report is malformed: " + std::string(e.what()));
  }
  r.all = merge_summaries(parts, candidates, 5).summary;
  for (input_class cls : all_input_classes()) {
    const auto it = class_parts.find(std::string(to_string(cls)));
    if (it == class_parts.end()) continue;
    const auto p = of_class(candidates, cls);
    r.by_class.emplace_back(cls, merge_summaries(it->second, p, 1).summary);
    r.class_rows.emplace_back(cls, merge_summaries(it->second, p, 0).summary);
  }
  std::sort(verdicts.begin(), verdicts.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [position, v] : verdicts) r.case_verdicts.push_back(std::move(v));
  r.lookup = [&cases](std::uint64_t id) -> const test_case& { return cases.at(id); };
  r.conv_of = [&case_conv](std::uint64_t id) -> const conventions& { return case_conv.at(id); };
  return print_grade_report(o, r);
}

}  // namespace shadowproof::cli
