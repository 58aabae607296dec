#pragma once
/// The exact answer of a case as rationals: what the grader rounds, before any rounding.
#include <optional>
#include <vector>

#include "shadowproof/core/number.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof {

/// The exact outputs for c's very inputs, in the canonical layout (row-major, column vectors),
/// for the conventions that change the values: a directional light given along its rays is
/// negated, projections use conv.depth, clamps_behind_receiver keeps a point behind the
/// receiver in place. signature(c.op).output_count entries; an entry is nothing where no exact
/// value exists (the image of a point level with a point light, the divided-by-zero entries of
/// a flat view volume, the normal matrix of a singular matrix). grade_case rounds exactly these
/// (times λ when it grades up to scale). Preconditions as for grade_case: c's inputs name an
/// instance of its operation (invalid_inputs_reason(c) is empty).
std::vector<std::optional<rational>> exact_answer(const test_case& c, const conventions& conv);

}  // namespace shadowproof
