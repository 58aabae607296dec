#pragma once
// Midpoint-radius intervals over double or long double: a value m and a bound e with the exact
// real result in [m − e, m + e]. Every operation runs in the default round-to-nearest mode
// (no rounding-mode switch, no -frounding-math): the new bound adds the rounding error of the
// midpoint, u|m| plus the smallest subnormal for underflow, and is inflated by (1 + 8u) to
// cover the rounding of the bound's own computation (all its terms are non-negative).
// Exact operands whose result is exact (TwoSum / TwoProduct say so) keep e = 0, so exact zeros
// and representable entries stay decidable. A comparison, a sign or a division the interval
// cannot decide throws `undecided`; the oracle then redoes the case with rationals.
#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <type_traits>

namespace shadowproof::detail {

struct undecided {};

// Hardware fused multiply-add, chosen at run time (the library is built for baseline x86-64).
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("fma"))) inline double fma_hw(double a, double b, double c) { return __builtin_fma(a, b, c); }
inline const bool hardware_fma = [] {
  __builtin_cpu_init();  // may run before the library's own initialisation
  return __builtin_cpu_supports("fma") != 0;
}();
inline bool has_hardware_fma() { return hardware_fma; }
#else
inline double fma_hw(double a, double b, double c) { return std::fma(a, b, c); }
inline bool has_hardware_fma() { return false; }
#endif

template <class B>
class interval {
 public:
  interval() : m_(0), e_(0) {}
  interval(int x) : m_(x), e_(0) {}  // NOLINT: exact for the small constants formulas use
  static interval point(B x) { return interval(x, B(0)); }

  B mid() const { return m_; }
  B radius() const { return e_; }
  bool is_point() const { return e_ == 0; }
  /// Bounds lower() ≤ every point ≤ upper(), rounded outwards.
  B lower() const { return e_ == 0 ? m_ : down(m_ - e_); }
  B upper() const { return e_ == 0 ? m_ : up(m_ + e_); }
  /// An interval holding every real in [lo, hi] (lo ≤ hi, both finite): the midpoint
  /// lo/2 + hi/2 (halving first cannot overflow) and a radius rounded upwards past both ends.
  static interval between(B lo, B hi) {
    if (lo == hi) return point(lo);
    const B m = lo / 2 + hi / 2;
    const B e = up(std::max(m - lo, hi - m));  // each difference is within u of its exact value
    return interval(m, up(e + B(2) * std::numeric_limits<B>::denorm_min()));  // the halving's underflow
  }

  friend interval operator-(const interval& a) { return interval(-a.m_, a.e_); }
  friend interval operator+(const interval& a, const interval& b) { return sum(a, b.m_, b.e_); }
  friend interval operator-(const interval& a, const interval& b) { return sum(a, -b.m_, b.e_); }
  friend interval operator*(const interval& a, const interval& b) {
    if ((a.m_ == 0 && a.e_ == 0) || (b.m_ == 0 && b.e_ == 0)) return interval();
    const B p = a.m_ * b.m_;
    if (a.e_ == 0 && b.e_ == 0 && product_is_exact(a.m_, b.m_, p)) return point(p);
    const B e = std::fabs(a.m_) * b.e_ + std::fabs(b.m_) * a.e_ + a.e_ * b.e_ + rounding(p);
    return interval(p, e * inflate());
  }
  friend interval operator/(const interval& a, const interval& b) {
    const B lower = (std::fabs(b.m_) - b.e_) * (B(1) - 4 * unit());  // ≤ |every point of b|
    if (!(lower > 0)) throw undecided{};
    const B q = a.m_ / b.m_;
    if (a.e_ == 0 && b.e_ == 0 && product_is_exact(q, b.m_, a.m_)) return point(q);
    // |a/b − a.m/b.m| ≤ (a.e + |a.m/b.m| b.e) / (|b.m| − b.e), and |a.m/b.m| ≤ |q| (1 + u).
    const B e = (a.e_ + std::fabs(q) * b.e_ * (B(1) + 2 * unit())) / lower * inflate() + rounding(q);
    return interval(q, e * inflate());
  }
  // √a for a ≥ 0 (throws undecided when a may hold a negative point). A point whose root is
  // exact stays a point; otherwise the correctly rounded roots of the outward ends (IEEE sqrt
  // is correctly rounded, |RN(√x) − √x| ≤ u √x), each pushed outwards past that error.
  friend interval sqrt(const interval& a) {
    const B lo = a.lower(), hi = a.upper();
    if (std::isnan(lo) || std::isnan(hi) || !std::isfinite(hi) || lo < 0) throw undecided{};
    if (a.e_ == 0) {
      if (a.m_ == 0) return interval();
      const B r = std::sqrt(a.m_);
      if (product_is_exact(r, r, a.m_)) return point(r);
      return interval(r, up(rounding(r)));
    }
    return between(std::max(B(0), down(std::sqrt(lo))), up(std::sqrt(hi)));
  }
  interval& operator+=(const interval& b) { return *this = *this + b; }
  interval& operator-=(const interval& b) { return *this = *this - b; }
  interval& operator*=(const interval& b) { return *this = *this * b; }

