#pragma once
// Error-free transformations of doubles: the exact rounding error of a sum or a product is
// itself a double, computed with a few more operations.
//
//   two_sum(a, b)      s + e = a + b exactly, s = fl(a + b)            (Knuth; 6 additions)
//   split(x)           hi + lo = x exactly, each with at most 26 significant bits (Veltkamp)
//   two_product(a, b)  p + e = a · b exactly, p = fl(a · b)            (FMA, or Dekker's split)
//
// They hold in round-to-nearest only as written: a compiler that contracts x·y + z into a
// fused multiply-add changes split's hi and Dekker's e and breaks both. The library is compiled
// with -ffp-contract=off (src/CMakeLists.txt), and tests/test_oracle_kernels.cpp checks every
// property exactly on the instances compiled into the library (error_free.cpp), so a build that
// contracts fails its tests.
//
// Range: two_sum is exact for all finite a, b whose sum does not overflow. split needs
// |x| < 2^996 (2^27 x must not overflow). Dekker's product additionally needs a · b far from
// underflow: its error term must be a normal double, |a · b| ≥ 2^-969 or a · b = 0. The callers
// bound their inputs accordingly (kernels/bounded.h).
#include <cmath>

#include "lanes.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// Unit roundoff of double: |fl(x) − x| ≤ unit_roundoff · |fl(x)| for x in the normal range.
constexpr double unit_roundoff = 0x1p-53;
/// An absolute error bound for one rounding near underflow: at least half the smallest
/// subnormal (2^-1075), and itself a normal double, because arithmetic on subnormal operands
/// takes a microcode assist of a hundred cycles or more on x86. Negligible beside the values
/// the kernels decide (above 2^-920, bounded.h).
constexpr double underflow_slack = 0x1p-1000;

/// s = fl(a + b), e = (a + b) − s exactly (Knuth's TwoSum, no condition on |a|, |b|). R is
/// double or a vector of doubles (lanes.h).
template <class R>
inline void two_sum(R a, R b, R& s, R& e) {
  s = a + b;
  const R b_virtual = s - a;
  const R a_virtual = s - b_virtual;
  e = (a - a_virtual) + (b - b_virtual);
}

/// hi + lo = x exactly with hi = x rounded to 26 significant bits and |lo| ≤ 2^-27 |x| on 26
/// bits (Veltkamp's split with the factor 2^27 + 1). Precondition |x| < 2^996.
template <class R>
inline void split(R x, R& hi, R& lo) {
  const R c = R(134217729.0) * x;  // (2^27 + 1) x
  hi = c - (c - x);
  lo = x - hi;
}

/// p = fl(a · b), e = a · b − p exactly, from Veltkamp's splits (Dekker's product): every
/// partial product of two 26-bit halves is exact, and so is each subtraction.
/// Precondition: |a|, |b| < 2^996 and a · b = 0 or |a · b| ≥ 2^-969.
template <class R>
inline void two_product_dekker(R a, R b, R& p, R& e) {
  p = a * b;
  R a_hi, a_lo, b_hi, b_lo;
  split(a, a_hi, a_lo);
  split(b, b_hi, b_lo);
  e = ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
}

/// Whether two_product uses the processor's fused multiply-add (the build targets a processor
/// that has one, e.g. -march=x86-64-v3) or Dekker's product.
#if defined(__FMA__)
inline constexpr bool two_product_uses_fma = true;
#else
inline constexpr bool two_product_uses_fma = false;
#endif

/// p = fl(a · b), e = a · b − p exactly: e = fma(a, b, −p), one rounding of an exact value that
/// is a double, where the build guarantees a hardware FMA; Dekker's product otherwise (same
/// preconditions; the FMA form needs only a · b = 0 or |a · b| ≥ 2^-969).
inline void two_product(double a, double b, double& p, double& e) {
#if defined(__FMA__)
  p = a * b;
  e = __builtin_fma(a, b, -p);
#else
  two_product_dekker(a, b, p, e);
#endif
}

}  // namespace SHADOWPROOF_KERNEL_TARGET

/// The instances compiled into the library with the library's own flags, for the tests of the
/// defining properties above (an inline copy in a test would be compiled with the test's flags).
namespace compiled {
void two_sum(double a, double b, double& s, double& e);
void split(double x, double& hi, double& lo);
void two_product(double a, double b, double& p, double& e);
void two_product_dekker(double a, double b, double& p, double& e);
/// Grows `n` doubles into a nonoverlapping expansion (kernels/expansion.h); returns its length.
int expansion_of(const double* terms, int n, double* components);
}  // namespace compiled

}  // namespace shadowproof::detail
