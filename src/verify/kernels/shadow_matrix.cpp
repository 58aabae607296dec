// shadow-matrix kernels: M = (P·L) I − L Pᵀ. An off-diagonal entry is one product −L_r P_c;
// the diagonal entry r is P·L − L_r P_r = Σ_{j≠r} P_j L_j exactly (the same exact value, one
// term fewer). No denominators: every entry is a short sum of exact products.
#include "fraction_kernel.h"

namespace shadowproof::detail {
namespace {

struct shadow_matrix_form {
  static constexpr int inputs = 8, entries = 16, denominators = 0;
  static constexpr int degree = 2;

  // The canonical light: a directional light given along its rays is negated (exact).
  static void prepare(const double* in, const conventions& conv, double* x) {
    copy_inputs(in, 8, x);
    if (conv.light == light_sign::along_rays && in[7] == 0)
      for (int i = 4; i < 7; ++i) x[i] = -in[i];
  }
  static bool undefined_case(const double*, const conventions&) { return false; }
  static fraction_layout layout(const conventions&) { return {}; }

  template <class N>
  static void evaluate(const N* x, const conventions&, N* num, N*) {
    const N* P = x;
    const N* L = x + 4;
    N products[4];
    for (int j = 0; j < 4; ++j) products[j] = exact_product(P[j], L[j]);
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        if (r != c) {
          num[r * 4 + c] = -exact_product(L[r], P[c]);
          continue;
        }
        N sum(0.0);
        bool first = true;
        for (int j = 0; j < 4; ++j) {
          if (j == r) continue;
          sum = first ? products[j] : sum + products[j];
          first = false;
        }
        num[r * 4 + c] = sum;
      }
  }
};

}  // namespace

bool fast_shadow_matrix_f32(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<shadow_matrix_form, float>(in, conv, out);
}

bool fast_shadow_matrix_f64(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<shadow_matrix_form, double>(in, conv, out);
}

}  // namespace shadowproof::detail
