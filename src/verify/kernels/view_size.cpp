// ortho-size and perspective-size (size = w, h, n, f) through the box kernels: their exact
// outputs are, by definition (operations/view_size.cpp), ortho's and frustum's for the box
// (−w/2, w/2, −h/2, h/2, n, f) with symmetric_view set. Declines, leaving the case to the
// generic oracle, where that reading does not hold: a negative w or h (no projection, which
// the box would not say) or a half that is not exact in the case's type.
#include <cmath>

#include "../oracle_fast.h"

namespace shadowproof::detail {
namespace {

using box_kernel = bool (*)(const double*, const conventions&, fast_reference&);

template <class F>
bool through_box(const double* in, const conventions& conv, fast_reference& out, box_kernel kernel) {
  const double w = in[0], h = in[1];
  if (!(w >= 0) || !(h >= 0)) return false;
  const double half_w = w / 2, half_h = h / 2;
  // Halving is exact unless it drops the last bit of a subnormal of the type.
  if (static_cast<F>(half_w) * 2 != static_cast<F>(w) || static_cast<F>(half_h) * 2 != static_cast<F>(h)) return false;
  const double box[6] = {-half_w, half_w, -half_h, half_h, in[2], in[3]};
  conventions symmetric = conv;
  symmetric.symmetric_view = true;
  return kernel(box, symmetric, out);
}

}  // namespace

bool fast_ortho_size_f32(const double* in, const conventions& conv, fast_reference& out) {
  return through_box<float>(in, conv, out, fast_ortho_f32);
}
bool fast_ortho_size_f64(const double* in, const conventions& conv, fast_reference& out) {
  return through_box<double>(in, conv, out, fast_ortho_f64);
}
bool fast_perspective_size_f32(const double* in, const conventions& conv, fast_reference& out) {
  return through_box<float>(in, conv, out, fast_frustum_f32);
}
bool fast_perspective_size_f64(const double* in, const conventions& conv, fast_reference& out) {
  return through_box<double>(in, conv, out, fast_frustum_f64);
}

}  // namespace shadowproof::detail
