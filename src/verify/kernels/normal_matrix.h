#pragma once
// normal-matrix kernels: G = (A⁻¹)ᵀ = cof(A)/det A for a 3x3 A (row by row). The cofactor
// cof(i, j) = a[i+1][j+1] a[i+2][j+2] − a[i+1][j+2] a[i+2][j+1] (indices mod 3, the sign comes
// from the cyclic order) is a difference of two exact products; det A = Σ_j a[0][j] cof(0, j).
// det A = 0: no inverse, every output undefined.
#include "fraction_form.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

struct normal_matrix_form {
  static constexpr int inputs = 9, entries = 9, denominators = 1;
  static constexpr int degree = 3;

  template <class R>
  static void canonical_inputs(R*, const conventions&) {}
  template <class R>
  static auto undefined_case(const R* x, const conventions&) { return no_lanes(x[0]); }
  static constexpr signed char denominator_of[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  static fraction_layout layout(const conventions&) {
    fraction_layout l = layout_of<normal_matrix_form>();
    l.on_zero[0] = zero_denominator::undefines_case;
    return l;
  }

  template <class N>
  static void evaluate(const N* a, const conventions&, N* num, N* den) {
    auto at = [&](int i, int j) -> const N& { return a[(i % 3) * 3 + (j % 3)]; };
    SHADOWPROOF_UNROLL
    for (int i = 0; i < 3; ++i)
      SHADOWPROOF_UNROLL
      for (int j = 0; j < 3; ++j)
        num[i * 3 + j] = exact_product(at(i + 1, j + 1), at(i + 2, j + 2)) - exact_product(at(i + 1, j + 2), at(i + 2, j + 1));
    den[0] = a[0] * num[0] + a[1] * num[1] + a[2] * num[2];
  }
};

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
