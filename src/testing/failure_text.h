#pragma once
// The text of a failure: which entries, what the routine gave, the exact value, its correct
// rounding, the ulps, and the command that prints the exact answer.
#include <string>

#include "judgement.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof::detail {

/// "plane (0, 1, 0, 0), light (2, 5, 1, 1)": the inputs by group, as exact rationals.
std::string inputs_text(const test_case& c);

/// The conventions that differ from the library's, as words ("column-major, up to scale"),
/// or an empty string.
std::string conventions_text(const conventions& conv, operation op);

/// Lines (each ending in '\n') describing a failing case: one per failing entry, the scale when
/// graded up to scale, a misclassification, the inputs and the reproducer command.
std::string failure_text(const test_case& c, const conventions& conv, const double* got, const case_judgement& j);

}  // namespace shadowproof::detail
