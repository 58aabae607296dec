// The generic batch filters (batch.h): blocks of cases in local columns, one case per
// iteration of a loop whose body has no branch on the values, for the compiler to vectorise on
// the build's baseline target (GCC 12 -O3 vectorises those of ortho, frustum, perspective and
// the f32 shadow and normal matrices with SSE2; the others run as straight-line scalar code).
// Also the run-time check for the AVX2 variant.
#include "batch_filters.h"

namespace shadowproof::detail {

batch_filter generic_batch_filter(operation op, scalar_type type) { return batch_filter_over<double>(op, type); }

batch_filter generic_image_filter(scalar_type type) { return image_filter_over<double>(type); }

bool avx2_supported() {
#if defined(__x86_64__) && defined(__GNUC__)
  static const bool supported = [] {
    __builtin_cpu_init();  // may run before the library's own initialisation
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return supported;
#else
  return false;
#endif
}

}  // namespace shadowproof::detail
