// The AVX2 batch filters (batch.h): four cases per vector of doubles, the same formulas and
// rounding tests as one case (written over the real type, lanes.h), with TwoProduct from the
// fused multiply-add. This file alone is compiled for AVX2 and FMA (src/CMakeLists.txt), and
// every inline function it compiles lives in the inline namespace `avx2`, so none of them can
// stand in for a baseline one at link time. It is called only when avx2_supported().
#define SHADOWPROOF_KERNEL_TARGET avx2

#include "batch.h"

#if defined(__AVX2__) && defined(__FMA__)

#include <immintrin.h>

#include <cstddef>
#include <cstdint>

namespace shadowproof::detail {
inline namespace avx2 {

/// Four doubles, and a mask of four lanes (all bits set where true).
struct v4d {
  __m256d v;
  v4d() = default;
  v4d(double x) : v(_mm256_set1_pd(x)) {}  // NOLINT: constants of the formulas broadcast
  explicit v4d(__m256d x) : v(x) {}
};
struct m4d {
  __m256d v;
};

inline v4d operator+(v4d a, v4d b) { return v4d(_mm256_add_pd(a.v, b.v)); }
inline v4d operator-(v4d a, v4d b) { return v4d(_mm256_sub_pd(a.v, b.v)); }
inline v4d operator*(v4d a, v4d b) { return v4d(_mm256_mul_pd(a.v, b.v)); }
inline v4d operator/(v4d a, v4d b) { return v4d(_mm256_div_pd(a.v, b.v)); }
inline v4d operator-(v4d a) { return v4d(_mm256_xor_pd(a.v, _mm256_set1_pd(-0.0))); }
inline m4d operator==(v4d a, v4d b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_EQ_OQ)}; }
inline m4d operator!=(v4d a, v4d b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_NEQ_UQ)}; }
inline m4d operator<(v4d a, v4d b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)}; }
inline m4d operator<=(v4d a, v4d b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)}; }
inline m4d operator>(v4d a, v4d b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)}; }
inline m4d operator>=(v4d a, v4d b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GE_OQ)}; }
inline m4d operator&(m4d a, m4d b) { return {_mm256_and_pd(a.v, b.v)}; }
inline m4d operator|(m4d a, m4d b) { return {_mm256_or_pd(a.v, b.v)}; }
inline m4d operator!(m4d a) { return {_mm256_xor_pd(a.v, _mm256_castsi256_pd(_mm256_set1_epi64x(-1)))}; }

inline v4d magnitude(v4d x) { return v4d(_mm256_andnot_pd(_mm256_set1_pd(-0.0), x.v)); }
inline v4d select(m4d m, v4d a, v4d b) { return v4d(_mm256_blendv_pd(b.v, a.v, m.v)); }
inline m4d select(m4d m, m4d a, m4d b) { return {_mm256_blendv_pd(b.v, a.v, m.v)}; }
inline m4d no_lanes(v4d) { return {_mm256_setzero_pd()}; }
// Round to float (to nearest, ties to even: the MXCSR default) and widen back.
inline v4d round_to_float_value(v4d x) { return v4d(_mm256_cvtps_pd(_mm256_cvtpd_ps(x.v))); }
inline void neighbours(v4d positive, v4d& above, v4d& below) {
  const __m256i bits = _mm256_castpd_si256(positive.v), one = _mm256_set1_epi64x(1);
  above = v4d(_mm256_castsi256_pd(_mm256_add_epi64(bits, one)));
  below = v4d(_mm256_castsi256_pd(_mm256_sub_epi64(bits, one)));
}
// TwoProduct by the fused multiply-add: e = fma(a, b, −p) exactly.
inline void two_product(v4d a, v4d b, v4d& p, v4d& e) {
  p = a * b;
  e = v4d(_mm256_fmsub_pd(a.v, b.v, p.v));
}

}  // namespace avx2
}  // namespace shadowproof::detail

#include "batch_filters.h"

namespace shadowproof::detail {
inline namespace avx2 {

template <>
struct lanes_of<v4d> {
  static constexpr std::size_t width = 4;
  static v4d load(const double* p) { return v4d(_mm256_loadu_pd(p)); }
  static void store(double* p, v4d x) { _mm256_storeu_pd(p, x.v); }
  static void store_mask(std::uint8_t* p, m4d m) {
    const int bits = _mm256_movemask_pd(m.v);
    for (int l = 0; l < 4; ++l) p[l] = static_cast<std::uint8_t>((bits >> l) & 1);
  }
  static void store_classes(std::int8_t* p, v4d x) {
    alignas(32) double lanes[4];
    _mm256_store_pd(lanes, x.v);
    for (int l = 0; l < 4; ++l) p[l] = static_cast<std::int8_t>(lanes[l]);
  }
};

}  // namespace avx2

batch_filter avx2_batch_filter(operation op, scalar_type type) { return batch_filter_over<v4d>(op, type); }

}  // namespace shadowproof::detail

#else  // no AVX2 in this build

namespace shadowproof::detail {
batch_filter avx2_batch_filter(operation, scalar_type) { return nullptr; }
}  // namespace shadowproof::detail

#endif
