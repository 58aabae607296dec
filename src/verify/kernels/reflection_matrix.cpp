// The reflection-matrix kernels (the formula: reflection_matrix.h).
#include "reflection_matrix.h"

#include "fraction_kernel.h"

namespace shadowproof::detail {

bool fast_reflection_matrix_f32(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<reflection_matrix_form, float>(in, conv, out);
}

bool fast_reflection_matrix_f64(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<reflection_matrix_form, double>(in, conv, out);
}

}  // namespace shadowproof::detail
