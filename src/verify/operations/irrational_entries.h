#pragma once
// What the operations with irrational exact values share (perspective-fov, look-at,
// target-to): their exact outputs are correctly rounding representatives
// (constructions/irrational.h), decided by MPFR enclosures at increasing precision, so only
// the rational oracle computes them; the interval oracles defer to it at once.
#include <type_traits>

#include "../operation_table.h"
#include "shadowproof/constructions/irrational.h"
#include "shadowproof/core/error.h"

namespace shadowproof::detail {

/// Calls `exact()` (the rational computation) for N = rational; for the interval types throws
/// `undecided`, which sends the case to the rational oracle. Grading up to scale would scale
/// the representatives, not the exact values, and could misjudge a rounding: refused.
template <class N, class Exact>
exact_outputs<N> irrational_outputs(const conventions& conv, const char* op, Exact exact) {
  if (conv.homogeneous)
    throw error(errc::verify_irrational_scale,
                std::string(op) + ": its exact values are irrational, so it cannot be graded up to scale "
                                  "(--homogeneous); grade the matrix as it is");
  if constexpr (std::is_same_v<N, rational>) return exact();
  else throw undecided{};
}

}  // namespace shadowproof::detail
