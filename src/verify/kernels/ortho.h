#pragma once
// ortho kernels: orthographic(l, r, b, t, n, f, depth) (project.h):
//   [ 2/(r−l)  0        0  −(r+l)/(r−l) ]
//   [ 0        2/(t−b)  0  −(t+b)/(t−b) ]      A = (z_near − z_far)/(f − n)
//   [ 0        0        A  (z_near f − z_far n)/(f − n) ]    (= z_near + A n)
//   [ 0        0        0  1 ]
// Three denominators, r − l, t − b and f − n; a zero one undefines its row's two entries.
#include "view_volume.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

struct ortho_form {
  static constexpr int inputs = 6, entries = 16, denominators = 3;
  static constexpr int degree = 1;

  template <class R>
  static void canonical_inputs(R*, const conventions&) {}
  template <class R>
  static auto undefined_case(const R* x, const conventions&) { return no_lanes(x[0]); }
  static constexpr signed char E = exact_entry;  // zeros, ±1 and inputs
  static constexpr signed char denominator_of[16] = {0, E, E, 0, E, 1, E, 1, E, E, 2, 2, E, E, E, E};
  static fraction_layout layout(const conventions& conv) {
    fraction_layout l = layout_of<ortho_form>();
    for (int k = 0; k < 3; ++k) flat_row_layout(l, k, 3, conv);
    return l;
  }

  template <class N>
  static void evaluate(const N* x, const conventions& conv, N* num, N* den) {
    SHADOWPROOF_UNROLL
    for (int j = 0; j < 16; ++j) num[j] = N(0.0);
    SHADOWPROOF_UNROLL
    for (int k = 0; k < 2; ++k) {
      const N& lo = x[2 * k];
      const N& hi = x[2 * k + 1];
      den[k] = hi - lo;
      num[k * 4 + k] = N(2.0);
      num[k * 4 + 3] = -(hi + lo);
    }
    const N& n = x[4];
    const N& f = x[5];
    const depth_ndc z = depth_of(conv);
    den[2] = f - n;
    num[10] = N(static_cast<double>(z.near_ndc - z.far_ndc));
    num[11] = times(z.near_ndc, f) - times(z.far_ndc, n);
    num[15] = N(1.0);
  }
};

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
