// Seed 004: change of basis from child axes; inverse = transpose exactly for orthonormal axes.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation change_of_basis() {
  const auto qw = symbol("qw", "q_w"), qx = symbol("qx", "q_x"), qy = symbol("qy", "q_y"),
             qz = symbol("qz", "q_z");
  const auto ox = symbol("ox", "O_x"), oy = symbol("oy", "O_y"), oz = symbol("oz", "O_z");
  const auto a = symbol("a", "a"), b = symbol("b", "b"), c = symbol("c", "c");
  std::vector<GiNaC::realsymbol> u;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const std::string ij = std::to_string(i) + std::to_string(j);
      u.push_back(symbol("u" + ij, "u_{" + ij + "}"));
    }

  const matrix A = quaternion_rotation(qw, qx, qy, qz);  // columns X_c, Y_c, Z_c
  const matrix Xc = column(A(0, 0), A(1, 0), A(2, 0)), Yc = column(A(0, 1), A(1, 1), A(2, 1)),
               Zc = column(A(0, 2), A(1, 2), A(2, 2));
  const matrix O = column(ox, oy, oz);
  matrix M = embed(A);
  M(0, 3) = ox;
  M(1, 3) = oy;
  M(2, 3) = oz;

  derivation D;
  D.slug = "change_of_basis";
  D.title = "Change of basis and the transpose as inverse";
  D.source = "seed 004";
  D.intro =
      "A child frame has origin $O_c = (O_x, O_y, O_z)$ and axes $X_c, Y_c, Z_c$, given in parent "
      "coordinates. A point with child coordinates $(a, b, c)$ is $O_c + a X_c + b Y_c + c Z_c$ in "
      "the parent. For orthonormal axes the 3x3 matrix $A = (X_c\\ Y_c\\ Z_c)$ is a rotation; every "
      "rotation is the quaternion rotation $R(q)/|q|^2$ for some $q \\neq 0$, so checking that form "
      "checks all orthonormal (right-handed) frames.";
  D.assume(qw * qw + qx * qx + qy * qy + qz * qz, "|q|^2 \\neq 0");

  D.show("the child-to-parent matrix",
         "Walking from $O_c$ by $a X_c + b Y_c + c Z_c$ is the matrix with columns $X_c, Y_c, Z_c, O_c$ "
         "applied to $(a, b, c, 1)$.",
         {M * column(a, b, c, 1), "M_{c \\to p}\\,(a, b, c, 1)"},
         {column(ox, oy, oz, 1) + a * embed(A) * column(1, 0, 0, 0) + b * embed(A) * column(0, 1, 0, 0) +
              c * embed(A) * column(0, 0, 1, 0),
          "(O_c + a X_c + b Y_c + c Z_c,\\ 1)"});
  D.show("directions ignore the origin",
         "A vector has $w = 0$, so the last column drops out; that is why the seed removes it for "
         "vectors.",
         {M * column(a, b, c, 0), "M_{c \\to p}\\,(a, b, c, 0)"},
         {embed(A) * column(a, b, c, 0), "(a X_c + b Y_c + c Z_c,\\ 0)"});
  D.show("the axes are orthonormal",
         "$X_c \\cdot X_c = 1$, $X_c \\cdot Y_c = 0$, and so on: the entries of $A^{\\mathsf T} A$.",
         {matrix{{dot(Xc, Xc), dot(Xc, Yc), dot(Xc, Zc)},
                 {dot(Yc, Xc), dot(Yc, Yc), dot(Yc, Zc)},
                 {dot(Zc, Xc), dot(Zc, Yc), dot(Zc, Zc)}},
          "A^{\\mathsf T} A"},
         identity(3));
  D.show("so the transpose is the inverse",
         "$A^{\\mathsf T} A = I$ for a square matrix implies $A A^{\\mathsf T} = I$: parent to child is "
         "$A^{\\mathsf T}$, whose rows are the axes.",
         {A * A.transpose(), "A A^{\\mathsf T}"}, identity(3));
  D.show("child coordinates are dot products with the axes",
         "$A^{\\mathsf T} v = (X_c \\cdot v, Y_c \\cdot v, Z_c \\cdot v)$ recovers $(a, b, c)$ from "
         "$v = a X_c + b Y_c + c Z_c$.",
         {A.transpose() * (A * column(a, b, c)), "A^{\\mathsf T} (a X_c + b Y_c + c Z_c)"}, column(a, b, c));
  matrix inverse4 = embed(A.transpose());
  const matrix back = (-1) * (A.transpose() * O);
  for (unsigned i = 0; i < 3; ++i) inverse4(i, 3) = at(back, i);
  D.show("with the origin, the inverse is not the transpose",
         "For points, $M_{p \\to c} = \\begin{pmatrix} A^{\\mathsf T} & -A^{\\mathsf T} O_c \\\\ 0 & 1 "
         "\\end{pmatrix}$.",
         {M * inverse4, "M_{c \\to p} \\begin{pmatrix} A^{\\mathsf T} & -A^{\\mathsf T} O_c \\\\ 0 & 1 "
                        "\\end{pmatrix}"},
         identity(4));
  D.disprove("the 4x4 matrix is inverted by its transpose",
           "Only the 3x3 part is orthogonal. With $q = (1, 0, 0, 0)$ (no rotation) and origin "
           "$(1, 0, 0)$, $M^{\\mathsf T} M$ picks up the origin.",
           {M.transpose() * M, "M_{c \\to p}^{\\mathsf T} M_{c \\to p}"}, identity(4),
           {{qw, 1}, {qx, 0}, {qy, 0}, {qz, 0}, {ox, 1}, {oy, 0}, {oz, 0}});
  const matrix U{{u[0], u[1], u[2]}, {u[3], u[4], u[5]}, {u[6], u[7], u[8]}};
  D.disprove("the transpose inverts any axes",
           "The seed's precondition matters: for axes that are not orthonormal, for example $X_c$ of "
           "length 2, $A^{\\mathsf T} A \\neq I$.",
           {U.transpose() * U, "A^{\\mathsf T} A"}, identity(3),
           {{u[0], 2}, {u[1], 0}, {u[2], 0}, {u[3], 0}, {u[4], 1}, {u[5], 0}, {u[6], 0}, {u[7], 0}, {u[8], 1}});
  D.conclusion =
      "For orthonormal axes the parent-to-child matrix of directions is the transpose; for points the "
      "origin adds the column $-A^{\\mathsf T} O_c$.";
  return D;
}

}  // namespace shadowproof::proofs
