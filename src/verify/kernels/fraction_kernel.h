#pragma once
// The kernels for one case of a fraction form (fraction_form.h): the filter number first, exact
// expansions when a sign or a rounding is undecided, false only when the inputs are outside the
// kernels' range or an expansion overflows (the generic oracle then decides).
#include <cstdint>
#include <type_traits>

#include "../oracle_fast.h"
#include "exact_rounding.h"
#include "fraction_form.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// The filter number of an output type for one case.
template <class F>
using filter_number = filter_number_of<F, double>;

/// Whether a form has a rescale(double* x) for the kernel for one case (an exact scaling of
/// inputs the outputs do not depend on).
template <class Form, class = void>
struct rescales : std::false_type {};
template <class Form>
struct rescales<Form, std::void_t<decltype(&Form::rescale)>> : std::true_type {};

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
  copy_inputs(in, Form::inputs, x);
  Form::canonical_inputs(x, conv);
  if constexpr (rescales<Form>::value) Form::rescale(x);
  if (!kernel_inputs<F, Form::degree, Form::inputs>(x)) return false;
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


}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
