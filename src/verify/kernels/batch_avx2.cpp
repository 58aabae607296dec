// The AVX2 batch filters (batch.h): four cases per vector of doubles, the same formulas and
// rounding tests as one case (written over the real type, lanes.h), with TwoProduct from the
// fused multiply-add; and the column grader, eight floats or four doubles at a time. This file alone is compiled for AVX2 and FMA (src/CMakeLists.txt), and
// every inline function it compiles lives in the inline namespace `avx2`, so none of them can
// stand in for a baseline one at link time. It is called only when avx2_supported().
#define SHADOWPROOF_KERNEL_TARGET avx2

#include "batch.h"

#if defined(__AVX2__) && defined(__FMA__)

#include <immintrin.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

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
inline bool any_lane(m4d m) { return _mm256_movemask_pd(m.v) != 0; }
inline v4d square_root(v4d x) { return v4d(_mm256_sqrt_pd(x.v)); }  // correctly rounded, as std::sqrt
// Round to float (to nearest, ties to even: the MXCSR default) and widen back.
inline v4d round_to_float_value(v4d x) { return v4d(_mm256_cvtps_pd(_mm256_cvtpd_ps(x.v))); }
inline v4d quotient_in_float(v4d a, v4d b) {
  return v4d(_mm256_cvtps_pd(_mm_div_ps(_mm256_cvtpd_ps(a.v), _mm256_cvtpd_ps(b.v))));
}
inline void neighbours(v4d positive, v4d& above, v4d& below) {
  const __m256i bits = _mm256_castpd_si256(positive.v), one = _mm256_set1_epi64x(1);
  above = v4d(_mm256_castsi256_pd(_mm256_add_epi64(bits, one)));
  below = v4d(_mm256_castsi256_pd(_mm256_sub_epi64(bits, one)));
}
// table[index] in each lane, index an integer in the table's range.
inline v4d gather(const double* table, v4d index) {
  return v4d(_mm256_i32gather_pd(table, _mm256_cvtpd_epi32(index.v), 8));
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

// The distance in ulps of two floats (ulp.h's definition): their bit patterns mapped to a
// signed order-preserving integer (magnitude, negated for negative values), then the absolute
// difference, which is below 2^32, as an unsigned 32-bit number.
inline __m256i float_positions(__m256i bits) {
  const __m256i negative = _mm256_srai_epi32(bits, 31);  // −1 or 0
  const __m256i magnitude = _mm256_and_si256(bits, _mm256_set1_epi32(0x7fffffff));
  return _mm256_sub_epi32(_mm256_xor_si256(magnitude, negative), negative);
}
inline __m256i finite_floats(__m256i bits) {
  const __m256i exponent = _mm256_set1_epi32(0x7f800000);
  return _mm256_xor_si256(_mm256_cmpeq_epi32(_mm256_and_si256(bits, exponent), exponent), _mm256_set1_epi32(-1));
}
// Eight doubles rounded to float (to nearest, as static_cast<float>).
inline __m256i float_bits(const double* p) {
  const __m128 low = _mm256_cvtpd_ps(_mm256_loadu_pd(p)), high = _mm256_cvtpd_ps(_mm256_loadu_pd(p + 4));
  return _mm256_castps_si256(_mm256_insertf128_ps(_mm256_castps128_ps256(low), high, 1));
}
// a > b for unsigned 64-bit lanes.
inline __m256i greater_u64(__m256i a, __m256i b) {
  const __m256i flip = _mm256_set1_epi64x(static_cast<long long>(0x8000000000000000ull));
  return _mm256_cmpgt_epi64(_mm256_xor_si256(a, flip), _mm256_xor_si256(b, flip));
}
// Stores four 64-bit ulps and updates the cases' maximum; returns the mask of lanes where it
// grew (all bits set per 64-bit lane).
inline __m256i store_ulps(__m256i d, std::uint64_t* ulps, std::uint64_t* max_ulps) {
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(ulps), d);
  const __m256i max = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(max_ulps));
  const __m256i worse = greater_u64(d, max);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(max_ulps), _mm256_blendv_epi8(max, d, worse));
  return worse;
}
// Eight 32-bit lane masks (all bits set or clear) as eight bytes, in lane order.
inline __m128i mask_bytes(__m256i masks) {
  const __m128i words = _mm_packs_epi32(_mm256_castsi256_si128(masks), _mm256_extracti128_si256(masks, 1));
  return _mm_packs_epi16(words, words);  // the low eight bytes
}
// Four 64-bit lane masks as four 32-bit lane masks in the low half.
inline __m128i narrow_mask(__m256i masks) {
  const __m256i dwords = _mm256_permutevar8x32_epi32(masks, _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7));
  return _mm256_castsi256_si128(dwords);
}
// flags = 1 where common, 0x80 elsewhere; worst = j where worse: `lanes` bytes each.
inline void store_bytes(__m128i common, __m128i worse, std::size_t j, std::uint8_t* flags, std::uint8_t* worst, int lanes) {
  const __m128i flag = _mm_blendv_epi8(_mm_set1_epi8(static_cast<char>(0x80)), _mm_set1_epi8(1), common);
  std::uint64_t old_worst = 0, flag_bytes, worst_bytes;
  std::memcpy(&old_worst, worst, static_cast<std::size_t>(lanes));
  const __m128i updated = _mm_blendv_epi8(_mm_cvtsi64_si128(static_cast<long long>(old_worst)),
                                          _mm_set1_epi8(static_cast<char>(j)), worse);
  flag_bytes = static_cast<std::uint64_t>(_mm_cvtsi128_si64(flag));
  worst_bytes = static_cast<std::uint64_t>(_mm_cvtsi128_si64(updated));
  std::memcpy(flags, &flag_bytes, static_cast<std::size_t>(lanes));
  std::memcpy(worst, &worst_bytes, static_cast<std::size_t>(lanes));
}
// Bit j of each case's undefined mask is clear, for four cases (the double columns): a 16-byte
// load, so that the last four cases of a column never read past its end.
inline __m128i defined_lanes4(const std::uint32_t* undefined, std::size_t j) {
  const __m128i masks = _mm_loadu_si128(reinterpret_cast<const __m128i*>(undefined));
  const __m128i bit = _mm_and_si128(_mm_srl_epi32(masks, _mm_cvtsi64_si128(static_cast<long long>(j))),
                                    _mm_set1_epi32(1));
  return _mm_cmpeq_epi32(bit, _mm_setzero_si128());
}

