#pragma once
// Shard reports: the JSON block a sharded check, grade or fuzz run adds to its report, and the
// checks `shadowproof merge` makes before combining them.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/shard.h"
#include "shadowproof/verify/summary_merge.h"

namespace shadowproof::cli {

/// {"index": i, "count": N, "run": run}: `run` names everything that makes two reports shards
/// of one run (command, implementation, seed, case count, files, thresholds).
nlohmann::json shard_json(const shard& part, const nlohmann::json& run);

/// One shard report read back.
struct shard_report {
  std::string path;
  shard part;
  nlohmann::json run;  ///< the "run" object
  nlohmann::json doc;  ///< the whole report
};

/// Reads the reports at `paths` and checks that they are the N shards of one run, each once:
/// merge.input for an unreadable file or one without a shard block, merge.mismatch for shards
/// of different runs, merge.duplicate_shard and merge.missing_shard. Returns them by index.
std::vector<shard_report> read_shard_reports(const std::vector<std::string>& paths);

/// Reads a JSON member of a shard report, or throws merge.input naming the file and the member.
const nlohmann::json& member(const shard_report& r, const nlohmann::json& object, const char* name);

/// The statistics of a summary (cases, outputs, counts, histograms, distribution of ulps): what
/// merge_summaries adds up. The cases it singles out travel as candidates.
nlohmann::json mergeable_json(const mergeable_summary& m);
/// Inverse of mergeable_json (the summary's chosen cases left empty).
mergeable_summary mergeable_from_json(const shard_report& r, const nlohmann::json& j);

/// A case and an implementation's outputs for it, bit for bit: what a merge needs to grade a
/// singled-out case again, exactly as the shard did.
struct candidate {
  test_case c;
  std::vector<double> outputs;
};
nlohmann::json candidate_json(const candidate& c);
/// Doubles as the 16 hex digits of their bits (NaN payloads, −0 and infinities survive), and back.
nlohmann::json bits_json(const std::vector<double>& xs);
std::vector<double> doubles_from_bits(const shard_report& r, const nlohmann::json& array);
/// Inverse of candidate_json for a case of op and type.
candidate candidate_from_json(const shard_report& r, const nlohmann::json& j, operation op, scalar_type type);

/// What merging a command's shards prints: the report of the unsharded run, text or JSON.
struct merge_options {
  bool json = false;
  bool wide = false;
};

// Each command that can be sharded merges its own reports (cmd_check.cpp, cmd_grade.cpp,
// cmd_fuzz.cpp); the reports are complete and validated by read_shard_reports.
int merge_check_shards(const std::vector<shard_report>& shards, const merge_options& o);
int merge_grade_shards(const std::vector<shard_report>& shards, const merge_options& o);
int merge_fuzz_shards(const std::vector<shard_report>& shards, const merge_options& o);

}  // namespace shadowproof::cli
