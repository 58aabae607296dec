#pragma once
// Reports shared by `shadowproof check` and `shadowproof grade`: the verdict table, the example
// cases with their reproducers, and the JSON documents. Text is at most `width` columns (100 by
// default); --wide and --json show every field.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/report.h"

namespace shadowproof::cli {

/// The verdict of `--fail-on TEXT` (nothing for an empty text); error verify.unknown_verdict
/// naming the verdicts otherwise.
std::optional<verdict> parse_fail_on(const std::string& text);

/// How much a text report shows.
struct report_style {
  bool wide = false;       ///< every example per verdict, every output of an example, the inputs
  std::size_t width = 100;  ///< the longest line (a reproducer wraps with backslashes)
};

/// One row of the verdict table.
struct verdict_row {
  std::string label;  ///< implementation name, or name and class
  grade_summary summary;
};

/// Finds the case a grade refers to (by id).
using case_lookup = std::function<const test_case&(std::uint64_t id)>;
/// Finds the conventions a case is graded in (by id).
using conventions_lookup = std::function<const conventions&(std::uint64_t id)>;

/// The verdict table: label, verdict, then the cases of each verdict.
void print_verdict_table(std::ostream& out, const std::vector<verdict_row>& rows, const report_style& style);

/// The example cases of one implementation: its worst finite case and its worst non-finite case
/// (wide: one case per verdict worse than faithful), each with the output that decided its
/// verdict, the conditioning and the command that prints the exact answer.
void print_examples(std::ostream& out, const std::string& name, const grade_summary& s, const case_lookup& lookup,
                    const conventions_lookup& conv_of, const report_style& style);

/// A count of ulps: the number itself below 2^16, a power of two above ("2^31.2").
std::string ulps_text(std::uint64_t ulps);
/// x in scientific notation with three significant digits ("3.20e-04"), or inf / nan.
std::string scientific(double x);

/// The command on lines of at most `width` columns, continued with " \" at word boundaries and
/// indented by `indent`; a word longer than a line is cut after a comma with a backslash and
/// continued at column 0, which a POSIX shell joins back into the same word.
std::string wrap_command(const std::string& command, std::size_t indent, std::size_t width);

/// JSON of a summary: cases, verdict, verdicts (counts by name), max_ulps, median_ulps, max_bits,
/// bits_histogram, nonfinite, garbage, misclassified, worst (cases), worst_finite,
/// worst_nonfinite, examples.
nlohmann::json summary_json(const grade_summary& s, const case_lookup& lookup, const conventions_lookup& conv_of);

/// One case as JSON: id, class, closeness, verdict, rejected, the deciding output (name, got,
/// expected, ulps, bits, relative error, condition, backward error), normwise conditioning,
/// scale and pivot, classes, inputs, reproduce, and (wide) every output.
nlohmann::json case_json(const case_grade& g, const test_case& c, const conventions& conv, bool every_output = true);

/// The cases per verdict, by name ({"exact": 12, "faithful": 3, ...}; every verdict present).
nlohmann::json verdict_counts_json(const grade_summary& s);

/// The declared conventions as JSON (storage, vectors, light, depth, sentinel, flags).
nlohmann::json conventions_json(const conventions& c);

}  // namespace shadowproof::cli
