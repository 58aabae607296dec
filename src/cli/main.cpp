// The shadowproof executable: dispatches to the registered subcommands.
// Exit codes: 0 success, 1 a check failed, 2 bad input or usage, 3 an internal error (a bug).
#include <algorithm>
#include <iostream>

#include "command.h"
#include "html_report.h"
#include "shadowproof/core/error.h"

namespace shadowproof::cli {

std::vector<command>& command_list() {
  static std::vector<command> commands;
  return commands;
}

}  // namespace shadowproof::cli

int main(int argc, char** argv) {
  using namespace shadowproof;
  CLI::App app{"shadowproof: exact planar shadows, reflections and projections, and a grader "
               "for float implementations against the exact answer.\n"
               "Numbers: 42, 0.1 (= 1/10), -2.5e-3, 1/3, 0x1.8p-3, f32:0.1, f64:0.1."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "shadowproof " SHADOWPROOF_VERSION, "print the version and exit");
  cli::global_options globals;
  globals.command_line = cli::shell_command_line(argc, argv);
  app.add_option("--max-bits", globals.limits.max_bits,
                 "largest numerator/denominator of any input number, in bits")
      ->capture_default_str();

  auto commands = cli::command_list();
  std::sort(commands.begin(), commands.end(),
            [](const cli::command& a, const cli::command& b) { return a.name < b.name; });
  std::function<int()> action;
  for (const auto& c : commands) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    auto run = c.setup(*sub, globals);
    sub->callback([&action, run] { action = run; });
  }

  // The first word that is not an option must name a subcommand; say so plainly if it does not.
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') {
      if (word == "--max-bits") ++i;  // skip its value
      continue;
    }
    const bool known = std::any_of(commands.begin(), commands.end(),
                                   [&](const cli::command& c) { return c.name == word; });
    if (!known) {
      std::string names;
      for (const auto& c : commands) names += (names.empty() ? "" : ", ") + c.name;
      std::cerr << "shadowproof: unknown subcommand '" << word << "' (one of: " << names << ")\n";
      return 2;
    }
    break;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Points at the help of the (sub)command the words got to, not the program's list of them.
    std::string where = "shadowproof";
    for (const CLI::App* at = &app; !at->get_subcommands().empty();) {
      at = at->get_subcommands().front();
      where += " " + at->get_name();
    }
    std::cerr << "shadowproof: " << e.what() << "\n(run '" << where << " --help' for usage)\n";
    return 2;
  } catch (const error& e) {
    std::cerr << "shadowproof: " << e.what() << '\n';
    return 2;
  }

  try {
    return action ? action() : 2;
  } catch (const error& e) {
    std::cerr << "shadowproof: " << e.what() << '\n';
    return 2;
  } catch (const internal_error& e) {
    std::cerr << "shadowproof: " << e.what() << '\n';
    return 3;
  } catch (const std::bad_alloc&) {
    std::cerr << "shadowproof: out of memory; lower the input sizes or --max-bits\n";
    return 2;
  }
}
