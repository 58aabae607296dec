#pragma once
// The "real" types the filter numbers and rounding tests are written over: double (one case at
// a time, and the loops over cases the compiler vectorises) and, in batch_avx2.cpp only, a
// vector of four doubles. A real type R provides + − × ÷, comparisons giving a mask type
// (bool for double), and the functions below; the kernels' filter stage is then the same
// source for one case and for four.
//
// Every kernel header puts its code in the inline namespace SHADOWPROOF_KERNEL_TARGET
// (baseline by default; batch_avx2.cpp, compiled for AVX2, sets avx2), so that an inline
// function compiled for AVX2 never stands in for the baseline one at link time.
#include <cmath>
#include <cstdint>
#include <cstring>

/// Unrolls the small fixed loops of the formulas completely, so that a loop over cases whose
/// body is a formula has no inner control flow left for the vectoriser to reject.
#define SHADOWPROOF_UNROLL _Pragma("GCC unroll 16")

/// Inlines every call of a batch filter's loop into it (no call, no spill of its lanes). Not
/// under AddressSanitizer: instrumenting the inlined filters of the camera builders, some
/// thousand lines each, takes minutes of compile time, and inlining changes no result (no
/// contraction: -ffp-contract=off).
#if defined(__SANITIZE_ADDRESS__)
#define SHADOWPROOF_FLATTEN
#else
#define SHADOWPROOF_FLATTEN [[gnu::flatten]]
#endif

#ifndef SHADOWPROOF_KERNEL_TARGET
#define SHADOWPROOF_KERNEL_TARGET baseline
#endif

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// 2^k as a constant expression (exact for −1022 ≤ k ≤ 1023).
constexpr double power_of_two(int k) {
  double r = 1;
  for (; k > 0; --k) r *= 2;
  for (; k < 0; ++k) r /= 2;
  return r;
}

/// |x|.
inline double magnitude(double x) { return std::fabs(x); }
/// m ? a : b, lane by lane.
inline double select(bool m, double a, double b) { return m ? a : b; }
/// x rounded to float (to nearest, ties to even) and widened back: exact both ways.
inline double round_to_float_value(double x) { return static_cast<double>(static_cast<float>(x)); }
/// a / b in float arithmetic, widened back: the correctly rounded quotient where a and b are
/// floats.
inline double quotient_in_float(double a, double b) {
  return static_cast<double>(static_cast<float>(a) / static_cast<float>(b));
}
/// The neighbours of a positive finite double: its bit pattern ± 1.
inline void neighbours(double positive, double& above, double& below) {
  std::uint64_t bits;
  std::memcpy(&bits, &positive, sizeof bits);
  const std::uint64_t up = bits + 1, down = bits - 1;
  std::memcpy(&above, &up, sizeof above);
  std::memcpy(&below, &down, sizeof below);
}
/// table[index], index an integer in the table's range held as a double (a gather in a vector).
inline double gather(const double* table, double index) { return table[static_cast<int>(index)]; }
/// A mask false in every lane, of the mask type of x's real type.
inline bool no_lanes(double) { return false; }
/// Whether the mask is true in any lane.
inline bool any_lane(bool m) { return m; }
/// √x correctly rounded (IEEE 754), lane by lane; NaN for x < 0.
inline double square_root(double x) { return std::sqrt(x); }

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
