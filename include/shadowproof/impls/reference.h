#pragma once
/// The correctly rounded references: for any operation, type and declared conventions, an
/// implementation that returns the exact answer correctly rounded (round to nearest, ties to
/// even, with MPFR), and NaN (or the declared sentinel) where the answer does not exist. The
/// grader's fixed point: graded, every case must come out `exact`.
#include "shadowproof/core/number.h"
#include "shadowproof/verify/implementation.h"

namespace shadowproof {

/// The reference for op in type under conv, named "correctly-rounded-<op>-<type>". Its outputs
/// are laid out as conv declares (storage order, vector side), scaled by `scale` before rounding
/// (any non-zero multiple is correct for a homogeneous result), and where the answer does not
/// exist they are NaN, or the declared sentinel (conv.sentinel) when `use_sentinel`.
implementation correctly_rounded_implementation(operation op, scalar_type type, const conventions& conv = {},
                                                const rational& scale = rational(1), bool use_sentinel = false);

}  // namespace shadowproof
