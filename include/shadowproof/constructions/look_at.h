#pragma once
/// Look-at cameras: the view matrix of a camera at `eye` looking at `target` with the up
/// direction `up` (gluLookAt, D3DXMatrixLookAtLH), and its inverse, the camera's placement in
/// the world (gl-matrix targetTo, three.js Object3D.lookAt, wgpu-matrix aim/cameraAim).
///
/// With w = eye − target (right-handed: the camera looks down −z) or w = target − eye
/// (left-handed: it looks down +z), the camera's axes are
///   z = w/|w|,   x = (up × z)/|up × z| = X/|X| with X = up × w,   y = z × x = Y/(|w| |X|)
/// with Y = w × X. The view matrix has rows (x, −x·eye), (y, −y·eye), (z, −z·eye), (0, 0, 0, 1);
/// the placement has columns x, y, z, (eye, 1). Every entry is q/√s with q and s rational
/// (s ∈ {|X|², |w|²|X|², |w|²}), so over rationals the constructions return the pairs (q, s):
/// exact, and irrational unless s is a square (irrational.h rounds them correctly).
/// Degenerate cases: eye = target (w = 0) leaves every axis undefined; up parallel to w
/// (including up = 0) leaves x and y undefined while z and its translation exist.
#include <array>
#include <cmath>
#include <type_traits>

#include "shadowproof/constructions/handedness.h"
#include "shadowproof/core/homogeneous.h"

namespace shadowproof {

template <class T>
using vec3 = std::array<T, 3>;

/// One entry q/√s of a matrix (s > 0); `defined` is false when s = 0 (the entry divides by a
/// zero length). Rational entries have s = 1.
template <class T>
struct root_entry {
  T numerator = T(0);
  T radicand = T(1);
  bool defined = true;
};

namespace detail {
template <class T>
vec3<T> cross3(const vec3<T>& a, const vec3<T>& b) {
  return {T(a[1] * b[2] - a[2] * b[1]), T(a[2] * b[0] - a[0] * b[2]), T(a[0] * b[1] - a[1] * b[0])};
}
template <class T>
T dot3(const vec3<T>& a, const vec3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
bool is_zero_length(const T& squared_length) {
  return squared_length == T(0);
}
}  // namespace detail

/// The unnormalised camera frame: W = w, X = up × w, Y = w × X, their squared lengths |W|²,
/// |X|² and the radicand of y, |W|²|X|². Exact over rationals.
template <class T>
struct camera_frame {
  vec3<T> W, X, Y;
  T ww, xx, yy;
};

/// The frame of a camera at eye looking at target with up (see the header comment).
template <class T>
camera_frame<T> make_camera_frame(const vec3<T>& eye, const vec3<T>& target, const vec3<T>& up, handedness h) {
  camera_frame<T> f;
  for (std::size_t i = 0; i < 3; ++i) f.W[i] = h == handedness::right ? T(eye[i] - target[i]) : T(target[i] - eye[i]);
  f.X = detail::cross3(up, f.W);
  f.Y = detail::cross3(f.W, f.X);
  f.ww = detail::dot3(f.W, f.W);
  f.xx = detail::dot3(f.X, f.X);
  f.yy = f.ww * f.xx;
  return f;
}

/// The view matrix (world to eye) as entries q/√s, row-major:
///   [ X/√|X|²         −(X·eye)/√|X|²      ]
///   [ Y/√(|W|²|X|²)   −(Y·eye)/√(|W|²|X|²) ]
///   [ W/√|W|²         −(W·eye)/√|W|²      ]
///   [ 0 0 0           1                    ]
/// Rows 0 and 1 are undefined when |X|² = 0, rows 0 to 2 when |W|² = 0.
template <class T>
std::array<root_entry<T>, 16> look_at_entries(const vec3<T>& eye, const vec3<T>& target, const vec3<T>& up,
                                              handedness h) {
  const camera_frame<T> f = make_camera_frame(eye, target, up, h);
  std::array<root_entry<T>, 16> m;
  const vec3<T>* axes[3] = {&f.X, &f.Y, &f.W};
  const T* radicands[3] = {&f.xx, &f.yy, &f.ww};
  for (std::size_t r = 0; r < 3; ++r) {
    const bool defined = !detail::is_zero_length(*radicands[r]) && !detail::is_zero_length(f.ww);
    for (std::size_t c = 0; c < 3; ++c) m[r * 4 + c] = {(*axes[r])[c], *radicands[r], defined};
    m[r * 4 + 3] = {T(-detail::dot3(*axes[r], eye)), *radicands[r], defined};
  }
  m[12] = m[13] = m[14] = {T(0), T(1), true};
  m[15] = {T(1), T(1), true};
  return m;
}

/// The camera's placement (eye to world), the inverse of the view matrix, as entries q/√s:
/// columns X/√|X|², Y/√(|W|²|X|²), W/√|W|², and (eye, 1) exactly. Columns 0 and 1 are
/// undefined when |X|² = 0, columns 0 to 2 when |W|² = 0.
template <class T>
std::array<root_entry<T>, 16> target_to_entries(const vec3<T>& eye, const vec3<T>& target, const vec3<T>& up,
                                                handedness h) {
  const std::array<root_entry<T>, 16> v = look_at_entries(eye, target, up, h);
  std::array<root_entry<T>, 16> m;
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < 3; ++c) m[r * 4 + c] = v[c * 4 + r];  // the rotation's transpose
  for (std::size_t r = 0; r < 3; ++r) m[r * 4 + 3] = {eye[r], T(1), true};
  m[12] = m[13] = m[14] = {T(0), T(1), true};
  m[15] = {T(1), T(1), true};
  return m;
}

/// Float look-at as libraries write it: z = normalize(w), x = normalize(up × z), y = z × x,
/// one rounding per operation (std::sqrt is correctly rounded). A reference implementation
/// under test, not an exact construction; with eye = target or up ∥ w it divides by zero
/// (NaN/Inf), as a textbook routine without guards does.
template <class F>
mat4<F> look_at_float(const vec3<F>& eye, const vec3<F>& target, const vec3<F>& up, handedness h) {
  static_assert(std::is_floating_point_v<F>, "look_at_float is the float routine; use look_at_entries exactly");
  vec3<F> z;
  for (std::size_t i = 0; i < 3; ++i) z[i] = h == handedness::right ? F(eye[i] - target[i]) : F(target[i] - eye[i]);
  auto normalize = [](vec3<F> v) {
    const F len = std::sqrt(detail::dot3(v, v));
    for (auto& c : v) c = c / len;
    return v;
  };
  z = normalize(z);
  const vec3<F> x = normalize(detail::cross3(up, z));
  const vec3<F> y = detail::cross3(z, x);
  mat4<F> m = identity4<F>();
  const vec3<F>* axes[3] = {&x, &y, &z};
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t c = 0; c < 3; ++c) m(r, c) = (*axes[r])[c];
    m(r, 3) = -detail::dot3(*axes[r], eye);
  }
  return m;
}

}  // namespace shadowproof