// Bit j of each case's undefined mask is clear, for eight cases.
inline __m256i defined_lanes(const std::uint32_t* undefined, std::size_t j) {
  const __m256i masks = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(undefined));
  const __m256i bit = _mm256_and_si256(_mm256_srl_epi32(masks, _mm_cvtsi64_si128(static_cast<long long>(j))),
                                       _mm256_set1_epi32(1));
  return _mm256_cmpeq_epi32(bit, _mm256_setzero_si256());
}

bool grade_column_f32(const double* got, const double* ref, const std::uint32_t* undefined, std::size_t j,
                      std::size_t first, std::size_t end, std::uint64_t* ulps, std::uint8_t* flags,
                      std::uint64_t* max_ulps, std::uint8_t* worst) {
  const std::uint64_t counted_bytes = 0x0101010101010101ull;
  int special = 0;
  std::size_t i = first;
  for (; i + 8 <= end; i += 8) {
    const __m256i a = float_bits(got + i), b = float_bits(ref + i);
    const __m256i defined = defined_lanes(undefined + i, j);
    // The common case of a good implementation: eight finite floats equal to their references,
    // 0 ulps, counted; the maxima stay.
    if (_mm256_movemask_ps(_mm256_castsi256_ps(
            _mm256_and_si256(_mm256_and_si256(defined, finite_floats(a)), _mm256_cmpeq_epi32(a, b)))) == 0xff) {
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(ulps + i), _mm256_setzero_si256());
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(ulps + i + 4), _mm256_setzero_si256());
      std::memcpy(flags + i, &counted_bytes, 8);
      continue;
    }
    const __m256i common = _mm256_and_si256(defined, _mm256_and_si256(finite_floats(a), finite_floats(b)));
    const __m256i x = float_positions(a), y = float_positions(b);
    const __m256i d = _mm256_and_si256(_mm256_sub_epi32(_mm256_max_epi32(x, y), _mm256_min_epi32(x, y)), common);
    const __m256i worse_low = store_ulps(_mm256_cvtepu32_epi64(_mm256_castsi256_si128(d)), ulps + i, max_ulps + i);
    const __m256i worse_high = store_ulps(_mm256_cvtepu32_epi64(_mm256_extracti128_si256(d, 1)), ulps + i + 4, max_ulps + i + 4);
    const __m256i worse = _mm256_setr_m128i(narrow_mask(worse_low), narrow_mask(worse_high));
    store_bytes(mask_bytes(common), mask_bytes(worse), j, flags + i, worst + i, 8);
    special |= _mm256_movemask_ps(_mm256_castsi256_ps(common)) ^ 0xff;
  }
  for (; i < end; ++i) {  // the tail, one case at a time (the same arithmetic)
    const float a = static_cast<float>(got[i]), b = static_cast<float>(ref[i]);
    std::int32_t x, y;
    std::memcpy(&x, &a, sizeof x);
    std::memcpy(&y, &b, sizeof y);
    const bool common = !((undefined[i] >> j) & 1) && std::isfinite(a) && std::isfinite(b);
    auto position = [](std::int32_t bits) {
      const std::int32_t negative = bits >> 31;
      return ((bits & 0x7fffffff) ^ negative) - negative;
    };
    const std::int32_t px = position(x), py = position(y);
    const std::uint64_t d = common ? static_cast<std::uint32_t>(static_cast<std::uint32_t>(px > py ? px : py) -
                                                                static_cast<std::uint32_t>(px > py ? py : px))
                                   : 0;
    ulps[i] = d;
    flags[i] = common ? 1 : 0x80;
    if (d > max_ulps[i]) {
      max_ulps[i] = d;
      worst[i] = static_cast<std::uint8_t>(j);
    }
    special |= !common;
  }
  return special != 0;
}

