#pragma once
// Exact sums and products of doubles as nonoverlapping expansions (Shewchuk, "Adaptive
// precision floating-point arithmetic and fast robust geometric predicates", 1997): a value
// is the exact sum of components e[0] + … + e[n−1], nonzero, nonoverlapping and increasing in
// magnitude, so the last component carries the sign and is the value to within one of its ulps.
// Fixed capacity, no allocation: an operation whose result would not fit marks the expansion
// as overflowed, and the kernels then leave the case to the generic oracle.
#include <cmath>

#include "error_free.h"
#include "lanes.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// Grows the nonoverlapping expansion e[0..m) by x (Shewchuk's Grow-Expansion with zero
/// elimination); e must have room for m + 1 components. Returns the new length.
inline int grow_expansion(double* e, int m, double x) {
  int k = 0;
  for (int i = 0; i < m; ++i) {
    double sum, error;
    two_sum(x, e[i], sum, error);
    x = sum;
    if (error != 0) e[k++] = error;
  }
  if (x != 0) e[k++] = x;
  return k;
}

/// An exact real number as a nonoverlapping expansion of at most `capacity` doubles.
/// Every operation is exact: sums by Grow-Expansion, products by two_product of every pair of
/// components. Preconditions of two_product apply to every pair (the kernels bound their inputs
/// so that no partial product under- or overflows).
class expansion {
 public:
  static constexpr int capacity = 64;

  expansion() = default;
  explicit expansion(double x) {
    if (x != 0) e_[n_++] = x;
  }

  int size() const { return n_; }
  bool overflowed() const { return overflowed_; }
  double component(int i) const { return e_[i]; }
  /// The exact sign: the sign of the largest component.
  int sign() const { return n_ == 0 ? 0 : (e_[n_ - 1] > 0 ? 1 : -1); }
  bool is_zero() const { return n_ == 0; }
  /// The largest component: the value to within one of its ulps.
  double top() const { return n_ == 0 ? 0.0 : e_[n_ - 1]; }

  void add(double x) {
    if (n_ == capacity) {
      overflowed_ = true;
      return;
    }
    n_ = grow_expansion(e_, n_, x);
  }
  /// Adds x · y exactly (two terms from two_product).
  void add_product(double x, double y) {
    double p, e;
    two_product(x, y, p, e);
    add(e);
    add(p);
  }

  friend expansion operator-(const expansion& a) {
    expansion r = a;
    for (int i = 0; i < r.n_; ++i) r.e_[i] = -r.e_[i];
    return r;
  }
  friend expansion operator+(const expansion& a, const expansion& b) {
    expansion r = a.n_ >= b.n_ ? a : b;
    const expansion& s = a.n_ >= b.n_ ? b : a;
    r.overflowed_ = a.overflowed_ || b.overflowed_;
    for (int i = 0; i < s.n_; ++i) r.add(s.e_[i]);
    return r;
  }
  friend expansion operator-(const expansion& a, const expansion& b) { return a + (-b); }
  friend expansion operator*(const expansion& a, const expansion& b) {
    expansion r;
    r.overflowed_ = a.overflowed_ || b.overflowed_;
    for (int i = 0; i < a.n_; ++i)
      for (int j = 0; j < b.n_; ++j) r.add_product(a.e_[i], b.e_[j]);
    return r;
  }
  /// x · 2^k exactly (k small enough that no component under- or overflows).
  friend expansion scaled(const expansion& a, int k) {
    expansion r = a;
    for (int i = 0; i < r.n_; ++i) r.e_[i] = std::ldexp(r.e_[i], k);
    return r;
  }
  /// a · b for two inputs (the same as a * b; the filter numbers have a cheaper exact form).
  friend expansion exact_product(const expansion& a, const expansion& b) { return a * b; }
  /// An output that is the product of two inputs: here the exact product.
  friend expansion rounded_product(const expansion& a, const expansion& b) { return a * b; }
  /// a · c for c = 0 or ±2^k (small k): exact.
  friend expansion scaled_by(const expansion& a, double c) {
    if (c == 0) return expansion();
    expansion r = a;
    for (int i = 0; i < r.n_; ++i) r.e_[i] *= c;
    return r;
  }
  expansion& operator+=(const expansion& b) { return *this = *this + b; }
  expansion& operator-=(const expansion& b) { return *this = *this - b; }

 private:
  double e_[capacity];
  int n_ = 0;
  bool overflowed_ = false;
};

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
