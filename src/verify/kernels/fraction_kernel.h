#pragma once
// The driver shared by every kernel whose outputs are fractions of polynomials in the inputs:
// each canonical output is a polynomial, or a polynomial over one of a few shared
// denominators (r − l, det A, |n|², …). An operation describes itself as a "form":
//
//   struct my_form {
//     static constexpr int inputs = …, entries = …, denominators = …;
//     // The largest degree of a product of inputs in any numerator or denominator (the f64
//     // kernels' input range depends on it, bounded.h).
//     static constexpr int degree = …;
//     // The inputs the formula reads, from the case's (an exact transformation: the canonical
//     // light of a light given along its rays, a plane scaled by a power of two).
//     static void prepare(const double* in, const conventions&, double* x);
//     // True when the inputs alone leave every output undefined (near plane ≤ 0).
//     static bool undefined_case(const double* x, const conventions&);
//     // Which denominator each entry has, and what a zero denominator means.
//     static fraction_layout layout(const conventions&);
//     // Numerators and denominators over any number type N: bounded (f32 filter),
//     // bounded_pair (f64 filter), expansion (exact), or a vector of them (batch.h).
//     template <class N> static void evaluate(const N* x, const conventions&, N* num, N* den);
//   };
//
// and its kernels are fraction_kernel<my_form, float> and <my_form, double>: the filter number
// first, exact expansions when a sign or a rounding is undecided, false only when the inputs
// are outside the kernels' range or an expansion overflows (the generic oracle then decides).
#include <cstdint>

#include "../oracle_fast.h"
#include "bounded.h"
#include "exact_rounding.h"
#include "expansion.h"
#include "rounding.h"
#include "shadowproof/core/number.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof::detail {

/// What an exactly zero denominator means.
enum class zero_denominator : std::uint8_t {
  undefines_entries,  ///< the entries over it do not exist (a flat view volume's row)
  undefines_case,     ///< no output exists (a singular matrix has no inverse)
  impossible,         ///< the inputs are invalid (a zero normal): leave the case to the generic oracle
};

/// The shape of a fraction form's outputs.
struct fraction_layout {
  signed char denominator[16] = {-1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1};  ///< −1: none
  bool zero_when_undefined[16] = {};  ///< the entry is 0 (defined) where its denominator is 0
  zero_denominator on_zero[4] = {};
};

// ----------------------------------------------------------------------------------------------
// Small exact helpers for formulas written over N.

/// c · x for a constant c ∈ {−2, −1, 0, 1, 2} (exact in every number type).
template <class N>
N times(int c, const N& x) {
  switch (c) {
    case 0: return N(0.0);
    case 1: return x;
    case -1: return -x;
    case 2: return scaled(x, 1);
    default: return -scaled(x, 1);  // −2
  }
}

/// The filter number of an output type: bounded for float, bounded_pair for double.
template <class F>
using filter_number = std::conditional_t<std::is_same_v<F, float>, bounded, bounded_pair>;

/// Inputs the kernels of type F accept in polynomials of degree ≤ `degree`: floats for f32
/// (every product of two is exact in a double), doubles in bounded.h's range for f64.
template <class F>
bool kernel_inputs(const double* x, int n, int degree) {
  bool ok = true;
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_same_v<F, float>) ok = ok && representable_in_float(x[i]);
    else ok = ok && f64_input_in_range(x[i], degree);
  }
  return ok;
}

