#pragma once
// Forward-mode derivatives for the exact oracle: a number that carries its value and its partial
// derivatives with respect to the case's inputs, over any of the oracle's number types B
// (rational, or an outward-rounded interval). Each operation's exact<N> template, instantiated
// with N = dual<B>, yields the exact outputs together with ∂f_i/∂x_j and needs no formula of its
// own:  (a ± b)' = a' ± b',  (a b)' = a' b + a b',  (a / b)' = (a' − (a/b) b') / b.
//
// Each number also carries two notes about how it was computed, for the verdicts
// (docs/verdicts.md), inherited from its operands:
//   - near_singular: some divisor b on the way was within a relative c·u of vanishing under
//     componentwise perturbations of the inputs, to first order: |b| ≤ c·u Σ_j |∂b/∂x_j| |x_j|.
//     A non-finite result is then explained by a nearby input for which it does not exist.
//   - out_of_range: an intermediate on the way left the range of the case's type, as a
//     straightforward evaluation meets it: a sum, product or quotient beyond the largest finite
//     value, or a nonzero product or quotient below the smallest normal one (sums of
//     representable numbers that land below it are exact in IEEE arithmetic, products are not).
//     The context also collects it over the whole evaluation: an overflow anywhere can reach
//     every output of a routine that combines its entries (a product of matrices).
// Comparisons and signs look at the value only, so the derivatives are those of the branch the
// exact value takes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <ostream>

#include "oracle_interval.h"
#include "shadowproof/core/number.h"

namespace shadowproof::detail {

/// The most inputs an operation may have for its derivatives to be computed.
inline constexpr std::size_t max_derivative_inputs = 16;

/// A fact an evaluation may meet: never, certainly, or possibly (an interval could not decide).
enum class noted { no, yes, undecided };

/// What one derivative evaluation is about, per thread: which inputs are the variables (a number
/// read from inputs[j] by from_double gets ∂/∂x_j = 1) and the thresholds of the notes.
struct derivative_context {
  const double* inputs = nullptr;
  std::size_t count = 0;
  double singular_threshold = 0;  ///< c·u: a divisor this close to vanishing is near singular
  double max_finite = 0;          ///< largest finite value of the case's type
  double min_normal = 0;          ///< smallest normal value of the case's type
  noted out_of_range = noted::no;  ///< some intermediate of the evaluation left the range
};

/// The context of the evaluation running on this thread, or null.
inline derivative_context*& current_derivative_context() {
  thread_local derivative_context* context = nullptr;
  return context;
}

/// Makes `context` current for its lifetime.
class derivative_scope {
 public:
  explicit derivative_scope(derivative_context& context) : previous_(current_derivative_context()) {
    current_derivative_context() = &context;
  }
  ~derivative_scope() { current_derivative_context() = previous_; }
  derivative_scope(const derivative_scope&) = delete;
  derivative_scope& operator=(const derivative_scope&) = delete;

 private:
  derivative_context* previous_;
};

// The base types' primitives: an exact or enclosing conversion of a double, |x| (an enclosure
// for intervals, never throwing), and the sign of x when it is decided.
inline rational base_from(double x, const rational*) { return exact_value(x); }
template <class X>
interval<X> base_from(double x, const interval<X>*) { return interval<X>::point(static_cast<X>(x)); }
inline rational magnitude_of(const rational& q) { return abs(q); }
template <class X>
interval<X> magnitude_of(const interval<X>& x) { return magnitude(x); }
inline bool decided_sign_of(const rational& q, int& s) {
  s = sgn(q);
  return true;
}
template <class X>
bool decided_sign_of(const interval<X>& x, int& s) { return decided_sign(x, s); }

// Merges a fact into a note: certainly beats possibly beats never.
inline void merge(noted& into, noted fact) {
  if (fact == noted::yes || into == noted::yes) into = noted::yes;
  else if (fact == noted::undecided) into = noted::undecided;
}

// Whether a > b: yes, no, or undecided.
template <class B>
noted exceeds(const B& a, const B& b) {
  int s = 0;
  if (!decided_sign_of(B(a - b), s)) return noted::undecided;
  return s > 0 ? noted::yes : noted::no;
}

template <class B>
class dual {
 public:
  using base = B;
  dual() : v_(0) {}
  dual(int x) : v_(x) {}  // NOLINT: the small constants formulas use, N(0), N(2)
  /// The input x_j as a variable: value x, ∂/∂x_j = 1.
  static dual variable(const B& x, std::size_t j) {
    dual r;
    r.v_ = x;
    r.d_[j] = B(1);
    r.n_ = static_cast<std::uint8_t>(j + 1);
    return r;
  }
  /// A constant: every derivative 0.
  static dual constant(const B& x) {
    dual r;
    r.v_ = x;
    return r;
  }

  const B& value() const { return v_; }
  /// ∂/∂x_j (0 beyond lanes()).
  const B& derivative(std::size_t j) const { return d_[j]; }
  /// Derivatives possibly nonzero: j < lanes().
  std::size_t lanes() const { return n_; }
  /// The notes (see above).
  noted near_singular() const { return singular_; }
  noted out_of_range() const { return range_; }

