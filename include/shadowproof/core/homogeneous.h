#pragma once
/// Homogeneous 4-vectors and 4x4 matrices, generic over the number type T (rational, double,
/// float, intervals). Column vectors: the image of V under M is M V. Only +, -, * and
/// comparisons are used, so every operation is exact for rationals.
#include <array>
#include <cstddef>
#include <ostream>

#include "shadowproof/core/number.h"

namespace shadowproof {

namespace detail {
// Non-deduced context, so a scalar expression (e.g. a gmpxx expression template) converts to T.
template <class T>
struct type_identity {
  using type = T;
};
template <class T>
using scalar_of = typename type_identity<T>::type;
}  // namespace detail

/// Homogeneous vector (x, y, z, w); w = 0 is a point at infinity (a direction).
template <class T>
struct vec4 {
  std::array<T, 4> v{T(0), T(0), T(0), T(0)};

  T& operator[](std::size_t i) { return v[i]; }
  const T& operator[](std::size_t i) const { return v[i]; }
  friend bool operator==(const vec4& a, const vec4& b) { return a.v == b.v; }
  friend bool operator!=(const vec4& a, const vec4& b) { return !(a == b); }
};

/// 4x4 matrix, row-major storage m[row][col].
template <class T>
struct mat4 {
  std::array<std::array<T, 4>, 4> m{};

  mat4() {
    for (auto& row : m) row.fill(T(0));
  }
  T& operator()(std::size_t r, std::size_t c) { return m[r][c]; }
  const T& operator()(std::size_t r, std::size_t c) const { return m[r][c]; }
  friend bool operator==(const mat4& a, const mat4& b) { return a.m == b.m; }
  friend bool operator!=(const mat4& a, const mat4& b) { return !(a == b); }
};

template <class T>
vec4<T> make_vec4(const T& x, const T& y, const T& z, const T& w) {
  vec4<T> r;
  r[0] = x; r[1] = y; r[2] = z; r[3] = w;
  return r;
}

/// The finite point (x, y, z, 1).
template <class T>
vec4<T> make_point(const T& x, const T& y, const T& z) {
  return make_vec4<T>(x, y, z, T(1));
}

/// Builds a matrix from 16 entries given row by row.
template <class T>
mat4<T> make_mat4(const std::array<T, 16>& rows) {
  mat4<T> r;
  for (std::size_t i = 0; i < 16; ++i) r(i / 4, i % 4) = rows[i];
  return r;
}

// --- vector algebra -----------------------------------------------------------------------

/// a · b = Σ aᵢ bᵢ over all four coordinates.
template <class T>
T dot(const vec4<T>& a, const vec4<T>& b) {
  T s = a[0] * b[0];
  for (std::size_t i = 1; i < 4; ++i) s += a[i] * b[i];
  return s;
}

/// a·b over x, y, z only (the normal part of a plane, the direction part of a light).
template <class T>
T dot3(const vec4<T>& a, const vec4<T>& b) {
  T s = a[0] * b[0];
  s += a[1] * b[1];
  s += a[2] * b[2];
  return s;
}

template <class T>
vec4<T> operator+(const vec4<T>& a, const vec4<T>& b) {
  vec4<T> r;
  for (std::size_t i = 0; i < 4; ++i) r[i] = a[i] + b[i];
  return r;
}

template <class T>
vec4<T> operator-(const vec4<T>& a, const vec4<T>& b) {
  vec4<T> r;
  for (std::size_t i = 0; i < 4; ++i) r[i] = a[i] - b[i];
  return r;
}

template <class T>
vec4<T> operator*(const detail::scalar_of<T>& s, const vec4<T>& a) {
  vec4<T> r;
  for (std::size_t i = 0; i < 4; ++i) r[i] = s * a[i];
  return r;
}

template <class T>
bool is_zero(const vec4<T>& a) {
  return a[0] == T(0) && a[1] == T(0) && a[2] == T(0) && a[3] == T(0);
}

/// True when a = λ b for some λ ≠ 0 (both non-zero): every 2x2 minor aᵢbⱼ − aⱼbᵢ vanishes.
template <class T>
bool proportional(const vec4<T>& a, const vec4<T>& b) {
  if (is_zero(a) || is_zero(b)) return false;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = i + 1; j < 4; ++j)
      if (a[i] * b[j] != a[j] * b[i]) return false;
  return true;
}

// --- matrix algebra -----------------------------------------------------------------------

template <class T>
mat4<T> identity4() {
  mat4<T> r;
  for (std::size_t i = 0; i < 4; ++i) r(i, i) = T(1);
  return r;
}

/// Translation T(t): X ↦ X + t (for w = 1).
template <class T>
mat4<T> translation(const T& x, const T& y, const T& z) {
  mat4<T> r = identity4<T>();
  r(0, 3) = x; r(1, 3) = y; r(2, 3) = z;
  return r;
}

/// Scaling S(sx, sy, sz).
template <class T>
mat4<T> scaling(const T& sx, const T& sy, const T& sz) {
  mat4<T> r = identity4<T>();
  r(0, 0) = sx; r(1, 1) = sy; r(2, 2) = sz;
  return r;
}

/// Outer product a bᵀ.
template <class T>
mat4<T> outer(const vec4<T>& a, const vec4<T>& b) {
  mat4<T> r;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) r(i, j) = a[i] * b[j];
  return r;
}