  // Comparisons answer only when every pair of points in the intervals agrees.
  friend bool operator<(const interval& a, const interval& b) {
    if (a.e_ == 0 && b.e_ == 0) return check(a.m_ < b.m_, a, b);
    const int s = difference_sign(a, b);
    return s < 0;
  }
  friend bool operator>(const interval& a, const interval& b) { return b < a; }
  friend bool operator<=(const interval& a, const interval& b) { return !(b < a); }
  friend bool operator>=(const interval& a, const interval& b) { return !(a < b); }
  friend bool operator==(const interval& a, const interval& b) {
    if (a.e_ == 0 && b.e_ == 0) return check(a.m_ == b.m_, a, b);
    difference_sign(a, b);  // throws unless the intervals are disjoint
    return false;
  }
  friend bool operator!=(const interval& a, const interval& b) { return !(a == b); }
  // For messages of formulas that print their operands (project.h's errors).
  friend std::ostream& operator<<(std::ostream& out, const interval& a) {
    return out << a.m_ << " ± " << a.e_;
  }
  // An enclosure of |x| for every point x of a, decided or not: the absolute values of the
  // derivatives that the conditioning sums need even where a derivative's sign is unknown.
  friend interval magnitude(const interval& a) {
    if (std::fabs(a.m_) > a.e_) return a.m_ < 0 ? -a : a;
    const B top = up(std::fabs(a.m_) + a.e_);  // |x| ∈ [0, top]
    return interval(top / 2, up(top / 2));
  }

  static B unit() { return std::numeric_limits<B>::epsilon() / 2; }
  // Pushes a bound computed in round-to-nearest outwards past its own rounding error.
  static B down(B r) { return r - (std::fabs(r) * std::numeric_limits<B>::epsilon() + std::numeric_limits<B>::denorm_min()); }
  static B up(B r) { return r + (std::fabs(r) * std::numeric_limits<B>::epsilon() + std::numeric_limits<B>::denorm_min()); }

 private:
  interval(B m, B e) : m_(m), e_(e) {}

  static B inflate() { return B(1) + 8 * unit(); }
  static B rounding(B r) { return std::fabs(r) * unit() + std::numeric_limits<B>::denorm_min(); }

  static interval sum(const interval& a, B bm, B be) {
    const B s = a.m_ + bm;
    if (a.e_ == 0 && be == 0) {
      const B bb = s - a.m_;  // TwoSum (Knuth): the exact rounding error of s
      if (std::isfinite(s) && (a.m_ - (s - bb)) + (bm - bb) == 0) return point(s);
    }
    return interval(s, (a.e_ + be + rounding(s)) * inflate());
  }

