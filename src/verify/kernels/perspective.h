#pragma once
// perspective kernels: perspective(c, aspect, n, f, depth) with c = cot(fovy/2) (project.h):
//   [ c/aspect 0 0 0; 0 c 0 0; 0 0 A B; 0 0 −1 0 ], A and B as in frustum over f − n.
// c, aspect, n or f ≤ 0 admits no projection (every output undefined); n = f undefines A and B.
#include "view_volume.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

struct perspective_form {
  static constexpr int inputs = 4, entries = 16, denominators = 2;
  static constexpr int degree = 2;

  template <class R>
  static void canonical_inputs(R*, const conventions&) {}
  template <class R>
  static auto undefined_case(const R* x, const conventions&) {
    return (x[0] <= R(0.0)) | (x[1] <= R(0.0)) | (x[2] <= R(0.0)) | (x[3] <= R(0.0));
  }
  // (0, 0) = c / aspect, a quotient of two inputs (one division in the output type over
  // lanes); (2, 2) and (2, 3) over f − n; (1, 1) = c itself.
  static constexpr signed char E = exact_entry;  // zeros, ±1 and inputs
  static constexpr signed char denominator_of[16] = {direct_over(0), E, E, E, E, E, E, E, E, E, 1, 1, E, E, E, E};
  static fraction_layout layout(const conventions&) {
    fraction_layout l = layout_of<perspective_form>();
    l.on_zero[0] = zero_denominator::impossible;  // aspect > 0 here
    l.on_zero[1] = zero_denominator::undefines_entries;
    return l;
  }

  template <class N>
  static void evaluate(const N* x, const conventions& conv, N* num, N* den) {
    SHADOWPROOF_UNROLL
    for (int j = 0; j < 16; ++j) num[j] = N(0.0);
    const N& n = x[2];
    const N& f = x[3];
    den[0] = x[1];
    num[0] = x[0];
    num[5] = x[0];
    den[1] = f - n;
    perspective_depth_numerators(n, f, conv, num[10], num[11]);
    num[14] = N(-1.0);
  }
};

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
