// shadowproof merge: the report of a whole run from the JSON reports of its shards.
#include <iostream>

#include "command.h"
#include "shadowproof/core/error.h"
#include "shard_report.h"

namespace shadowproof::cli {
namespace {

struct merge_command_options {
  std::vector<std::string> paths;
  merge_options merge;
};

int run_merge(const merge_command_options& o) {
  const auto shards = read_shard_reports(o.paths);
  const std::string command = shards.front().run["command"].get<std::string>();
  if (command == "check") return merge_check_shards(shards, o.merge);
  if (command == "grade") return merge_grade_shards(shards, o.merge);
  if (command == "fuzz") return merge_fuzz_shards(shards, o.merge);
  throw error(errc::merge_input, shards.front().path + ": a shard of '" + command +
                                 "', which merge does not know (check, grade, fuzz)");
}

const command_registration merge_registration{command{
    "merge", "combine the JSON reports of the shards of a check, grade or fuzz run into the run's report",
    [](CLI::App& app, const global_options&) {
      auto o = std::make_shared<merge_command_options>();
      app.add_option("reports", o->paths, "the shards' reports (--shard i/N --json), in any order")->required();
      app.add_flag("--json", o->merge.json, "print the merged report as JSON (as the unsharded run's --json)");
      app.add_flag("--wide", o->merge.wide, "check and grade: show a worst case per verdict (as the run's --wide)");
      return [o] { return run_merge(*o); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
