#pragma once
// How a kernel whose outputs are fractions of polynomials in the inputs describes itself:
// each canonical output is a polynomial, or a polynomial over one of a few shared
// denominators (r − l, det A, |n|², …). An operation describes itself as a "form":
//
//   struct my_form {
//     static constexpr int inputs = …, entries = …, denominators = …;
//     // The largest degree of a product of inputs in any numerator or denominator (the f64
//     // kernels' input range depends on it, bounded.h).
//     static constexpr int degree = …;
//     // The inputs the formula reads, in place, from the case's: an exact transformation (the
//     // canonical light of a light given along its rays, a plane scaled by a power of two).
//     // R is double or a vector of doubles (lanes.h).
//     template <class R> static void canonical_inputs(R* x, const conventions&);
//     // True (lane by lane) when the inputs alone leave every output undefined (near ≤ 0).
//     template <class R> static auto undefined_case(const R* x, const conventions&);
//     // Which denominator each entry has, and what a zero denominator means.
//     static fraction_layout layout(const conventions&);
//     // Numerators and denominators over any number type N: bounded (f32 filter),
//     // bounded_pair (f64 filter), expansion (exact), or their vector forms (batch_avx2.cpp).
//     template <class N> static void evaluate(const N* x, const conventions&, N* num, N* den);
//   };
//
// Its kernels for one case are fraction_kernel<my_form, float> and <my_form, double>
// (fraction_kernel.h); filter_lanes below is its filter stage over a vector of cases.
#include <cstdint>
#include <type_traits>
#include <utility>

#include "bounded.h"
#include "expansion.h"
#include "lanes.h"
#include "rounding.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

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

/// In Form::denominator_of: the entry is an input or a small integer, exactly a value of both
/// output types, so it is its own correct rounding (no test needed).
constexpr signed char exact_entry = -2;

/// In Form::denominator_of: the entry is a quotient over denominator d whose numerator and
/// denominator are, by the formula, exact values of the output type (2 over an input w, an
/// input over an input). The filter over lanes divides once in that type, which IEEE
/// arithmetic rounds correctly, and checks lane by lane that both are exact values of it and
/// the quotient a normal number (rounding.h's round_direct_quotient); the kernel for one case
/// takes it as a quotient over d.
constexpr signed char direct_over(int d) { return static_cast<signed char>(16 + d); }
/// The denominator of a denominator_of code (d for direct_over(d)), and whether it is direct.
constexpr int denominator_index(signed char code) { return code >= 16 ? code - 16 : code; }
constexpr bool is_direct(signed char code) { return code >= 16; }

/// A layout with the form's denominators (Form::denominator_of, a constant array so that the
/// filter over lanes picks each entry's rounding at compile time), nothing else set.
template <class Form>
fraction_layout layout_of() {
  fraction_layout l;
  for (int j = 0; j < Form::entries; ++j)
    l.denominator[j] = static_cast<signed char>(denominator_index(Form::denominator_of[j]));
  return l;
}

/// Whether an entry of the form divides by denominator d other than directly: only those need
/// d prepared (its reciprocal and the bound's).
template <class Form>
constexpr bool prepared_denominator(int d) {
  for (int j = 0; j < Form::entries; ++j)
    if (Form::denominator_of[j] == d) return true;
  return false;
}

// ----------------------------------------------------------------------------------------------
// Small exact helpers for formulas written over N.

/// c · x for a constant c ∈ {−2, −1, 0, 1, 2}: exact in every number type, and without a
/// branch (scaled_by multiplies by c).
template <class N>
N times(int c, const N& x) {
  return scaled_by(x, static_cast<double>(c));
}

/// x[0..n) = in[0..n).
inline void copy_inputs(const double* in, int n, double* x) {
  for (int i = 0; i < n; ++i) x[i] = in[i];
}

/// The filter number of an output type over the real type R: bounded for float, bounded_pair
/// for double.
template <class F, class R>
using filter_number_of = std::conditional_t<std::is_same_v<F, float>, basic_bounded<R>, basic_bounded_pair<R>>;

/// Inputs the kernels of type F accept in polynomials of degree ≤ `degree`, lane by lane:
/// floats for f32 (every product of two is exact in a double), doubles in bounded.h's range
/// for f64.
template <class F, int degree, int n, class R>
auto kernel_inputs(const R* x) {
  auto ok = !no_lanes(x[0]);  // true in every lane
  SHADOWPROOF_UNROLL
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_same_v<F, float>) ok = ok & f32_input_in_range(x[i]);
    else ok = ok & f64_input_in_range<degree>(x[i]);
  }
  return ok;
}

/// Rounds entry J of a form over its denominator, chosen at compile time, into values[J], and
/// narrows the mask ok to the lanes decided.
template <class Form, class F, int J, class N, class D, class R, class Mask>
void round_entry(const N* num, const N* den, const D* prepared_den, R* values, Mask& ok) {
  constexpr signed char code = Form::denominator_of[J];
  constexpr int d = denominator_index(code);
  if constexpr (code == exact_entry) values[J] = select(first_of(num[J]) == R(0.0), R(0.0), first_of(num[J]));
  else if constexpr (d < 0) ok = ok & round_value(num[J], values[J]);
  else if constexpr (is_direct(code)) ok = ok & round_direct_quotient<F>(num[J], den[d], values[J]);
  else ok = ok & round_quotient(num[J], prepared_den[d], values[J]);
}
template <class Form, class F, class N, class D, class R, class Mask, int... J>
void round_entries(const N* num, const N* den, const D* prepared_den, R* values, Mask& ok,
                   std::integer_sequence<int, J...>) {
  (round_entry<Form, F, J>(num, den, prepared_den, values, ok), ...);
}

/// The filter stage of a fraction form over a vector of cases (or one, R = double), without a
/// branch on the values: the canonical outputs in `values`, and a mask of the lanes where every
/// one is decided. A lane with a zero or undecided denominator, an undefined case or inputs out
/// of range is left undecided (the kernel for one case settles it).
template <class Form, class F, class R>
auto filter_lanes(R* x, const conventions& conv, R* values) {
  using N = filter_number_of<F, R>;
  Form::canonical_inputs(x, conv);
  auto ok = kernel_inputs<F, Form::degree, Form::inputs>(x) & !Form::undefined_case(x, conv);
  constexpr int dens = Form::denominators > 0 ? Form::denominators : 1;
  N xs[Form::inputs];
  SHADOWPROOF_UNROLL
  for (int i = 0; i < Form::inputs; ++i) xs[i] = N(x[i]);
  N num[Form::entries], den[dens];
  Form::template evaluate<N>(xs, conv, num, den);
  decltype(prepare(N())) prepared_den[dens];
  SHADOWPROOF_UNROLL
  for (int d = 0; d < Form::denominators; ++d) {
    ok = ok & nonzero(den[d]);
    if (prepared_denominator<Form>(d)) prepared_den[d] = prepare(den[d]);
  }
  round_entries<Form, F>(num, den, prepared_den, values, ok, std::make_integer_sequence<int, Form::entries>());
  return ok;
}

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
