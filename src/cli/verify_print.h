#pragma once
// Tables, JSON and reproducers shared by `shadowproof check` and `shadowproof grade`.
#include <nlohmann/json.hpp>

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/report.h"

namespace shadowproof::cli {

/// One row of a report: an implementation (or a graded file) on one operation and class.
struct report_row {
  std::string impl;
  operation op;
  scalar_type type;
  std::string cls;  ///< input class name, or "all"
  grade_summary summary;
};

/// Finds the case a grade refers to (by id).
using case_lookup = std::function<const test_case&(std::uint64_t id)>;
/// Finds the conventions a case is graded in (by id).
using conventions_lookup = std::function<const conventions&(std::uint64_t id)>;

/// Fixed-width table: impl, op, class, cases, max ulps, median, max bits, histogram, counts.
void print_table(std::ostream& out, const std::vector<report_row>& rows);

/// The worst case of a grade as a bit-exact reproducer: inputs as hex floats, the output that
/// is furthest off (got vs correctly rounded exact), and the shadowproof command that prints
/// the exact answer.
void print_worst(std::ostream& out, const std::string& title, const case_grade& g, const test_case& c,
                 const conventions& conv = {});

/// JSON of a summary: cases, max_ulps, median_ulps, max_bits, bits_histogram, nonfinite,
/// garbage, misclassified, worst (id, class, output, got, expected, ulps, bits, inputs, ...).
nlohmann::json summary_json(const grade_summary& s, const case_lookup& lookup,
                            const conventions_lookup& conv_of);

/// The declared conventions of an implementation as JSON (storage, vectors, light, depth, flags).
nlohmann::json conventions_json(const conventions& c);

/// One worst case as JSON.
nlohmann::json worst_json(const case_grade& g, const test_case& c, const conventions& conv = {});

}  // namespace shadowproof::cli
