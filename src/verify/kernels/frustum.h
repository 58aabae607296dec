#pragma once
// frustum kernels: frustum(l, r, b, t, n, f, depth) (project.h):
//   [ 2n/(r−l)  0         (r+l)/(r−l)  0 ]
//   [ 0         2n/(t−b)  (t+b)/(t−b)  0 ]     A = (n z_near − f z_far)/(f − n)
//   [ 0         0         A            B ]     B = n f (z_near − z_far)/(f − n)
//   [ 0         0         −1           0 ]
// n ≤ 0 or f ≤ 0 admits no projection (every output undefined); a zero r − l, t − b or f − n
// undefines its row's two entries.
#include "view_volume.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

struct frustum_form {
  static constexpr int inputs = 6, entries = 16, denominators = 3;
  static constexpr int degree = 2;

  template <class R>
  static void canonical_inputs(R*, const conventions&) {}
  template <class R>
  static auto undefined_case(const R* x, const conventions&) {
    return (x[4] <= R(0.0)) | (x[5] <= R(0.0));
  }
  static constexpr signed char E = exact_entry;  // zeros, ±1 and inputs
  static constexpr signed char denominator_of[16] = {0, E, 0, E, E, 1, 1, E, E, E, 2, 2, E, E, E, E};
  static fraction_layout layout(const conventions& conv) {
    fraction_layout l = layout_of<frustum_form>();
    flat_row_layout(l, 0, 2, conv);
    flat_row_layout(l, 1, 2, conv);
    flat_row_layout(l, 2, 3, conv);
    return l;
  }

  template <class N>
  static void evaluate(const N* x, const conventions& conv, N* num, N* den) {
    SHADOWPROOF_UNROLL
    for (int j = 0; j < 16; ++j) num[j] = N(0.0);
    const N& n = x[4];
    const N& f = x[5];
    SHADOWPROOF_UNROLL
    for (int k = 0; k < 2; ++k) {
      const N& lo = x[2 * k];
      const N& hi = x[2 * k + 1];
      den[k] = hi - lo;
      num[k * 4 + k] = scaled(n, 1);
      num[k * 4 + 2] = hi + lo;
    }
    den[2] = f - n;
    perspective_depth_numerators(n, f, conv, num[10], num[11]);
    num[14] = N(-1.0);
  }
};

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
