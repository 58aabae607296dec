#pragma once
// Reference texts generated from the command-line definitions themselves (the CLI::App tree
// every cmd_<name>.cpp builds), so they cannot drift from what the parser accepts: the help of
// every command, the man page and the bash completion script.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace shadowproof::cli {

/// The subcommands of `app` (option groups excluded), sorted by name.
std::vector<const CLI::App*> subcommands_of(const CLI::App& app);

/// The help of one command, its usage line naming the whole path ("shadowproof explain shadow").
std::string help_of(const CLI::App& app);

/// The help of `root` followed by the help of every command and subcommand below it.
std::string help_all(const CLI::App& root);

/// The man page shadowproof(1) in troff (-man): name, synopsis, description, global options,
/// every command with its options, exit status.
std::string man_page(const CLI::App& root, const std::string& version);

/// A bash completion script: completes command names, then the options and subcommands of the
/// command typed so far; file names elsewhere.
std::string bash_completion(const CLI::App& root);

}  // namespace shadowproof::cli