template <class T>
mat4<T> transpose(const mat4<T>& a) {
  mat4<T> r;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) r(i, j) = a(j, i);
  return r;
}

template <class T>
mat4<T> operator+(const mat4<T>& a, const mat4<T>& b) {
  mat4<T> r;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) r(i, j) = a(i, j) + b(i, j);
  return r;
}

template <class T>
mat4<T> operator-(const mat4<T>& a, const mat4<T>& b) {
  mat4<T> r;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) r(i, j) = a(i, j) - b(i, j);
  return r;
}

template <class T>
mat4<T> operator*(const detail::scalar_of<T>& s, const mat4<T>& a) {
  mat4<T> r;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) r(i, j) = s * a(i, j);
  return r;
}

/// (A B)ᵢⱼ = Σₖ Aᵢₖ Bₖⱼ.
template <class T>
mat4<T> operator*(const mat4<T>& a, const mat4<T>& b) {
  mat4<T> r;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      T s = a(i, 0) * b(0, j);
      for (std::size_t k = 1; k < 4; ++k) s += a(i, k) * b(k, j);
      r(i, j) = s;
    }
  return r;
}

/// (M V)ᵢ = Σⱼ Mᵢⱼ Vⱼ: the image of V (column vector convention).
template <class T>
vec4<T> operator*(const mat4<T>& a, const vec4<T>& x) {
  vec4<T> r;
  for (std::size_t i = 0; i < 4; ++i) {
    T s = a(i, 0) * x[0];
    for (std::size_t k = 1; k < 4; ++k) s += a(i, k) * x[k];
    r[i] = s;
  }
  return r;
}

template <class T>
bool is_zero(const mat4<T>& a) {
  for (const auto& row : a.m)
    for (const auto& x : row)
      if (x != T(0)) return false;
  return true;
}

/// True when a = λ b for some λ ≠ 0: the same projective map. Division-free (cross products).
template <class T>
bool proportional(const mat4<T>& a, const mat4<T>& b) {
  if (is_zero(a) || is_zero(b)) return false;
  // Find a pivot where b is non-zero; then a = λ b with λ = a_p / b_p iff a_ij b_p = b_ij a_p.
  std::size_t pr = 0, pc = 0;
  for (std::size_t i = 0; i < 16; ++i)
    if (b(i / 4, i % 4) != T(0)) { pr = i / 4; pc = i % 4; break; }
  const T& ap = a(pr, pc);
  const T& bp = b(pr, pc);
  if (ap == T(0)) return false;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      if (a(i, j) * bp != b(i, j) * ap) return false;
  return true;
}

/// Determinant by Laplace expansion in 2x2 minors (division-free, exact for rationals).
template <class T>
T determinant(const mat4<T>& a) {
  auto m2 = [&](std::size_t r0, std::size_t r1, std::size_t c0, std::size_t c1) {
    return T(a(r0, c0) * a(r1, c1) - a(r0, c1) * a(r1, c0));
  };
  T s0 = m2(0, 1, 0, 1), s1 = m2(0, 1, 0, 2), s2 = m2(0, 1, 0, 3);
  T s3 = m2(0, 1, 1, 2), s4 = m2(0, 1, 1, 3), s5 = m2(0, 1, 2, 3);
  T c5 = m2(2, 3, 2, 3), c4 = m2(2, 3, 1, 3), c3 = m2(2, 3, 1, 2);
  T c2 = m2(2, 3, 0, 3), c1 = m2(2, 3, 0, 2), c0 = m2(2, 3, 0, 1);
  T d = s0 * c5;
  d -= s1 * c4;
  d += s2 * c3;
  d += s3 * c2;
  d -= s4 * c1;
  d += s5 * c0;
  return d;
}

/// Determinant of the 3x3 matrix left when row r and column c are deleted.
template <class T>
T minor3(const mat4<T>& a, std::size_t r, std::size_t c) {
  std::array<std::size_t, 3> rows{}, cols{};
  for (std::size_t i = 0, k = 0; i < 4; ++i) if (i != r) rows[k++] = i;
  for (std::size_t j = 0, k = 0; j < 4; ++j) if (j != c) cols[k++] = j;
  auto e = [&](std::size_t i, std::size_t j) -> const T& { return a(rows[i], cols[j]); };
  T d = e(0, 0) * (e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1));
  d -= e(0, 1) * (e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0));
  d += e(0, 2) * (e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0));
  return d;
}

/// adj(A)ᵢⱼ = (−1)^(i+j) minor(A, j, i); A adj(A) = det(A) I. Division-free.
template <class T>
mat4<T> adjugate(const mat4<T>& a) {
  mat4<T> r;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) {
      T m = minor3(a, j, i);
      r(i, j) = ((i + j) % 2 == 0) ? m : T(-m);
    }
  return r;
}

/// Converts every entry with number_cast (exact to rational, correctly rounded to float).
template <class To, class From>
vec4<To> convert(const vec4<From>& a) {
  vec4<To> r;
  for (std::size_t i = 0; i < 4; ++i) r[i] = number_cast<To>(a[i]);
  return r;
}

template <class To, class From>
mat4<To> convert(const mat4<From>& a) {
  mat4<To> r;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) r(i, j) = number_cast<To>(a(i, j));
  return r;
}

}  // namespace shadowproof
