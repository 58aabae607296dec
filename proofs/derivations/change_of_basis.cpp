// Seed 004: change of basis from child axes; inverse = transpose exactly for orthonormal axes; the
// library's child_to_parent, parent_to_child and the orthonormal shortcut against it.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/basis.h"
#include "shadowproof/constructions/reflect.h"

namespace shadowproof::proofs {

derivation change_of_basis() {
  const term qw = var("qw", "q_w"), qx = var("qx", "q_x"), qy = var("qy", "q_y"), qz = var("qz", "q_z");
  const term ox = var("ox", "O_x"), oy = var("oy", "O_y"), oz = var("oz", "O_z");
  const term a = var("a", "a"), b = var("b", "b"), c = var("c", "c");
  std::vector<term> u;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const std::string ij = std::to_string(i + 1) + std::to_string(j + 1);
      u.push_back(var("u" + ij, "u_{" + ij + "}"));
    }

  // The axes are the columns of a rotation: the transpose of the library's quaternion frame.
  const frame3<term> frame = frame_from_quaternion(qw, qx, qy, qz);
  const mat Xc = mat::named("X_c", column(frame.rows[0][0], frame.rows[0][1], frame.rows[0][2]));
  const mat Yc = mat::named("Y_c", column(frame.rows[1][0], frame.rows[1][1], frame.rows[1][2]));
  const mat Zc = mat::named("Z_c", column(frame.rows[2][0], frame.rows[2][1], frame.rows[2][2]));
  const mat O = mat::named("O_c", column(ox, oy, oz));
  const mat A = mat(3, 3,
                    {Xc[0], Yc[0], Zc[0], Xc[1], Yc[1], Zc[1], Xc[2], Yc[2], Zc[2]},
                    "A", tex_precedence::atom);
  const mat M = mat::named("M_{c \\to p}", mat{{Xc[0], Yc[0], Zc[0], ox},
                                              {Xc[1], Yc[1], Zc[1], oy},
                                              {Xc[2], Yc[2], Zc[2], oz},
                                              {0, 0, 0, 1}});
  const mat child = column(a, b, c, 1).as("\\left(a, b, c, 1\\right)", tex_precedence::atom);

  derivation D;
  D.slug = "change_of_basis";
  D.title = "Change of basis and the transpose as inverse";
  D.source = "seed 004";
  D.intro =
      "A child frame has origin $O_c = (O_x, O_y, O_z)$ and axes $X_c, Y_c, Z_c$, given in parent coordinates. "
      "A point with child coordinates $(a, b, c)$ is $O_c + a X_c + b Y_c + c Z_c$ in the parent. For "
      "orthonormal axes the 3x3 matrix $A = (X_c\\ Y_c\\ Z_c)$ is a rotation; every rotation is the quaternion "
      "rotation $R(q)/|q|^2$ of the library's `frame_from_quaternion` for some $q \\neq 0$ (here $A$ is its "
      "transpose, so the axes are its rows), so checking that form checks all orthonormal right-handed "
      "frames. Vectors are columns.";
  D.assume_nonzero(qw * qw + qx * qx + qy * qy + qz * qz);

