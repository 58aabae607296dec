#pragma once
// The exact outputs of a case, written once over the number type N of the oracle: rational
// (the reference), or an outward-rounded interval over double (float cases) or long double
// (double cases) that throws `undecided` when it cannot decide a sign. Each operation's file
// (operations/<op>.cpp) computes them with the library's own constructions.
#include <array>
#include <cstddef>
#include <optional>
#include <type_traits>

#include "dual.h"
#include "oracle_interval.h"
#include "shadowproof/constructions/classify.h"
#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/number.h"
#include "shadowproof/core/plane.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof::detail {

// Intervals over double decide float outputs (and f32 products are exact in double); double
// outputs need the 64-bit significand of long double.
using ival32 = interval<double>;
using ival64 = interval<long double>;

// The number N for the input or output value at x. Taken by reference: for the dual numbers of
// the derivative evaluation (dual.h), an input is told apart by its address.
template <class N>
N from_double(const double& x) {
  if constexpr (std::is_same_v<N, rational>) return exact_value(x);
  else if constexpr (is_dual<N>::value) return dual_from_double<typename N::base>(x);
  else return N::point(x);
}

/// q correctly rounded to F (+0 for an exact 0).
template <class F>
F round_exact(const rational& q) {
  F r;
  if constexpr (std::is_same_v<F, float>) r = to_nearest_float(q);
  else r = to_nearest_double(q);
  return r == 0 ? F(0) : r;
}
/// The interval's value correctly rounded to F; throws `undecided` when the interval straddles
/// a rounding boundary.
template <class F, class B>
F round_exact(const interval<B>& x) { return round_to<F>(x); }

inline int sign_n(const rational& q) { return sgn(q); }
template <class B>
int sign_n(const interval<B>& x) { return sign(x); }

template <class N>
N abs_n(const N& x) { return sign_n(x) < 0 ? N(-x) : x; }

// Fixed-size storage: the oracle's inner loop allocates nothing but the grade itself.
template <class T>
struct small_vector {
  std::array<T, 16> v{};
  std::size_t n = 0;
  void push_back(const T& x) { v[n++] = x; }
  void assign(std::size_t count, const T& x) {
    n = count;
    for (std::size_t i = 0; i < count; ++i) v[i] = x;
  }
  bool empty() const { return n == 0; }
  T& operator[](std::size_t i) { return v[i]; }
  const T& operator[](std::size_t i) const { return v[i]; }
};

/// The canonical exact outputs (row-major for matrices) of one case.
template <class N>
struct exact_outputs {
  small_vector<N> values;
  bool defined = true;                 ///< false: no output exists (undefined image, singular A)
  small_vector<bool> entry_undefined;  ///< when defined: entries that divide by zero (flat volumes)
  std::optional<point_class> cls;      ///< shadow-point: the exact class of the point

  void set_matrix(const mat4<N>& M) {
    for (std::size_t i = 0; i < 16; ++i) values.push_back(M(i / 4, i % 4));
  }
  void set_undefined(std::size_t count) {
    defined = false;
    values.assign(count, N(0));
  }
};

/// (x0, …, x_{n−1}) as a homogeneous vector; for n = 3 the fourth coordinate is `last`.
template <class N>
vec4<N> vec_from(const double* x, std::size_t n, const N& last) {
  vec4<N> v;
  for (std::size_t i = 0; i < n; ++i) v[i] = from_double<N>(x[i]);
  if (n == 3) v[3] = last;
  return v;
}

/// The plane (a, b, c, d) at x.
template <class N>
plane<N> plane_from(const double* x) {
  return plane<N>{vec_from<N>(x, 4, N(0))};
}

/// The light at x in canonical form: a directional light given along its rays is the negation
/// of the canonical one (exact).
template <class N>
light<N> canonical_light(const double* x, const conventions& conv) {
  light<N> L{vec_from<N>(x, 4, N(0))};
  if (conv.light == light_sign::along_rays && x[3] == 0)
    for (std::size_t i = 0; i < 3; ++i) L.l[i] = -L.l[i];
  return L;
}

}  // namespace shadowproof::detail
