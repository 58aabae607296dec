#pragma once
// reflection-matrix kernels: M = [I − 2 n nᵀ/|n|², −2 d n/|n|²; 0 0 0 1] for P = (n, d). Entry
// (i, j) of the upper 3x3 block is (δ_ij |n|² − 2 n_i n_j)/|n|², which for i = j is
// (Σ_{k≠i} n_k² − n_i²)/|n|²; the offset column is −2 d n_i/|n|². One shared denominator |n|²,
// never 0 for a valid plane.
#include <cmath>
#include "fraction_form.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

struct reflection_matrix_form {
  static constexpr int inputs = 4, entries = 16, denominators = 1;
  static constexpr int degree = 2;

  template <class R>
  static void canonical_inputs(R*, const conventions&) {}
  // The mirror does not depend on the scale of P: P is scaled by the power of two that brings
  // its largest normal component into [1, 2), when that is exact for every component, so that
  // normals whose |n|² would over- or underflow still have a kernel (the kernel for one case
  // calls it; the batch filter leaves such cases to that kernel).
  static void rescale(double* x) {
    const double in[4] = {x[0], x[1], x[2], x[3]};
    const double largest = std::fmax(std::fabs(in[0]), std::fmax(std::fabs(in[1]), std::fabs(in[2])));
    if (!(largest > 0) || !std::isfinite(largest)) return;
    int exponent;
    std::frexp(largest, &exponent);
    bool exact = true;
    double scaled_in[4];
    for (int i = 0; i < 4; ++i) {
      scaled_in[i] = std::ldexp(in[i], 1 - exponent);
      exact = exact && std::ldexp(scaled_in[i], exponent - 1) == in[i] && std::isfinite(scaled_in[i]);
    }
    if (exact) copy_inputs(scaled_in, 4, x);
  }
  template <class R>
  static auto undefined_case(const R* x, const conventions&) { return no_lanes(x[0]); }
  static constexpr signed char E = exact_entry;  // zeros, ±1 and inputs
  static constexpr signed char denominator_of[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, E, E, E, E};
  static fraction_layout layout(const conventions&) {
    fraction_layout l = layout_of<reflection_matrix_form>();
    l.on_zero[0] = zero_denominator::impossible;  // a zero normal names no mirror
    return l;
  }

  template <class N>
  static void evaluate(const N* P, const conventions&, N* num, N* den) {
    const N squares[3] = {exact_product(P[0], P[0]), exact_product(P[1], P[1]), exact_product(P[2], P[2])};
    den[0] = squares[0] + squares[1] + squares[2];
    SHADOWPROOF_UNROLL
    for (int i = 0; i < 3; ++i) {
      SHADOWPROOF_UNROLL
      for (int j = 0; j < 3; ++j) num[i * 4 + j] = -scaled(exact_product(P[i], P[j]), 1);
      num[i * 5] = squares[(i + 1) % 3] + squares[(i + 2) % 3] - squares[i];  // the diagonal
      num[i * 4 + 3] = -scaled(exact_product(P[3], P[i]), 1);
    }
    SHADOWPROOF_UNROLL
    for (int j = 0; j < 3; ++j) num[12 + j] = N(0.0);
    num[15] = N(1.0);
  }
};

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
