#pragma once
// The batch filters' forms of ortho-size and perspective-size (size = w, h, n, f): by
// definition (operations/view_size.cpp) ortho's and frustum's matrices of the box
// (−w/2, w/2, −h/2, h/2, n, f) with symmetric_view set, written out on the box, so that what the
// symmetry makes exact is not computed:
//   ortho-size:        [ 2/w 0 0 0; 0 2/h 0 0; 0 0 A C; 0 0 0 1 ],   A = (z_near − z_far)/(f − n),
//                                                                     C = (z_near f − z_far n)/(f − n)
//   perspective-size:  [ 2n/w 0 0 0; 0 2n/h 0 0; 0 0 A B; 0 0 −1 0 ] as frustum's A and B
// r − l = w and t − b = h exactly, and the centre offsets (r + l)/(r − l), (t + b)/(t − b) are
// exactly 0 (defined 0 even for a flat extent, as symmetric_view says). 2/w, 2/h, 2n/w and 2n/h
// are quotients of two exact values of the output type: one division in that type
// (fraction_form.h's direct_over). Only the filter over lanes reads these forms, in the lanes
// where w, h ≥ 0 (batch_filters.h's size_op); a negative extent has no projection, and the
// kernels for one case (view_size.cpp) decide it through the box.
#include "view_volume.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// What the two forms share: four inputs, sixteen entries over three denominators, w, h and
/// f − n (entries 0 and 5 one division in the output type, 10 and 11 over f − n, the rest exact),
/// and a zero denominator undefining the entries over it.
template <class Form>
struct size_form_shape {
  static constexpr int inputs = 4, entries = 16, denominators = 3;
  template <class R>
  static void canonical_inputs(R*, const conventions&) {}
  static constexpr signed char E = exact_entry;
  static constexpr signed char denominator_of[16] = {direct_over(0), E, E, E, E, direct_over(1), E, E,
                                                     E,              E, 2, 2, E, E,              E, E};
  static fraction_layout layout(const conventions&) {
    fraction_layout l = layout_of<Form>();
    for (int k = 0; k < 3; ++k) l.on_zero[k] = zero_denominator::undefines_entries;
    return l;
  }
};

struct ortho_size_form : size_form_shape<ortho_size_form> {
  static constexpr int degree = 1;
  template <class R>
  static auto undefined_case(const R* x, const conventions&) { return no_lanes(x[0]); }

  template <class N>
  static void evaluate(const N* x, const conventions& conv, N* num, N* den) {
    SHADOWPROOF_UNROLL
    for (int j = 0; j < 16; ++j) num[j] = N(0.0);
    const N& n = x[2];
    const N& f = x[3];
    const depth_ndc z = depth_of(conv);
    den[0] = x[0];
    den[1] = x[1];
    num[0] = N(2.0);
    num[5] = N(2.0);
    den[2] = f - n;
    num[10] = N(static_cast<double>(z.near_ndc - z.far_ndc));
    num[11] = times(z.near_ndc, f) - times(z.far_ndc, n);
    num[15] = N(1.0);
  }
};

struct perspective_size_form : size_form_shape<perspective_size_form> {
  static constexpr int degree = 2;
  template <class R>
  static auto undefined_case(const R* x, const conventions&) {
    return (x[2] <= R(0.0)) | (x[3] <= R(0.0));
  }

  template <class N>
  static void evaluate(const N* x, const conventions& conv, N* num, N* den) {
    SHADOWPROOF_UNROLL
    for (int j = 0; j < 16; ++j) num[j] = N(0.0);
    const N& n = x[2];
    const N& f = x[3];
    den[0] = x[0];
    den[1] = x[1];
    num[0] = scaled(n, 1);
    num[5] = scaled(n, 1);
    den[2] = f - n;
    perspective_depth_numerators(n, f, conv, num[10], num[11]);
    num[14] = N(-1.0);
  }
};

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
