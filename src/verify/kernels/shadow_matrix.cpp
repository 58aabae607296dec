// The shadow-matrix kernels (the formula: shadow_matrix.h).
#include "shadow_matrix.h"

#include "fraction_kernel.h"

namespace shadowproof::detail {

bool fast_shadow_matrix_f32(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<shadow_matrix_form, float>(in, conv, out);
}

bool fast_shadow_matrix_f64(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<shadow_matrix_form, double>(in, conv, out);
}

}  // namespace shadowproof::detail
