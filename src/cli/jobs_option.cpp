// --jobs and the throughput figure (jobs_option.h).
#include "jobs_option.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace shadowproof::cli {

void add_jobs_option(CLI::App& app, unsigned& jobs) {
  app.add_option("--jobs", jobs,
                 "grade on this many threads (default: the number of processors); the report is the same "
                 "for any number")
      ->check(CLI::Range(1u, max_jobs));
}

std::string throughput_text(double cases, double seconds) {
  if (!(seconds > 0) || !std::isfinite(cases / seconds)) return "cases/s not measured";
  double rate = cases / seconds;
  const char* prefix = "";
  for (const char* p : {"k", "M", "G"}) {
    if (rate < 999.5) break;
    rate /= 1000;
    prefix = p;
  }
  char number[32];
  std::snprintf(number, sizeof number, "%.3g ", rate);
  return number + std::string(prefix) + (*prefix ? " " : "") + "cases/s";
}

}  // namespace shadowproof::cli
