#pragma once
/// Notation shared by the derivations: homogeneous vectors and 4x4 matrices as GiNaC matrices
/// (column vectors, image = M V), the usual elementary matrices, and a deterministic LaTeX
/// printer for the document.
#include <ginac/ginac.h>

#include <string>

namespace shadowproof::proofs {

using GiNaC::ex;
using GiNaC::matrix;

/// A real symbol named `name` that prints as `tex` in the document.
GiNaC::realsymbol symbol(const std::string& name, const std::string& tex);

/// Column vector (x, y, z, w) or (x, y, z).
matrix column(const ex& x, const ex& y, const ex& z, const ex& w);
matrix column(const ex& x, const ex& y, const ex& z);
/// Entry i of a column vector.
ex at(const matrix& v, unsigned i);
/// a · b = Σ aᵢ bᵢ of two column vectors of the same length.
ex dot(const matrix& a, const matrix& b);
/// a · b over the first three coordinates only.
ex dot3(const matrix& a, const matrix& b);
/// The n x n identity.
matrix identity(unsigned n);
/// Outer product a bᵀ of two column vectors.
matrix outer(const matrix& a, const matrix& b);
/// Translation T(x, y, z) and scaling S(x, y, z) as 4x4 matrices.
matrix translation(const ex& x, const ex& y, const ex& z);
matrix scaling(const ex& x, const ex& y, const ex& z);
/// The 4x4 matrix [A 0; 0 1] of a 3x3 matrix A.
matrix embed(const matrix& a3);
/// Rotation of the quaternion q = (w, x, y, z) ≠ 0, divided by |q|² so that it is orthogonal
/// for every q: every rotation is R(q) for some q, and the entries are rational functions.
matrix quaternion_rotation(const ex& w, const ex& x, const ex& y, const ex& z);
/// Products that stay GiNaC matrices (a * b on ex would stay unevaluated).
matrix operator*(const matrix& a, const matrix& b);
matrix operator*(const ex& s, const matrix& a);
matrix operator+(const matrix& a, const matrix& b);
matrix operator-(const matrix& a, const matrix& b);
/// Every entry put over a common denominator and cancelled (GiNaC's normal()).
matrix normalised(const matrix& a);

/// LaTeX of `e` with a fixed order of terms and factors (GiNaC's own order follows hash values
/// and changes from run to run; the document must not). Matrices print as pmatrix.
std::string tex(const ex& e);
/// LaTeX of `e` after normalisation to one fraction num/den, both expanded, with the sign fixed
/// so that the leading term of den is positive. Applies entry by entry to matrices.
std::string tex_normal(const ex& e);

}  // namespace shadowproof::proofs
