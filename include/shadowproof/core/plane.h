#pragma once
/// A plane P = (a, b, c, d): the points X with a x + b y + c z + d = 0, i.e. P · (x, y, z, 1) = 0.
#include <string>

#include "shadowproof/core/error.h"
#include "shadowproof/core/homogeneous.h"

namespace shadowproof {

/// Plane coefficients (a, b, c, d), never normalised: (a, b, c) is a normal (not necessarily
/// unit) and the positive side is where a x + b y + c z + d > 0. Scaling P by λ ≠ 0 gives the
/// same plane (with the sides swapped when λ < 0).
template <class T>
struct plane {
  vec4<T> p;

  const T& a() const { return p[0]; }
  const T& b() const { return p[1]; }
  const T& c() const { return p[2]; }
  const T& d() const { return p[3]; }
  /// Normal (a, b, c, 0) as a direction.
  vec4<T> normal() const { return make_vec4<T>(p[0], p[1], p[2], T(0)); }
};

/// Builds the plane a x + b y + c z + d = 0.
/// Throws error "geometry.zero_normal" when a = b = c = 0 (that is no plane: either every
/// point or none satisfies the equation).
template <class T>
plane<T> make_plane(const T& a, const T& b, const T& c, const T& d) {
  if (a == T(0) && b == T(0) && c == T(0))
    throw zero_normal_error();
  return plane<T>{make_vec4<T>(a, b, c, d)};
}

/// Signed value P · V = a x + b y + c z + d w (zero exactly when V lies on P).
template <class T>
T evaluate(const plane<T>& P, const vec4<T>& V) {
  return dot(P.p, V);
}

/// Converts the coefficients to another number type (exact to rational, rounded to float).
template <class To, class From>
plane<To> convert(const plane<From>& P) {
  return plane<To>{convert<To>(P.p)};
}

}  // namespace shadowproof
