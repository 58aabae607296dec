#pragma once
/// The planar reflection (mirror) matrix, in closed form and as the reference derivation's
/// composition of a frame change, a flip and the frame change back.
#include <array>

#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/plane.h"

namespace shadowproof {

/// Reflection about P = (a, b, c, d), n = (a, b, c), exact without normalising n:
///   M = [ I − 2 n nᵀ / (n·n)   −2 d n / (n·n) ]
///       [ 0   0   0              1            ]
/// M² = I, det M = −1, points of P are fixed, distances are preserved.
template <class T>
mat4<T> reflection_matrix(const plane<T>& P) {
  const T nn = dot3(P.p, P.p);
  mat4<T> M = identity4<T>();
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) M(i, j) -= T(2) * P.p[i] * P.p[j] / nn;
    M(i, 3) = T(-2) * P.p[3] * P.p[i] / nn;
  }
  return M;
}

/// An orthonormal frame given by its rows (U, N, V): U and V span the mirror, N is its unit
/// normal. As a matrix R with these rows, R maps N to the y axis.
template <class T>
struct frame3 {
  std::array<std::array<T, 3>, 3> rows;
};

/// Rotation matrix of the non-zero quaternion q = (qw, qx, qy, qz), divided by |q|²: rational
/// for rational q, so it yields orthonormal frames with exact rational coordinates.
///   R = (1/|q|²) [qw²+qx²−qy²−qz², 2(qx qy − qw qz), 2(qx qz + qw qy); ...]
template <class T>
frame3<T> frame_from_quaternion(const T& qw, const T& qx, const T& qy, const T& qz) {
  const T n = qw * qw + qx * qx + qy * qy + qz * qz;
  frame3<T> f;
  f.rows[0] = {T((qw * qw + qx * qx - qy * qy - qz * qz) / n), T(2 * (qx * qy - qw * qz) / n),
               T(2 * (qx * qz + qw * qy) / n)};
  f.rows[1] = {T(2 * (qx * qy + qw * qz) / n), T((qw * qw - qx * qx + qy * qy - qz * qz) / n),
               T(2 * (qy * qz - qw * qx) / n)};
  f.rows[2] = {T(2 * (qx * qz - qw * qy) / n), T(2 * (qy * qz + qw * qx) / n),
               T((qw * qw - qx * qx - qy * qy + qz * qz) / n)};
  return f;
}

/// The 4x4 rotation whose upper-left block has the frame's rows.
template <class T>
mat4<T> frame_matrix(const frame3<T>& f) {
  mat4<T> R = identity4<T>();
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) R(i, j) = f.rows[i][j];
  return R;
}

/// The mirror ⟨N, X⟩ + d = 0 with the frame's unit normal N = rows[1].
template <class T>
plane<T> frame_plane(const frame3<T>& f, const T& d) {
  return make_plane<T>(f.rows[1][0], f.rows[1][1], f.rows[1][2], d);
}

/// Reflection by frame change, correct for the plane ⟨N, X⟩ + d = 0 (N = rows[1], unit):
///   M = T(−d N) · Rᵀ · S(1, −1, 1) · R · T(d N).
/// T(d N) moves the mirror (through −d N) to the origin, R turns N onto y, S flips y.
/// Equals reflection_matrix(frame_plane(f, d)).
template <class T>
mat4<T> reflection_by_frame(const frame3<T>& f, const T& d) {
  const auto& N = f.rows[1];
  const mat4<T> R = frame_matrix(f);
  return translation<T>(-d * N[0], -d * N[1], -d * N[2]) * transpose(R) * scaling<T>(T(1), T(-1), T(1)) *
         R * translation<T>(d * N[0], d * N[1], d * N[2]);
}

/// Seed 003's composition exactly as printed, M = T(d N) · Rᵀ · S(1, −1, 1) · R · T(−d N).
/// Wrong for ⟨N, X⟩ + d = 0 whenever d ≠ 0: it reflects about ⟨N, X⟩ − d = 0 instead (the
/// translations are swapped). Kept to exhibit the mistake; do not use it.
template <class T>
mat4<T> reflection_by_frame_as_printed_in_seed003(const frame3<T>& f, const T& d) {
  const auto& N = f.rows[1];
  const mat4<T> R = frame_matrix(f);
  return translation<T>(d * N[0], d * N[1], d * N[2]) * transpose(R) * scaling<T>(T(1), T(-1), T(1)) *
         R * translation<T>(-d * N[0], -d * N[1], -d * N[2]);
}

}  // namespace shadowproof
