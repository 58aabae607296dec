// Shard blocks of reports and the checks made before merging them.
#include "shard_report.h"

#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "shadowproof/core/error.h"

namespace shadowproof::cli {

nlohmann::json shard_json(const shard& part, const nlohmann::json& run) {
  return {{"index", part.index}, {"count", part.count}, {"run", run}};
}

namespace {

shard_report read_one(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw error(errc::merge_input, "cannot read the shard report '" + path + "'");
  std::ostringstream text;
  text << f.rdbuf();
  shard_report r;
  r.path = path;
  r.doc = nlohmann::json::parse(text.str(), nullptr, false);
  if (r.doc.is_discarded() || !r.doc.is_object())
    throw error(errc::merge_input, path + " is not a JSON report (run check, grade or fuzz with --shard i/N --json)");
  const auto it = r.doc.find("shard");
  if (it == r.doc.end() || !it->is_object())
    throw error(errc::merge_input, path + " has no \"shard\" block: it is not the report of a run with --shard i/N");
  const auto& s = *it;
  if (!s.contains("index") || !s["index"].is_number_unsigned() || !s.contains("count") ||
      !s["count"].is_number_unsigned() || !s.contains("run") || !s["run"].is_object() ||
      !s["run"].contains("command") || !s["run"]["command"].is_string())
    throw error(errc::merge_input, path + ": the \"shard\" block needs an index, a count and a run");
  r.part.index = s["index"].get<std::uint64_t>();
  r.part.count = s["count"].get<std::uint64_t>();
  if (r.part.count == 0 || r.part.count > max_shard_count || r.part.index >= r.part.count)
    throw error(errc::merge_input, path + ": shard " + std::to_string(r.part.index) + "/" +
                                   std::to_string(r.part.count) + " is not a shard i/N with 0 <= i < N");
  r.run = s["run"];
  return r;
}

}  // namespace

std::vector<shard_report> read_shard_reports(const std::vector<std::string>& paths) {
  if (paths.empty()) throw error(errc::merge_input, "give the JSON reports of the shards to merge");
  std::vector<shard_report> reports;
  for (const auto& p : paths) reports.push_back(read_one(p));
  const shard_report& first = reports.front();
  for (const auto& r : reports) {
    if (r.part.count != first.part.count)
      throw error(errc::merge_mismatch, r.path + " is shard " + to_string(r.part) + " but " + first.path +
                                        " is shard " + to_string(first.part) + ": different shard counts");
    if (r.run != first.run)
      throw error(errc::merge_mismatch, r.path + " and " + first.path + " are shards of different runs: " +
                                        r.run.dump() + " vs " + first.run.dump());
  }
  std::vector<const shard_report*> by_index(first.part.count, nullptr);
  for (const auto& r : reports) {
    const shard_report*& slot = by_index[r.part.index];
    if (slot)
      throw error(errc::merge_duplicate_shard, "shard " + to_string(r.part) + " is given twice: " + slot->path +
                                               " and " + r.path);
    slot = &r;
  }
  for (std::uint64_t i = 0; i < first.part.count; ++i)
    if (!by_index[i]) {
      std::size_t missing = 0;
      for (const auto* r : by_index) missing += r ? 0 : 1;
      throw error(errc::merge_missing_shard, "shard " + to_string(shard{i, first.part.count}) +
                                             " is missing (" + std::to_string(missing) + " of " +
                                             std::to_string(first.part.count) + " shards not given)");
    }
  std::vector<shard_report> ordered;
  for (const auto* r : by_index) ordered.push_back(*r);
  return ordered;
}

namespace {

// Doubles travel as their 64 bits in hex, so NaN payloads, −0 and infinities survive.
std::string bits_text(double x) {
  std::uint64_t u = 0;
  std::memcpy(&u, &x, sizeof u);
  char text[24];
  std::snprintf(text, sizeof text, "%016" PRIx64, u);
  return text;
}

double bits_value(const shard_report& r, const nlohmann::json& j) {
  const std::string text = j.is_string() ? j.get<std::string>() : std::string();
  std::uint64_t u = 0;
  if (text.size() != 16 || text.find_first_not_of("0123456789abcdef") != std::string::npos ||
      std::sscanf(text.c_str(), "%" SCNx64, &u) != 1)
    throw error(errc::merge_input, r.path + ": " + j.dump() + " is not the 16 hex digits of a double");
  double x = 0;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

}  // namespace

nlohmann::json mergeable_json(const mergeable_summary& m) {
  const grade_summary& s = m.summary;
  nlohmann::json ulps = nlohmann::json::array();
  for (const auto& [u, n] : m.ulps_counts) ulps.push_back({u, n});
  return {{"cases", s.cases},
          {"outputs", s.outputs},
          {"max_ulps", s.max_ulps},
          {"nonfinite", s.nonfinite},
          {"garbage", s.garbage},
          {"misclassified", s.misclassified},
          {"bits_histogram", s.bits_histogram},
          {"verdicts", s.verdicts},
          {"worst_verdict", std::string(to_string(s.worst_verdict))},
          {"ulps_counts", ulps}};
}

mergeable_summary mergeable_from_json(const shard_report& r, const nlohmann::json& j) {
  try {
    mergeable_summary m;
    grade_summary& s = m.summary;
    s.cases = j.at("cases").get<std::size_t>();
    s.outputs = j.at("outputs").get<std::size_t>();
    s.max_ulps = j.at("max_ulps").get<std::uint64_t>();
    s.nonfinite = j.at("nonfinite").get<std::size_t>();
    s.garbage = j.at("garbage").get<std::size_t>();
    s.misclassified = j.at("misclassified").get<std::size_t>();
    s.bits_histogram = j.at("bits_histogram").get<std::vector<std::size_t>>();
    s.verdicts = j.at("verdicts").get<std::vector<std::size_t>>();
    const auto v = verdict_from_string(j.at("worst_verdict").get<std::string>());
    if (!v) throw error(errc::merge_input, r.path + ": unknown verdict " + j.at("worst_verdict").dump());
    s.worst_verdict = *v;
    for (const auto& pair : j.at("ulps_counts"))
      m.ulps_counts[pair.at(0).get<std::uint64_t>()] += pair.at(1).get<std::uint64_t>();
    return m;
  } catch (const nlohmann::json::exception& e) {
    throw error(errc::merge_input, r.path + ": a summary of the shard is malformed: " + e.what());
  }
}

nlohmann::json bits_json(const std::vector<double>& xs) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : xs) a.push_back(bits_text(x));
  return a;
}

