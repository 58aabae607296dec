#pragma once
/// Point and vector algebra in 3D over std::array<T, 3>, generic over the number type T
/// (rational, double, float, intervals). Only +, - and * are used, so every function is exact
/// for rationals; for floats each is the naive formula, rounded after every operation.
#include <array>

#include "shadowproof/core/homogeneous.h"

namespace shadowproof {

/// a − b, componentwise.
template <class T>
std::array<T, 3> difference(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

/// a + b, componentwise.
template <class T>
std::array<T, 3> sum(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

/// k a, componentwise.
template <class T>
std::array<T, 3> scaled(const detail::scalar_of<T>& k, const std::array<T, 3>& a) {
  return {k * a[0], k * a[1], k * a[2]};
}

/// a · b = a₀b₀ + a₁b₁ + a₂b₂.
template <class T>
T dot(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// a × b = (a₁b₂ − a₂b₁, a₂b₀ − a₀b₂, a₀b₁ − a₁b₀): orthogonal to a and b, zero exactly when
/// they are parallel (or one is zero); |a × b| is the area of the parallelogram they span.
template <class T>
std::array<T, 3> cross(const std::array<T, 3>& a, const std::array<T, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// True when every component is zero (exact for rationals; −0 counts as zero for floats).
template <class T>
bool is_zero(const std::array<T, 3>& a) {
  return a[0] == 0 && a[1] == 0 && a[2] == 0;
}

/// a + u (b − a): the point at parameter u on the line through a (u = 0) and b (u = 1).
template <class T>
std::array<T, 3> lerp(const std::array<T, 3>& a, const std::array<T, 3>& b, const detail::scalar_of<T>& u) {
  return {a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2])};
}

/// The value h·(X, 1) = h₀x + h₁y + h₂z + h₃ of the homogeneous plane (or linear form) h at the
/// finite point X: zero on the plane, its sign tells the side. For a plane P this is P·X.
template <class T>
T plane_value(const vec4<T>& h, const std::array<T, 3>& X) {
  return h[0] * X[0] + h[1] * X[1] + h[2] * X[2] + h[3];
}

}  // namespace shadowproof
