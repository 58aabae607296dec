#pragma once
// The --jobs option of the grading subcommands (check, grade, fuzz) and the throughput figure
// `check` prints.
#include <CLI/CLI.hpp>

#include <string>

namespace shadowproof::cli {

/// The most threads --jobs accepts: a cap on what a command line can make the program start.
constexpr unsigned max_jobs = 256;

/// Adds --jobs N (1 ≤ N ≤ max_jobs) writing into `jobs`; left unset, `jobs` keeps 0, which the
/// grading functions read as "the number of processors" (default_jobs()). Reports do not
/// depend on N.
void add_jobs_option(CLI::App& app, unsigned& jobs);

/// "N cases/s" for `cases` graded in `seconds`, N with three significant digits and a k/M/G
/// prefix ("1.23 M cases/s"); "cases/s not measured" when the time is too short to read.
std::string throughput_text(double cases, double seconds);

}  // namespace shadowproof::cli
