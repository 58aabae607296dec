#pragma once
// shadow-matrix kernels: M = (P·L) I − L Pᵀ. An off-diagonal entry is one product −L_r P_c,
// whose correct rounding is the IEEE product itself; the diagonal entry r is
// P·L − L_r P_r = Σ_{j≠r} P_j L_j exactly (the same exact value, one term fewer). No
// denominators: every entry is a short sum of exact products.
#include "fraction_form.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

struct shadow_matrix_form {
  static constexpr int inputs = 8, entries = 16, denominators = 0;
  static constexpr int degree = 2;

  // The canonical light: a directional light given along its rays is negated (exact).
  // The canonical light: a directional light given along its rays is negated (exact; a
  // multiplication by ±1, without a branch on the values).
  template <class R>
  static void canonical_inputs(R* x, const conventions& conv) {
    const R flip = select(x[7] == R(0.0), R(conv.light == light_sign::along_rays ? -1.0 : 1.0), R(1.0));
    SHADOWPROOF_UNROLL
    for (int i = 4; i < 7; ++i) x[i] = x[i] * flip;
  }
  template <class R>
  static auto undefined_case(const R* x, const conventions&) { return no_lanes(x[0]); }
  static constexpr signed char denominator_of[16] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1};
  static fraction_layout layout(const conventions&) { return layout_of<shadow_matrix_form>(); }

  template <class N>
  static void evaluate(const N* x, const conventions&, N* num, N*) {
    const N* P = x;
    const N* L = x + 4;
    N products[4];
    SHADOWPROOF_UNROLL
    for (int j = 0; j < 4; ++j) products[j] = exact_product(P[j], L[j]);
    SHADOWPROOF_UNROLL
    for (int r = 0; r < 4; ++r) {
      SHADOWPROOF_UNROLL
      for (int c = 0; c < 4; ++c) num[r * 4 + c] = -rounded_product(L[r], P[c]);  // an output by itself
      num[r * 5] = products[(r + 1) % 4] + products[(r + 2) % 4] + products[(r + 3) % 4];  // the diagonal
    }
  }
};

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