std::vector<double> doubles_from_bits(const shard_report& r, const nlohmann::json& array) {
  if (!array.is_array()) throw error(errc::merge_input, r.path + ": expected an array of doubles' bits");
  std::vector<double> xs;
  for (const auto& x : array) xs.push_back(bits_value(r, x));
  return xs;
}

nlohmann::json candidate_json(const candidate& c) {
  nlohmann::json inputs = nlohmann::json::array(), outputs = nlohmann::json::array();
  for (double x : c.c.inputs) inputs.push_back(bits_text(x));
  for (double x : c.outputs) outputs.push_back(bits_text(x));
  return {{"id", c.c.id},
          {"class", std::string(to_string(c.c.cls))},
          {"closeness", bits_text(c.c.closeness)},
          {"inputs", inputs},
          {"outputs", outputs}};
}

candidate candidate_from_json(const shard_report& r, const nlohmann::json& j, operation op, scalar_type type) {
  try {
    candidate k;
    k.c.id = j.at("id").get<std::uint64_t>();
    k.c.op = op;
    k.c.type = type;
    const auto cls = input_class_from_string(j.at("class").get<std::string>());
    if (!cls) throw error(errc::merge_input, r.path + ": unknown input class " + j.at("class").dump());
    k.c.cls = *cls;
    k.c.closeness = bits_value(r, j.at("closeness"));
    for (const auto& x : j.at("inputs")) k.c.inputs.push_back(bits_value(r, x));
    for (const auto& x : j.at("outputs")) k.outputs.push_back(bits_value(r, x));
    if (k.c.inputs.size() != signature(op).input_count || k.outputs.size() != signature(op).output_count)
      throw error(errc::merge_input, r.path + ": case " + std::to_string(k.c.id) + " has the wrong number of inputs or outputs");
    return k;
  } catch (const nlohmann::json::exception& e) {
    throw error(errc::merge_input, r.path + ": a case of the shard is malformed: " + e.what());
  }
}

const nlohmann::json& member(const shard_report& r, const nlohmann::json& object, const char* name) {
  const auto it = object.find(name);
  if (it == object.end()) throw error(errc::merge_input, r.path + ": the report has no \"" + name + "\"");
  return *it;
}

}  // namespace shadowproof::cli