  // x·y == p exactly? For double, one fused multiply-add when the processor has it;
  // otherwise (and for long double) TwoProduct by Dekker's split, far from under/overflow.
  static bool product_is_exact(B x, B y, B p) {
    if constexpr (std::is_same_v<B, double>) {
      if (has_hardware_fma()) return std::isfinite(p) && fma_hw(x, y, -p) == 0 && !tiny(p);
    }
    return product_is_exact_split(x, y, p);
  }
  // Near underflow the fused result can be exact-looking while the product is not.
  static bool tiny(B p) { return std::fabs(p) < tiny_product; }
  // Far enough from underflow and overflow for the split's error terms to be exact.
  static inline const B tiny_product = std::ldexp(std::numeric_limits<B>::min(), std::numeric_limits<B>::digits);
  static inline const B small = std::ldexp(std::numeric_limits<B>::min(), 2 * std::numeric_limits<B>::digits);
  static inline const B large = std::ldexp(std::numeric_limits<B>::max(), -std::numeric_limits<B>::digits);
  static bool product_is_exact_split(B x, B y, B p) {
    const B ax = std::fabs(x), ay = std::fabs(y), ap = std::fabs(p);
    if (!(ap >= small && ax >= small && ay >= small && ax <= large && ay <= large && ap <= large)) return false;
    B x1, x2, y1, y2;
    split(x, x1, x2);
    split(y, y1, y2);
    return ((x1 * y1 - p) + x1 * y2 + x2 * y1) + x2 * y2 == 0;
  }
  static void split(B x, B& hi, B& lo) {
    constexpr int half = (std::numeric_limits<B>::digits + 1) / 2;
    const B factor = static_cast<B>((1ull << half) + 1);
    const B c = factor * x;
    hi = c - (c - x);
    lo = x - hi;
  }

  static bool check(bool result, const interval& a, const interval& b) {
    if (std::isnan(a.m_) || std::isnan(b.m_)) throw undecided{};
    return result;
  }
  // Sign of (every point of a) − (every point of b), or undecided.
  static int difference_sign(const interval& a, const interval& b) {
    const B d = a.m_ - b.m_;
    const B bound = (a.e_ + b.e_ + rounding(d)) * inflate();
    if (std::isnan(d) || std::isnan(bound) || !(std::fabs(d) > bound)) throw undecided{};
    return d > 0 ? 1 : -1;
  }

  B m_, e_;
};

/// The value of x correctly rounded to F (float or double) if every point of x rounds to the
/// same F value; throws undecided otherwise (or when x is NaN or unbounded).
template <class F, class B>
F round_to(const interval<B>& x) {
  if (std::isnan(x.mid()) || std::isnan(x.radius())) throw undecided{};
  F a, b;
  if (x.is_point()) {
    a = b = static_cast<F>(x.mid());  // one correct rounding (B is at least as wide as F)
  } else {
    if (!std::isfinite(x.radius())) throw undecided{};
    // Round-to-nearest is monotone, so equal roundings of both ends decide every point.
    a = static_cast<F>(interval<B>::down(x.mid() - x.radius()));
    b = static_cast<F>(interval<B>::up(x.mid() + x.radius()));
  }
  if (!(a == b)) throw undecided{};
  return a == 0 ? F(0) : a;  // the exact oracle rounds 0 to +0
}

/// Sign of x (−1, 0, +1) in `s` when decided; false otherwise (never throws).
template <class B>
bool decided_sign(const interval<B>& x, int& s) {
  if (std::isnan(x.mid()) || std::isnan(x.radius())) return false;
  if (x.is_point()) {
    s = x.mid() > 0 ? 1 : (x.mid() < 0 ? -1 : 0);
    return true;
  }
  if (!(std::fabs(x.mid()) > x.radius())) return false;
  s = x.mid() > 0 ? 1 : -1;
  return true;
}

/// Sign of x (−1, 0, +1) when decided.
template <class B>
int sign(const interval<B>& x) {
  if (std::isnan(x.mid()) || std::isnan(x.radius())) throw undecided{};
  if (x.is_point()) return x.mid() > 0 ? 1 : (x.mid() < 0 ? -1 : 0);
  if (std::fabs(x.mid()) > x.radius()) return x.mid() > 0 ? 1 : -1;
  throw undecided{};
}

}  // namespace shadowproof::detail
