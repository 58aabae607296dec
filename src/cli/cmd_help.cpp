// shadowproof help: the help of any command, of all of them, the man page and the bash
// completion script, all generated from the command-line definitions.
#include <algorithm>
#include <iostream>
#include <memory>

#include "cli_reference.h"
#include "command.h"
#include "shadowproof/core/error.h"

namespace shadowproof::cli {
namespace {

struct help_options {
  std::vector<std::string> path;
  bool all = false, man = false, completion = false;
};

int run_help(const help_options& o, const CLI::App& root) {
  if (o.man) {
    std::cout << man_page(root, SHADOWPROOF_VERSION);
    return 0;
  }
  if (o.completion) {
    std::cout << bash_completion(root);
    return 0;
  }
  if (o.all) {
    std::cout << help_all(root);
    return 0;
  }
  const CLI::App* app = &root;
  std::string typed;
  for (const auto& word : o.path) {
    typed += (typed.empty() ? "" : " ") + word;
    const auto subs = subcommands_of(*app);
    const auto it = std::find_if(subs.begin(), subs.end(), [&](const CLI::App* s) { return s->get_name() == word; });
    if (it == subs.end()) {
      std::string names;
      for (const CLI::App* s : subs) names += (names.empty() ? "" : ", ") + s->get_name();
      throw error(errc::cli_unknown_command, "no command 'shadowproof " + typed + "'" +
                                                 (names.empty() ? std::string(" (it has no subcommands)")
                                                                : " (one of: " + names + ")"));
    }
    app = *it;
  }
  std::cout << help_of(*app);
  return 0;
}

const command_registration help_registration{command{
    "help", "the help of a command (help explain shadow), of every command (--all), the man page or the bash completion",
    [](CLI::App& app, const global_options&) -> std::function<int()> {
      auto o = std::make_shared<help_options>();
      app.add_option("command", o->path, "the command whose help to print, e.g. explain shadow");
      app.add_flag("--all", o->all, "print the help of every command");
      app.add_flag("--man", o->man, "print the man page shadowproof(1) in troff");
      app.add_flag("--bash-completion", o->completion, "print the bash completion script");
      const CLI::App* root = app.get_parent();
      return [o, root] { return run_help(*o, *root); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
