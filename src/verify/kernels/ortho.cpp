// The ortho kernels (the formula: ortho.h).
#include "ortho.h"

#include "fraction_kernel.h"

namespace shadowproof::detail {

bool fast_ortho_f32(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<ortho_form, float>(in, conv, out);
}

bool fast_ortho_f64(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<ortho_form, double>(in, conv, out);
}

}  // namespace shadowproof::detail
