// The normal-matrix kernels (the formula: normal_matrix.h).
#include "normal_matrix.h"

#include "fraction_kernel.h"

namespace shadowproof::detail {

bool fast_normal_matrix_f32(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<normal_matrix_form, float>(in, conv, out);
}

bool fast_normal_matrix_f64(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<normal_matrix_form, double>(in, conv, out);
}

}  // namespace shadowproof::detail