bool grade_column_f64(const double* got, const double* ref, const std::uint32_t* undefined, std::size_t j,
                      std::size_t first, std::size_t end, std::uint64_t* ulps, std::uint8_t* flags,
                      std::uint64_t* max_ulps, std::uint8_t* worst) {
  const __m256i magnitude_mask = _mm256_set1_epi64x(0x7fffffffffffffffll);
  const __m256i exponent = _mm256_set1_epi64x(0x7ff0000000000000ll);
  const std::uint32_t counted_bytes = 0x01010101u;
  int special = 0;
  std::size_t i = first;
  for (; i + 4 <= end; i += 4) {
    const __m256i a = _mm256_castpd_si256(_mm256_loadu_pd(got + i)), b = _mm256_castpd_si256(_mm256_loadu_pd(ref + i));
    const __m256i finite_a = _mm256_cmpeq_epi64(_mm256_cmpeq_epi64(_mm256_and_si256(a, exponent), exponent),
                                                _mm256_setzero_si256());
    const __m256i defined = _mm256_cvtepi32_epi64(defined_lanes4(undefined + i, j));
    // Four finite doubles equal to their references: 0 ulps, counted; the maxima stay.
    if (_mm256_movemask_pd(_mm256_castsi256_pd(
            _mm256_and_si256(_mm256_and_si256(defined, finite_a), _mm256_cmpeq_epi64(a, b)))) == 0xf) {
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(ulps + i), _mm256_setzero_si256());
      std::memcpy(flags + i, &counted_bytes, 4);
      continue;
    }
    const __m256i finite_b = _mm256_cmpeq_epi64(_mm256_cmpeq_epi64(_mm256_and_si256(b, exponent), exponent),
                                                _mm256_setzero_si256());
    const __m256i common = _mm256_and_si256(defined, _mm256_and_si256(finite_a, finite_b));
    auto position = [&](__m256i bits) {
      const __m256i negative = _mm256_cmpgt_epi64(_mm256_setzero_si256(), bits);
      return _mm256_sub_epi64(_mm256_xor_si256(_mm256_and_si256(bits, magnitude_mask), negative), negative);
    };
    const __m256i x = position(a), y = position(b);
    const __m256i x_greater = _mm256_cmpgt_epi64(x, y);
    const __m256i d = _mm256_and_si256(
        _mm256_blendv_epi8(_mm256_sub_epi64(y, x), _mm256_sub_epi64(x, y), x_greater), common);
    const __m256i worse = store_ulps(d, ulps + i, max_ulps + i);
    const __m256i masks = _mm256_setr_m128i(narrow_mask(common), narrow_mask(worse));  // common: bytes 0-3, worse: 4-7
    const __m128i bytes = mask_bytes(masks);
    store_bytes(bytes, _mm_srli_si128(bytes, 4), j, flags + i, worst + i, 4);
    special |= _mm256_movemask_pd(_mm256_castsi256_pd(common)) ^ 0xf;
  }
  for (; i < end; ++i) {
    std::int64_t x, y;
    std::memcpy(&x, got + i, sizeof x);
    std::memcpy(&y, ref + i, sizeof y);
    const bool common = !((undefined[i] >> j) & 1) && std::isfinite(got[i]) && std::isfinite(ref[i]);
    auto position = [](std::int64_t bits) {
      const std::int64_t negative = bits < 0 ? -1 : 0;
      return ((bits & 0x7fffffffffffffffll) ^ negative) - negative;
    };
    const std::int64_t px = position(x), py = position(y);
    const std::uint64_t d = common ? (px > py ? static_cast<std::uint64_t>(px) - static_cast<std::uint64_t>(py)
                                              : static_cast<std::uint64_t>(py) - static_cast<std::uint64_t>(px))
                                   : 0;
    ulps[i] = d;
    flags[i] = common ? 1 : 0x80;
    if (d > max_ulps[i]) {
      max_ulps[i] = d;
      worst[i] = static_cast<std::uint8_t>(j);
    }
    special |= !common;
  }
  return special != 0;
}

}  // namespace avx2

batch_filter avx2_batch_filter(operation op, scalar_type type) { return batch_filter_over<v4d>(op, type); }

batch_filter avx2_image_filter(scalar_type type) { return image_filter_over<v4d>(type); }

grade_column_function avx2_grade_column(scalar_type type) {
  return type == scalar_type::f32 ? grade_column_f32 : grade_column_f64;
}

}  // namespace shadowproof::detail

#else  // no AVX2 in this build

namespace shadowproof::detail {
batch_filter avx2_batch_filter(operation, scalar_type) { return nullptr; }
batch_filter avx2_image_filter(scalar_type) { return nullptr; }
grade_column_function avx2_grade_column(scalar_type) { return nullptr; }
}  // namespace shadowproof::detail

#endif