  D.define("the child-to-parent matrix", "Columns $X_c, Y_c, Z_c, O_c$.", M, M.written());
  D.define("the child-to-parent matrix walks from O_c",
         "$M_{c \\to p} (a, b, c, 1)$ is $O_c + a X_c + b Y_c + c Z_c$ with $w = 1$.", M * child,
         column(ox + a * Xc[0] + b * Yc[0] + c * Zc[0], oy + a * Xc[1] + b * Yc[1] + c * Zc[1],
                oz + a * Xc[2] + b * Yc[2] + c * Zc[2], 1)
             .as("\\left(O_c + a X_c + b Y_c + c Z_c,\\ 1\\right)", tex_precedence::atom));
  D.show("the axes are orthonormal",
         "$X_c \\cdot X_c = 1$, $X_c \\cdot Y_c = 0$, and so on: the entries of $A^{\\mathsf T} A$.",
         mat{{dot(Xc, Xc), dot(Xc, Yc), dot(Xc, Zc)}, {dot(Yc, Xc), dot(Yc, Yc), dot(Yc, Zc)}, {dot(Zc, Xc), dot(Zc, Yc), dot(Zc, Zc)}},
         identity(3));
  D.show("so the transpose is the inverse",
         "$A^{\\mathsf T} A = I$ for a square matrix implies $A A^{\\mathsf T} = I$: parent to child is $A^{\\mathsf "
         "T}$, whose rows are the axes.",
         A * transpose(A), identity(3));
  D.show("child coordinates are dot products with the axes",
         "$A^{\\mathsf T} v = (X_c \\cdot v, Y_c \\cdot v, Z_c \\cdot v)$ recovers $(a, b, c)$.",
         transpose(A) * (A * column(a, b, c)), column(a, b, c));
  std::vector<term> inv;
  for (unsigned i = 0; i < 3; ++i) {
    const mat& axis = i == 0 ? Xc : (i == 1 ? Yc : Zc);
    inv.push_back(axis[0]);
    inv.push_back(axis[1]);
    inv.push_back(axis[2]);
    inv.push_back(-dot(axis, O));
  }
  for (int j = 0; j < 4; ++j) inv.push_back(term(j == 3 ? 1 : 0));
  const mat inverse4 = mat(4, 4, inv, "\\begin{pmatrix} A^{\\mathsf T} & -A^{\\mathsf T} O_c \\\\ 0 & 1 \\end{pmatrix}",
                           tex_precedence::atom);
  D.show("with the origin, the inverse is not the transpose",
         "For points, $M_{p \\to c}$ has the rows $X_c, Y_c, Z_c$ and the column $-A^{\\mathsf T} O_c$.", M * inverse4,
         identity(4));
  D.disprove("the 4x4 matrix is inverted by its transpose",
             "Only the 3x3 part is orthogonal. With $q = (1, 0, 0, 0)$ (no rotation) and origin $(1, 0, 0)$, "
             "$M^{\\mathsf T} M$ picks up the origin.",
             transpose(M) * M, identity(4), {{qw, 1}, {qx, 0}, {qy, 0}, {qz, 0}, {ox, 1}, {oy, 0}, {oz, 0}});
  const mat U = mat::named("A", mat{{u[0], u[1], u[2]}, {u[3], u[4], u[5]}, {u[6], u[7], u[8]}});
  D.disprove("the transpose inverts any axes",
             "The seed's precondition matters: for axes that are not orthonormal, for example $X_c$ of length 2, "
             "$A^{\\mathsf T} A \\neq I$.",
             transpose(U) * U, identity(3),
             {{u[0], 2}, {u[1], 0}, {u[2], 0}, {u[3], 0}, {u[4], 1}, {u[5], 0}, {u[6], 0}, {u[7], 0}, {u[8], 1}});

  const auto decide = comparisons_from(D.facts);
  const scoped_comparisons installed(*decide);
  const vec3<term> x3{Xc[0], Xc[1], Xc[2]}, y3{Yc[0], Yc[1], Yc[2]}, z3{Zc[0], Zc[1], Zc[2]}, o3{ox, oy, oz};
  D.code("the library's child_to_parent", "Columns $X_c, Y_c, Z_c, O_c$, applied to a child point.", "basis.h",
         from_library(child_to_parent(x3, y3, z3, o3), code_tex("child_to_parent") + "(X_c, Y_c, Z_c, O_c)") * child,
         M * child);
  D.code("the library's parent_to_child", "The exact inverse, here for orthonormal axes.", "basis.h",
         from_library(parent_to_child(x3, y3, z3, o3), code_tex("parent_to_child") + "(X_c, Y_c, Z_c, O_c)"), inverse4);
  D.code("the library's orthonormal shortcut", "Rows $X_c, Y_c, Z_c$ and the translation $-(X_c \\cdot O_c, \\ldots)$.",
         "basis.h",
         from_library(parent_to_child_orthonormal(x3, y3, z3, o3),
                      code_tex("parent_to_child_orthonormal") + "(X_c, Y_c, Z_c, O_c)"),
         inverse4);
  D.code("the library's is_orthonormal accepts every rotation",
         "Its exact comparisons $X_c \\cdot X_c = 1$, ... are decided by normalising: 1 for true.", "basis.h",
         term::shown(term(is_orthonormal(x3, y3, z3) ? 1 : 0), code_tex("is_orthonormal") + "(X_c, Y_c, Z_c)",
                     tex_precedence::atom),
         1);
  D.conclusion =
      "For orthonormal axes the parent-to-child matrix of directions is the transpose; for points the origin "
      "adds the column $-A^{\\mathsf T} O_c$.";
  return D;
}

}  // namespace shadowproof::proofs
