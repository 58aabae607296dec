// The frustum kernels (the formula: frustum.h).
#include "frustum.h"

#include "fraction_kernel.h"

namespace shadowproof::detail {

bool fast_frustum_f32(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<frustum_form, float>(in, conv, out);
}

bool fast_frustum_f64(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<frustum_form, double>(in, conv, out);
}

}  // namespace shadowproof::detail
