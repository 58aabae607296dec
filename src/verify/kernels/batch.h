#pragma once
// The kernels' filter stage over many cases of one operation and type at once, structure of
// arrays: a batch filter reads input k of case i at in[k][i] and writes canonical output j at
// out[j][i] (any column order: the caller points out[j] where it wants output j). It decides
// almost every regular case; the others (undecided roundings, zero denominators, degenerate
// classes, inputs out of range) are flagged for the kernel for one case (oracle_fast.h),
// which decides them or hands them to the generic oracle.
//
// Two variants of every filter: the generic one, a branch-free loop over cases written for the
// compiler to vectorise (batch_generic.cpp, baseline x86-64), and one that processes four cases
// per AVX2 vector (batch_avx2.cpp, compiled for AVX2 and FMA), chosen at run time when the
// processor has both. Both decide exactly the same cases' outputs: correctly rounded values
// are unique, and tests/test_batch.cpp checks that they agree bit for bit.
#include <cstddef>
#include <cstdint>

#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof::detail {

/// Results of a batch filter, per case.
struct batch_filter_out {
  double* const* values;  ///< canonical output j of case i at values[j][i] (written where decided)
  std::uint8_t* decided;  ///< 1 where every output of case i is decided, 0 where not
  std::int8_t* point_class;  ///< shadow-point: the exact class of V (point_class) where decided
};

/// Filters `count` cases: in[k] is the column of input k.
using batch_filter = void (*)(const double* const* in, std::size_t count, const conventions& conv,
                              const batch_filter_out& out);

/// The generic filter of (op, type), or null for an operation without one (perspective-fov and
/// perspective-fov-infinite: their cases go one by one).
batch_filter generic_batch_filter(operation op, scalar_type type);

/// The AVX2 filter of (op, type), or null when this build has none (not x86-64, or the
/// compiler cannot target AVX2). Callable only when avx2_supported().
batch_filter avx2_batch_filter(operation op, scalar_type type);

/// The shadow-point image filter: grading the float images G of many cases against their
/// correctly rounded images C (what fast_image_class and fast_plane_value give one case).
/// in[0..10] are the cases' inputs, in[11..13] the columns of G and in[14..16] those of C.
/// out.point_class gets class(G) + 4 class(C) (image_class values), out.decided 1 where G's
/// class is decided and out.values[2] 1 where C's is (0 where not: only the classes shadow,
/// behind_receiver and beyond_light are decided); out.values[0] gets P·(G, 1) correctly rounded
/// to double where out.values[1] gets 1 (0 where that rounding is undecided).
batch_filter generic_image_filter(scalar_type type);
/// The same for AVX2, or null when this build has none. Callable only when avx2_supported().
batch_filter avx2_image_filter(scalar_type type);

/// Whether the processor running this program has AVX2 and FMA (checked once).
bool avx2_supported();

/// Grades output column j of cases [first, end) (batch.cpp's grade_column): where the exact
/// output is defined (bit j of undefined[i] clear) and the float value of got[i] and of ref[i]
/// are finite, ulps[i] = their distance in ulps of the type and flags[i] = 1 (counted), and
/// max_ulps[i] / worst[i] become ulps[i] / j when it exceeds max_ulps[i]; elsewhere ulps[i] = 0
/// and flags[i] = 0x80 (left to the caller). Returns whether any output was left.
using grade_column_function = bool (*)(const double* got, const double* ref, const std::uint32_t* undefined,
                                       std::size_t j, std::size_t first, std::size_t end, std::uint64_t* ulps,
                                       std::uint8_t* flags, std::uint64_t* max_ulps, std::uint8_t* worst);

/// The AVX2 column grader for outputs of `type`, or null when this build has none. Callable
/// only when avx2_supported().
grade_column_function avx2_grade_column(scalar_type type);

}  // namespace shadowproof::detail
