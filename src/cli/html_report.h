#pragma once
// One self-contained HTML page for a check, grade or fuzz run: the verdict of each
// implementation, its bits of error against closeness to degeneracy (inline SVG), its worst
// cases with reproducer commands, and the conventions it declares. No scripts, fonts, images or
// style sheets from elsewhere: the page reads the same offline, attached to a bug or a CI run.
#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace shadowproof::cli {

/// One graded case on the plot: x = log2 closeness to degeneracy (−inf exactly degenerate,
/// NaN unknown), y = bits of error of its worst output; `nonfinite` puts it in the top band
/// (NaN/±Inf where the answer exists, or a finite number where it does not).
struct html_point {
  double closeness = 0;
  double bits = 0;
  bool nonfinite = false;
  std::size_t count = 1;  ///< cases at this point
};

/// Graded cases for a plot, in memory that does not grow with their number: each case falls in
/// a cell of 1/16 of a unit of log2 closeness by 1/8 of a bit of error (finer than the plots'
/// pixels), and a cell is kept once, with its count. At most 70,000 × 513 cells exist (log2
/// closeness of doubles lies within ±2,200; bits of error within 0…64), whatever the case count.
class point_cloud {
 public:
  void add(double closeness, double bits, bool nonfinite);
  /// One point per occupied cell, at the cell's centre, with its count; in cell order.
  std::vector<html_point> points() const;
  /// Every case added.
  std::size_t cases() const { return cases_; }

 private:
  std::map<std::tuple<bool, long long, long long>, std::size_t> cells_;  // (nonfinite, x cell, y cell)
  std::size_t cases_ = 0;
};

/// A worst case: what it is, and the command that prints the exact answer for its inputs.
struct html_case {
  std::string title;                ///< e.g. "wrong: case 17 (near-degenerate), 2^31 ulps"
  std::vector<std::string> details; ///< lines shown as they are (inputs, outputs, exact values)
  std::string reproducer;           ///< a shell command; empty when there is none
};

/// One implementation (or one graded outputs file) of the run.
struct html_section {
  std::string name;
  std::string verdict;                                      ///< its worst case's verdict
  bool failed = false;                                      ///< past the run's threshold
  std::vector<std::pair<std::string, std::string>> facts;   ///< (label, value): operation, type, ulps…
  std::string counts_label = "verdict";                     ///< what `counts` counts cases by
  std::vector<std::pair<std::string, std::size_t>> counts;  ///< cases by verdict (or failure kind)
  std::vector<std::pair<std::string, std::string>> conventions;  ///< as declared
  std::vector<html_point> points;
  std::vector<html_case> worst;
};

struct html_page {
  std::string title;                  ///< e.g. "shadowproof check"
  std::string command;                ///< the command line that made the page
  std::vector<std::string> summary;   ///< lines under the title
  std::vector<html_section> sections;
};

/// Escapes &, <, >, " and ' for HTML text and attribute values.
std::string html_escape(const std::string& text);

/// The page as one HTML document (inline CSS and SVG only).
std::string render_html(const html_page& page);

/// Writes render_html(page) to `path` atomically.
void write_html(const std::string& path, const html_page& page);

/// The command line as the user typed it, quoted for a POSIX shell where needed.
std::string shell_command_line(int argc, const char* const* argv);

}  // namespace shadowproof::cli
