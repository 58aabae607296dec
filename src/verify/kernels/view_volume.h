#pragma once
// What the view-volume kernels (ortho, frustum, perspective) share: the NDC depths of the near
// and far planes, and the layout of a row that a flat extent leaves undefined.
#include "fraction_form.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// z_near and z_far of the depth convention as small integers (project.h's ndc_depth_range).
struct depth_ndc {
  int near_ndc, far_ndc;
};
inline depth_ndc depth_of(const conventions& conv) {
  switch (conv.depth) {
    case depth_convention::gl: return {-1, 1};
    case depth_convention::d3d: return {0, 1};
    case depth_convention::reverse_z: return {1, 0};
  }
  return {-1, 1};
}

/// The depth row of a central projection looking down −z (project.h):
///   A = (n z_near − f z_far)/(f − n),  B = n f (z_near − z_far)/(f − n).
template <class N>
void perspective_depth_numerators(const N& n, const N& f, const conventions& conv, N& A, N& B) {
  const depth_ndc z = depth_of(conv);
  A = times(z.near_ndc, n) - times(z.far_ndc, f);
  B = times(z.near_ndc - z.far_ndc, exact_product(n, f));
}

/// Row k of a view volume divides its diagonal entry and its offset entry (row k, column
/// `offset`) by denominator k; a flat extent (denominator 0) undefines both, except that a
/// builder declared symmetric has a zero centre offset by construction on the x and y rows
/// (view_volume.h of the operations).
inline void flat_row_layout(fraction_layout& l, int k, int offset, const conventions& conv) {
  l.zero_when_undefined[k * 4 + offset] = conv.symmetric_view && k < 2;
  l.on_zero[k] = zero_denominator::undefines_entries;
}

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
