#pragma once
/// Change of basis between a child frame and its parent (seed 004).
///
/// A child frame has axes X_c, Y_c, Z_c and origin O_c, all given in parent coordinates. The
/// child point (a, b, c) is the parent point O_c + a X_c + b Y_c + c Z_c, hence the matrix below.
#include <array>

#include "shadowproof/core/homogeneous.h"
#include "shadowproof/constructions/normal_matrix.h"

namespace shadowproof {

/// A 3-vector (x, y, z) of parent coordinates.
template <class T>
using vec3 = std::array<T, 3>;

/// Child → parent matrix with columns X_c, Y_c, Z_c, O_c:
///   [ X_c.x  Y_c.x  Z_c.x  O_c.x ]
///   [ X_c.y  Y_c.y  Z_c.y  O_c.y ]
///   [ X_c.z  Y_c.z  Z_c.z  O_c.z ]
///   [ 0      0      0      1     ]
/// Any axes are accepted; when they are linearly dependent the matrix is singular and
/// parent_to_child throws.
template <class T>
mat4<T> child_to_parent(const vec3<T>& x_axis, const vec3<T>& y_axis, const vec3<T>& z_axis,
                        const vec3<T>& origin) {
  mat4<T> M = identity4<T>();
  for (std::size_t i = 0; i < 3; ++i) {
    M(i, 0) = x_axis[i];
    M(i, 1) = y_axis[i];
    M(i, 2) = z_axis[i];
    M(i, 3) = origin[i];
  }
  return M;
}

/// Parent → child = (child → parent)⁻¹, for any linearly independent axes.
/// Throws error "matrix.singular" when the axes are linearly dependent.
template <class T>
mat4<T> parent_to_child(const vec3<T>& x_axis, const vec3<T>& y_axis, const vec3<T>& z_axis,
                        const vec3<T>& origin) {
  return inverse(child_to_parent(x_axis, y_axis, z_axis, origin));
}

/// Seed 004's shortcut for parent → child: rows X_c, Y_c, Z_c (the transpose of the 3x3 block)
/// and translation −(X_c·O_c, Y_c·O_c, Z_c·O_c):
///   [ X_cᵀ  −X_c·O_c ; Y_cᵀ  −Y_c·O_c ; Z_cᵀ  −Z_c·O_c ; 0 0 0 1 ]
/// Equals parent_to_child exactly when the axes are orthonormal (is_orthonormal); for any
/// other axes it is a different (wrong) matrix. No check is made.
template <class T>
mat4<T> parent_to_child_orthonormal(const vec3<T>& x_axis, const vec3<T>& y_axis,
                                    const vec3<T>& z_axis, const vec3<T>& origin) {
  const std::array<const vec3<T>*, 3> axes{&x_axis, &y_axis, &z_axis};
  mat4<T> M = identity4<T>();
  for (std::size_t i = 0; i < 3; ++i) {
    T d = T(0);
    for (std::size_t j = 0; j < 3; ++j) {
      M(i, j) = (*axes[i])[j];
      d += (*axes[i])[j] * origin[j];
    }
    M(i, 3) = -d;
  }
  return M;
}

/// True when X·X = Y·Y = Z·Z = 1 and X·Y = Y·Z = Z·X = 0, exactly.
template <class T>
bool is_orthonormal(const vec3<T>& x, const vec3<T>& y, const vec3<T>& z) {
  auto dot = [](const vec3<T>& u, const vec3<T>& v) {
    return T(u[0] * v[0] + u[1] * v[1] + u[2] * v[2]);
  };
  return dot(x, x) == T(1) && dot(y, y) == T(1) && dot(z, z) == T(1) && dot(x, y) == T(0) &&
         dot(y, z) == T(0) && dot(z, x) == T(0);
}

}  // namespace shadowproof
