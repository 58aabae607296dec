#pragma once
// Dedicated sensitivity kernels of the filtered oracle: closed forms of D_i = Σ_j |∂f_i/∂x_j| |x_j|
// (docs/verdicts.md) for the operations whose outputs are checked most often, bounded in
// floating point, so that a verdict rarely needs the generic derivatives (dual.h). Each kernel
// computes with midpoint-radius numbers (`bounded`: a value and a bound on its distance to the
// exact one); it returns false when it cannot bound (extreme magnitudes, a class it does not
// cover), and the generic derivatives decide. tests/test_verdicts.cpp checks every bound against
// the exact derivatives.
#include <array>
#include <bitset>
#include <optional>

#include "dual.h"
#include "shadowproof/constructions/classify.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof::detail {

/// What a kernel knows about a case's conditioning.
struct sensitivity_bounds {
  std::array<double, 16> lo{}, hi{};         ///< lo ≤ D_i ≤ hi for the canonical outputs asked for
  /// When `values`: f_lo ≤ f_i ≤ f_hi for the outputs asked for, tighter than the correct
  /// rounding's half ulp (the verdicts compare |g − f| with c·u (|f| + D) and need f closely).
  std::array<long double, 16> f_lo{}, f_hi{};
  bool values = false;
  noted near_singular = noted::undecided;    ///< the case's divisor within c·u of vanishing
  /// Besides moderate inputs and outputs (in_range below), what the kernel's formula needs to stay
  /// within the type's range (the normal matrix: a moderate det A).
  bool formula_in_range = true;
};


/// The kernel's question: the case, the canonical outputs correctly rounded (`reference`; the
/// kernels may use them for the exact values, within half an ulp), the exact class of a
/// shadow-point case, the outputs asked for (canonical indices), and the operation's c.
struct sensitivity_query {
  const test_case* c;
  const conventions* conv;
  const double* reference;
  std::optional<point_class> cls;
  std::bitset<16> wanted;
  int stable_constant;
};

using sensitivity_kernel = bool (*)(const sensitivity_query& q, sensitivity_bounds& out);

/// No intermediate of the operation's own formula leaves the type's range: every nonzero input
/// within 2^(emin/5) … 2^(emax/5) (no product of five of them over- or underflows), every output's
/// reference 0 or well inside the normal range, and what the kernel adds (formula_in_range).
bool in_range(const sensitivity_query& q, std::size_t outputs, const sensitivity_bounds& b);

bool shadow_matrix_sensitivity(const sensitivity_query& q, sensitivity_bounds& out);
bool shadow_point_sensitivity(const sensitivity_query& q, sensitivity_bounds& out);
bool reflection_matrix_sensitivity(const sensitivity_query& q, sensitivity_bounds& out);
bool normal_matrix_sensitivity(const sensitivity_query& q, sensitivity_bounds& out);

}  // namespace shadowproof::detail
