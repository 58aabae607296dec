#pragma once
/// Matrices and column vectors of recorded terms, with their notation: every operation computes
/// the entries (what is checked) and the LaTeX (what is printed) together, so a product prints as
/// "T(\ell) N T(-\ell)" and is checked entry by entry. Column vectors: the image of V is M V.
#include <initializer_list>
#include <string>
#include <vector>

#include "term.h"

namespace shadowproof::proofs {

class mat {
 public:
  /// The rows x cols zero matrix, printed as 0.
  mat(unsigned rows, unsigned cols);
  /// A matrix written out entry by entry, printed as a pmatrix of its entries.
  mat(std::initializer_list<std::initializer_list<term>> rows);
  /// Entries (row-major) with the notation `tex` of precedence `p`.
  mat(unsigned rows, unsigned cols, std::vector<term> entries, std::string tex, tex_precedence p);

  /// `value` printed as the name `tex` (a symbol for a matrix the text defines).
  static mat named(const std::string& tex, const mat& value);
  /// A column vector written out.
  static mat column(std::vector<term> entries);

  unsigned rows() const { return rows_; }
  unsigned cols() const { return cols_; }
  /// The entry as computed (for building further expressions).
  const term& operator()(unsigned i, unsigned j) const { return e_[i * cols_ + j]; }
  /// Entry i of a column vector, as computed.
  const term& operator[](unsigned i) const { return e_[i]; }
  /// The entry with notation: the entry itself when it is a number or a variable, otherwise
  /// shown as "M_{12}" (or "V_x" for vectors) under the matrix's name.
  term entry(unsigned i, unsigned j) const;
  term entry(unsigned i) const;
  const std::vector<term>& entries() const { return e_; }

  std::string tex() const;
  std::string tex(tex_precedence context) const;
  tex_precedence precedence() const { return precedence_; }
  /// True when the notation is the written-out entries.
  bool written_out() const { return written_out_; }
  /// The same entries with new notation.
  mat as(const std::string& tex, tex_precedence p) const;
  /// The same entries printed written out.
  mat written() const;

 private:
  unsigned rows_ = 0, cols_ = 0;
  std::vector<term> e_;
  std::string tex_;
  tex_precedence precedence_ = tex_precedence::atom;
  bool written_out_ = false;
};

mat operator*(const mat& a, const mat& b);
mat operator*(const term& s, const mat& a);
mat operator+(const mat& a, const mat& b);
mat operator-(const mat& a, const mat& b);
mat operator-(const mat& a);
/// Aᵀ.
mat transpose(const mat& a);
/// Σ aᵢ bᵢ of two column vectors, printed "A \cdot B".
term dot(const mat& a, const mat& b);
/// The same sum printed "\langle A, B \rangle".
term inner(const mat& a, const mat& b);
/// The determinant (Laplace expansion along the first row), printed "\det A".
term det(const mat& a);
/// The n x n identity, printed I.
mat identity(unsigned n);
/// Column vectors written out.
mat column(const term& x, const term& y, const term& z, const term& w);
mat column(const term& x, const term& y, const term& z);
/// A function of a matrix: `name` applied to `args`, e.g. "\operatorname{ndc}(M X)".
mat apply(const std::string& name, const mat& arg, const mat& value);
/// (x/w, y/w, z/w) of a homogeneous column, printed "\operatorname{affine}(V)".
mat affine(const mat& v);
/// The upper-left k x k block.
mat block(const mat& a, unsigned k);

// The usual 4x4 matrices (column vectors), written out and printed by name.
/// T(x, y, z).
mat translation(const term& x, const term& y, const term& z, const std::string& tex);
/// S(x, y, z).
mat scaling(const term& x, const term& y, const term& z, const std::string& tex);
/// [A 0; 0 1] of a 3x3 A.
mat embed(const mat& a3);

}  // namespace shadowproof::proofs