  friend dual operator-(const dual& a) {
    dual r;
    r.v_ = -a.v_;
    r.n_ = a.n_;
    r.singular_ = a.singular_;
    r.range_ = a.range_;
    for (std::size_t j = 0; j < r.n_; ++j) r.d_[j] = -a.d_[j];
    return r;
  }
  friend dual operator+(const dual& a, const dual& b) {
    dual r;
    r.v_ = a.v_ + b.v_;
    r.n_ = a.n_ > b.n_ ? a.n_ : b.n_;
    for (std::size_t j = 0; j < r.n_; ++j) r.d_[j] = a.d_[j] + b.d_[j];
    r.inherit(a, b);
    r.note_range(false);
    return r;
  }
  friend dual operator-(const dual& a, const dual& b) {
    dual r;
    r.v_ = a.v_ - b.v_;
    r.n_ = a.n_ > b.n_ ? a.n_ : b.n_;
    for (std::size_t j = 0; j < r.n_; ++j) r.d_[j] = a.d_[j] - b.d_[j];
    r.inherit(a, b);
    r.note_range(false);
    return r;
  }
  friend dual operator*(const dual& a, const dual& b) {
    dual r;
    r.v_ = a.v_ * b.v_;
    r.n_ = a.n_ > b.n_ ? a.n_ : b.n_;
    for (std::size_t j = 0; j < r.n_; ++j) {
      if (j >= a.n_) r.d_[j] = a.v_ * b.d_[j];
      else if (j >= b.n_) r.d_[j] = a.d_[j] * b.v_;
      else r.d_[j] = a.d_[j] * b.v_ + a.v_ * b.d_[j];
    }
    r.inherit(a, b);
    r.note_range(true);
    return r;
  }
  friend dual operator/(const dual& a, const dual& b) {
    dual r;
    r.v_ = a.v_ / b.v_;  // an interval b that may contain 0 throws `undecided` here
    r.n_ = a.n_ > b.n_ ? a.n_ : b.n_;
    for (std::size_t j = 0; j < r.n_; ++j) {
      if (j >= b.n_) r.d_[j] = a.d_[j] / b.v_;
      else r.d_[j] = (a.d_[j] - r.v_ * b.d_[j]) / b.v_;
    }
    r.inherit(a, b);
    r.note_divisor(b);
    r.note_range(true);
    return r;
  }
  dual& operator+=(const dual& b) { return *this = *this + b; }
  dual& operator-=(const dual& b) { return *this = *this - b; }
  dual& operator*=(const dual& b) { return *this = *this * b; }
  dual& operator/=(const dual& b) { return *this = *this / b; }

  friend bool operator==(const dual& a, const dual& b) { return a.v_ == b.v_; }
  friend bool operator!=(const dual& a, const dual& b) { return !(a.v_ == b.v_); }
  friend bool operator<(const dual& a, const dual& b) { return a.v_ < b.v_; }
  friend bool operator>(const dual& a, const dual& b) { return b.v_ < a.v_; }
  friend bool operator<=(const dual& a, const dual& b) { return !(b.v_ < a.v_); }
  friend bool operator>=(const dual& a, const dual& b) { return !(a.v_ < b.v_); }
  friend std::ostream& operator<<(std::ostream& out, const dual& a) { return out << a.v_; }

 private:
  static B from(double x) { return base_from(x, static_cast<const B*>(nullptr)); }

  void inherit(const dual& a, const dual& b) {
    singular_ = a.singular_;
    merge(singular_, b.singular_);
    range_ = a.range_;
    merge(range_, b.range_);
  }

  // out_of_range: |v| beyond the largest finite value, or (products and quotients) nonzero
  // below the smallest normal value.
  void note_range(bool product) {
    derivative_context* context = current_derivative_context();
    if (!context) return;
    noted fact = noted::no;
    const B size = magnitude_of(v_);
    merge(fact, exceeds(size, from(context->max_finite)));
    int s = 0;
    if (product) {
      if (!decided_sign_of(v_, s)) merge(fact, exceeds(from(context->min_normal), size) == noted::no ? noted::no
                                                                                                 : noted::undecided);
      else if (s != 0) merge(fact, exceeds(from(context->min_normal), size));  // an exact zero is representable
    }
    merge(range_, fact);
    merge(context->out_of_range, fact);
  }

  // near_singular: |b| ≤ c·u Σ_j |∂b/∂x_j| |x_j| for the divisor b.
  void note_divisor(const dual& b) {
    const derivative_context* context = current_derivative_context();
    if (!context || singular_ == noted::yes || b.n_ == 0) return;
    B sensitivity(0);
    for (std::size_t j = 0; j < b.n_ && j < context->count; ++j)
      sensitivity += magnitude_of(b.d_[j]) * magnitude_of(from(context->inputs[j]));
    const noted far = exceeds(magnitude_of(b.v_), B(from(context->singular_threshold) * sensitivity));
    merge(singular_, far == noted::yes ? noted::no : (far == noted::no ? noted::yes : noted::undecided));
  }

  B v_;
  std::array<B, max_derivative_inputs> d_{};
  std::uint8_t n_ = 0;
  noted singular_ = noted::no;
  noted range_ = noted::no;
};

template <class B>
int sign_n(const dual<B>& x) {
  if constexpr (std::is_same_v<B, rational>) return sgn(x.value());
  else return sign(x.value());
}

template <class T>
struct is_dual : std::false_type {};
template <class B>
struct is_dual<dual<B>> : std::true_type {};

/// The input read from `x` as a dual number: a variable when x is one of the current context's
/// inputs (by address), a constant otherwise.
template <class B>
dual<B> dual_from_double(const double& x) {
  const B value = base_from(x, static_cast<const B*>(nullptr));
  const derivative_context* context = current_derivative_context();
  if (context && &x >= context->inputs && &x < context->inputs + context->count)
    return dual<B>::variable(value, static_cast<std::size_t>(&x - context->inputs));
  return dual<B>::constant(value);
}

}  // namespace shadowproof::detail
