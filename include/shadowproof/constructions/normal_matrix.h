#pragma once
/// The normal matrix G = (M⁻¹)ᵀ: how normals (and planes) transform when points transform by M.
///
/// Why not M itself (seed 004's argument): a tangent t goes to M t; a normal n must go to some
/// G n with (M t)ᵀ (G n) = tᵀ (Mᵀ G) n = 0 for every t ⟂ n, which holds for all such pairs
/// exactly when Mᵀ G = λ I, i.e. G ∝ (M⁻¹)ᵀ. Under non-uniform scale or shear M ≠ (M⁻¹)ᵀ up to
/// scale, and M n is no longer perpendicular to the surface.
#include <string>

#include "shadowproof/core/error.h"
#include "shadowproof/core/homogeneous.h"

namespace shadowproof {

/// M⁻¹ = adj(M) / det(M), exact for rationals.
/// Throws error "matrix.singular" when det(M) = 0 (no inverse exists). In float the test is
/// det == 0 exactly, with no tolerance: a nearly singular float matrix yields huge entries.
template <class T>
mat4<T> inverse(const mat4<T>& M) {
  const T det = determinant(M);
  if (det == T(0))
    throw error(errc::matrix_singular,
                "the matrix is singular (determinant 0): it flattens space, so neither its inverse "
                "nor its normal matrix (M⁻¹)ᵀ exists");
  return (T(1) / det) * adjugate(M);
}

/// Normal matrix G = (M⁻¹)ᵀ. A plane P (row 4-vector: P · X = 0) maps to G P, so that
/// (G P) · (M X) = P · X; for P = (n, 0) the first three entries of G P are the transformed
/// normal. Throws error "matrix.singular" when det(M) = 0.
template <class T>
mat4<T> normal_matrix(const mat4<T>& M) {
  return transpose(inverse(M));
}

/// Division-free form: the cofactor matrix cof(M) = adj(M)ᵀ = det(M) · (M⁻¹)ᵀ. Proportional to
/// G when det(M) ≠ 0, with the sign of det(M): for det(M) < 0 (mirroring) it flips every normal,
/// so multiply by sign(det M) to keep orientation. Never throws, but for singular M it is no
/// normal transform (a singular M flattens space; cof(M) has rank ≤ 1 then, 0 for rank ≤ 2).
template <class T>
mat4<T> normal_matrix_adjugate(const mat4<T>& M) {
  return transpose(adjugate(M));
}

/// The linear part of M, [A 0; 0 1] with A the upper-left 3x3 block: what a shader applies to
/// directions (w = 0). Translations and the projective row are dropped.
template <class T>
mat4<T> linear_part(const mat4<T>& M) {
  mat4<T> r = identity4<T>();
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) r(i, j) = M(i, j);
  return r;
}

/// The 3x3 normal matrix shaders use, (A⁻¹)ᵀ of the upper-left block A, embedded as
/// [(A⁻¹)ᵀ 0; 0 1]. For an affine M (last row 0 0 0 1) it agrees with normal_matrix(M) on
/// directions (n, 0) in the first three entries. Throws error "matrix.singular" when det A = 0.
template <class T>
mat4<T> normal_matrix3(const mat4<T>& M) {
  return normal_matrix(linear_part(M));
}

}  // namespace shadowproof
