#pragma once
// The CLI's subcommand registry: each src/cli/cmd_<name>.cpp registers itself with a static
// `command_registration`, so adding a subcommand touches no other file.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

#include "shadowproof/core/number.h"

namespace shadowproof::cli {

/// Options every subcommand shares.
struct global_options {
  number_limits limits;
  std::string command_line;  ///< as typed, quoted for a shell (shown in reports)
};

struct command {
  std::string name;
  std::string description;
  // Adds the subcommand's options to `app` and returns the action to run when it is chosen.
  // The action returns the process exit code; it throws shadowproof::error for bad input.
  std::function<std::function<int()>(CLI::App& app, const global_options& globals)> setup;
};

std::vector<command>& command_list();

struct command_registration {
  explicit command_registration(command c) { command_list().push_back(std::move(c)); }
};

}  // namespace shadowproof::cli