namespace fraction_detail {

inline void set_undefined_case(int entries, fast_reference& out) {
  out.defined = false;
  for (int j = 0; j < entries; ++j) out.value[j] = 0;
}

// Evaluates the form over N and fills the denominators' signs; −1 when a zero denominator
// is impossible, 0 when a sign is undecided, 1 when the entries are to be rounded, 2 when a
// zero denominator left the whole case undefined (already written to out).
template <class Form, class N>
int evaluate_form(const double* x, const conventions& conv, const fraction_layout& layout, N* num, N* den,
                  int* den_sign, fast_reference& out) {
  N xs[Form::inputs];
  for (int i = 0; i < Form::inputs; ++i) xs[i] = N(x[i]);
  Form::template evaluate<N>(xs, conv, num, den);
  for (int d = 0; d < Form::denominators; ++d) {
    if constexpr (std::is_same_v<N, expansion>) den_sign[d] = den[d].sign();
    else den_sign[d] = sign(den[d]);
    if (den_sign[d] == 2) return 0;
    if (den_sign[d] == 0) {
      if (layout.on_zero[d] == zero_denominator::impossible) return -1;
      if (layout.on_zero[d] == zero_denominator::undefines_case) {
        set_undefined_case(Form::entries, out);
        return 2;
      }
    }
  }
  return 1;
}

// An entry over a zero denominator that undefines its entries: 0, and marked undefined unless
// the layout defines it as 0. True when entry j is such an entry.
inline bool over_zero_denominator(int j, const fraction_layout& layout, const int* den_sign, fast_reference& out) {
  const int d = layout.denominator[j];
  if (d < 0 || den_sign[d] != 0) return false;
  out.value[j] = 0;
  if (!layout.zero_when_undefined[j]) out.undefined |= std::uint32_t(1) << j;
  return true;
}

// The filter stage: 1 decided, 0 undecided, −1 for the generic oracle.
template <class Form, class F>
int filter_stage(const double* x, const conventions& conv, const fraction_layout& layout, fast_reference& out) {
  using N = filter_number<F>;
  using prepared = decltype(prepare(N()));
  constexpr int dens = Form::denominators > 0 ? Form::denominators : 1;
  N num[Form::entries], den[dens];
  int den_sign[dens] = {};
  const int shape = evaluate_form<Form>(x, conv, layout, num, den, den_sign, out);
  if (shape != 1) return shape == 2 ? 1 : shape;
  prepared prepared_den[dens];
  for (int d = 0; d < Form::denominators; ++d)
    if (den_sign[d] != 0) prepared_den[d] = prepare(den[d]);
  bool decided = true;
  for (int j = 0; j < Form::entries; ++j) {
    if (over_zero_denominator(j, layout, den_sign, out)) continue;
    const int d = layout.denominator[j];
    decided = decided && (d < 0 ? round_value(num[j], out.value[j]) : round_quotient(num[j], prepared_den[d], out.value[j]));
  }
  return decided ? 1 : 0;
}

// The exact stage: 1 decided, −1 for the generic oracle (an overflowed expansion, or a double
// quotient beyond the boundary test's range).
template <class Form, class F>
int exact_stage(const double* x, const conventions& conv, const fraction_layout& layout, fast_reference& out) {
  constexpr int dens = Form::denominators > 0 ? Form::denominators : 1;
  expansion num[Form::entries], den[dens];
  int den_sign[dens] = {};
  const int shape = evaluate_form<Form>(x, conv, layout, num, den, den_sign, out);
  if (shape != 1) return shape == 2 ? 1 : -1;
  for (int j = 0; j < Form::entries; ++j) {
    if (over_zero_denominator(j, layout, den_sign, out)) continue;
    const int d = layout.denominator[j];
    const bool decided = d < 0 ? round_exact_value<F>(num[j], out.value[j])
                               : round_exact_quotient<F>(num[j], den[d], out.value[j]);
    if (!decided) return -1;
  }
  return 1;
}

}  // namespace fraction_detail

/// The canonical outputs of a fraction form correctly rounded to F (see the top of this file).
template <class Form, class F>
bool fraction_kernel(const double* in, const conventions& conv, fast_reference& out) {
  double x[Form::inputs];
  Form::prepare(in, conv, x);
  if (!kernel_inputs<F>(x, Form::inputs, Form::degree)) return false;
  out = fast_reference{};
  out.count = Form::entries;
  if (Form::undefined_case(x, conv)) {
    fraction_detail::set_undefined_case(Form::entries, out);
    return true;
  }
  const fraction_layout layout = Form::layout(conv);
  const int filtered = kernels_exact_only ? 0 : fraction_detail::filter_stage<Form, F>(x, conv, layout, out);
  if (filtered != 0) return filtered > 0;
  out.undefined = 0;
  out.defined = true;
  return fraction_detail::exact_stage<Form, F>(x, conv, layout, out) > 0;
}

/// The inputs unchanged (most forms).
inline void copy_inputs(const double* in, int n, double* x) {
  for (int i = 0; i < n; ++i) x[i] = in[i];
}

}  // namespace shadowproof::detail
