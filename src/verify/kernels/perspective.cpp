// The perspective kernels (the formula: perspective.h).
#include "perspective.h"

#include "fraction_kernel.h"

namespace shadowproof::detail {

bool fast_perspective_f32(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<perspective_form, float>(in, conv, out);
}

bool fast_perspective_f64(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<perspective_form, double>(in, conv, out);
}

}  // namespace shadowproof::detail
