#pragma once
/// The exact answer the grader compares against, for tools built on top: the reference
/// implementations that round it, and the `shadowproof exact` command that prints it.
#include <optional>
#include <vector>

#include "shadowproof/constructions/classify.h"
#include "shadowproof/core/number.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof {

/// The exact canonical outputs of a case (row-major for matrices, column vectors), computed by
/// the operation's exact template over rationals under the conventions that change the exact
/// values (light sign, depth range, clamping, symmetric volumes); storage order, vector side and
/// scale are the grader's business and do not appear here.
struct exact_result {
  std::vector<rational> values;   ///< 0 where the output does not exist
  std::vector<bool> defined;      ///< false where the output does not exist (a division by 0)
  std::optional<point_class> cls;  ///< shadow-point: the exact class of the point
};

/// The exact answer for c under conv.
exact_result exact_result_of(const test_case& c, const conventions& conv);

/// The exact answer correctly rounded to c's type (round to nearest, ties to even, an exact 0
/// as +0; ±Inf when it overflows) in the layout `conv` declares (storage order, vector side),
/// NaN where it does not exist: what a correct implementation of conv returns, bit for bit.
/// `scale` multiplies every exact output before rounding (a homogeneous result may be any
/// non-zero multiple).
std::vector<double> correctly_rounded_outputs(const test_case& c, const conventions& conv,
                                              const rational& scale = rational(1));

}  // namespace shadowproof
