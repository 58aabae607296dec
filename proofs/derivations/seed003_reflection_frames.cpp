// Seed 003: reflection as a frame change, a flip and the frame change back, for every rotation
// (the library's quaternion frames). The printed product is wrong read with column vectors and
// right read with row vectors; it needs a unit normal in both; and S(1, -1, 1) is a reflection in
// the xz-plane, not about the Y axis.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/reflect.h"

namespace shadowproof::proofs {

namespace {

// The closed form [I - 2nnᵀ/(n·n), -2dn/(n·n); 0 1] of the mirror n·X + d = 0, written out.
mat mirror_closed_form(const mat& n, const term& d, const std::string& tex) {
  const term nn = dot(n, n);
  std::vector<term> e;
  for (unsigned i = 0; i < 4; ++i)
    for (unsigned j = 0; j < 4; ++j) {
      if (i == 3) e.push_back(term(j == 3 ? 1 : 0));
      else if (j == 3) e.push_back(-(2 * d * n[i]) / nn);
      else e.push_back((i == j ? term(1) : term(0)) - 2 * n[i] * n[j] / nn);
    }
  return mat(4, 4, std::move(e), tex, tex_precedence::atom);
}

mat frame_rows(const frame3<term>& f, const std::string& tex) {
  std::vector<term> e;
  for (const auto& row : f.rows)
    for (const auto& x : row) e.push_back(x);
  return mat(3, 3, std::move(e), tex, tex_precedence::atom);
}

}  // namespace

derivation seed003_reflection_frames() {
  const term qw = var("qw", "q_w"), qx = var("qx", "q_x"), qy = var("qy", "q_y"), qz = var("qz", "q_z");
  const term d = var("d", "d"), lambda = var("lambda", "\\lambda");
  const term y = var("y", "y");

  const frame3<term> frame = frame_from_quaternion(qw, qx, qy, qz);
  const mat R3 = frame_rows(frame, code_tex("frame_from_quaternion") + "(q)");
  const mat R = mat::named("R", embed(R3));
  const mat N = mat::named("N", column(R3(1, 0), R3(1, 1), R3(1, 2)));
  const mat S = scaling(1, -1, 1, "S(1, -1, 1)");
  const term q2 = qw * qw + qx * qx + qy * qy + qz * qz;
  const mat dN = d * N, minus_dN = -d * N;
  const mat T_dN = translation(dN[0], dN[1], dN[2], "T(dN)");
  const mat T_minus_dN = translation(minus_dN[0], minus_dN[1], minus_dN[2], "T(-dN)");
  const mat M = mirror_closed_form(N, d, "M(N, d)");

  derivation D;
  D.slug = "seed003_reflection_frames";
  D.title = "Reflection through a frame change, for every rotation";
  D.source = "seed 003";
  D.intro =
      "The mirror is $\\langle N, X \\rangle + d = 0$. The seed builds a frame $R$ with rows $(U, N, V)$, so "
      "that $R$ turns $N$ onto the y axis, flips y with $S(1, -1, 1)$, and undoes the frame; $M(N, d)$ is "
      "the closed form of the previous derivation. To check this for *every* rotation with rational algebra "
      "only, $R$ is the library's `frame_from_quaternion`: the rotation of a quaternion "
      "$q = (q_w, q_x, q_y, q_z) \\neq 0$ divided by $|q|^2$ (every rotation arises this way), and $N$ is its "
      "second row. The seed never says whether its vectors are columns ($X' = M X$, this project's "
      "convention) or rows ($X' = X M$); its steps apply $T$, then $R$, then $S$ from left to right, which is "
      "how row vectors read, and the answer depends on it.";
  D.assume_nonzero(q2);
  D.assume_nonzero(lambda);

  D.code("R(q) is a rotation", "Its rows are orthonormal for every $q \\neq 0$.", "reflect.h", R3 * transpose(R3),
         identity(3));
  D.code("its determinant is 1", "So it is a rotation, not a reflection.", "reflect.h", det(R3), 1);
  D.code("R turns N onto the y axis", "The rows of $R$ are orthonormal and $N$ is row 2.", "reflect.h", R3 * N,
         column(0, 1, 0));
  D.define("T(dN) moves the mirror to the origin",
         "The mirror's point closest to the origin is $-dN$ (as $\\langle N, -dN \\rangle + d = 0$ for unit $N$); "
         "$T(dN)$ sends it to the origin.",
         T_dN * column(minus_dN[0], minus_dN[1], minus_dN[2], 1).as("\\left(-dN, 1\\right)", tex_precedence::atom),
         column(0, 0, 0, 1));

  const mat printed = from_library(reflection_by_frame_as_printed_in_seed003(frame, d),
                                   code_tex("reflection_by_frame_as_printed_in_seed003") + "(R, d)");
  D.code("the library's copy of the printed product", "The seed's product, kept in the library to exhibit it.",
         "reflect.h", printed, T_dN * transpose(R) * S * R * T_minus_dN);
  D.disprove("the seed's T(dN) R^T S R T(-dN), read with column vectors",
           "Applied as $M X$, the rightmost factor acts first: $T(-dN)$ sends the mirror's point $-dN$ to $-2dN$ "
           "instead of the origin. The smallest counterexample: the mirror $y = 1$ ($N = (0, 1, 0)$, $d = -1$, "
           "$R = I$ from $q = (1, 0, 0, 0)$); the product sends the origin to $(0, -2, 0)$, but its mirror image "
           "is $(0, 2, 0)$.",
           printed, M, {{qw, 1}, {qx, 0}, {qy, 0}, {qz, 0}, {d, -1}});
  D.steps.back().convention = "column vectors, X' = M X";
  D.show("what the printed order reflects about, with column vectors",
         "It is the reflection about $\\langle N, X \\rangle - d = 0$: right only for mirrors through the origin.",
         printed, mirror_closed_form(N, -d, "M(N, -d)"));

  // Row vectors: X' = X·A with the row form Aᵀ of each column-convention factor, T_row(t) = T(t)ᵀ.
  const mat T_row_dN = transpose(T_dN).as("T_{\\text{row}}(dN)", tex_precedence::atom);
  const mat T_row_minus_dN = transpose(T_minus_dN).as("T_{\\text{row}}(-dN)", tex_precedence::atom);
  const mat row_product = T_row_dN * transpose(R) * S * R * T_row_minus_dN;
  D.show("the seed's product read with row vectors is the reflection",
         "Read as $X' = X\\,M_{\\text{row}}$ with the row-vector translations $T_{\\text{row}}(t) = T(t)^{\\mathsf "
         "T}$, the factors act from left to right, as the seed's steps are listed: translate the mirror to the "
         "origin, turn $N$ onto y, flip, turn back, translate back. The column form of that map is "
         "$M_{\\text{row}}^{\\mathsf T}$, and it is the reflection for every rotation and every $d$. So this is "
         "not a mistake of the seed but a convention it leaves unstated.",
         transpose(row_product), M);
  D.not_a_mistake("right read with row vectors, as its steps are listed; the seed never states its convention");

  const mat corrected = from_library(reflection_by_frame(frame, d), code_tex("reflection_by_frame") + "(R, d)");
  D.code("corrected for column vectors: T(-dN) R^T S R T(dN)",
         "The library's `reflection_by_frame`: move the mirror to the origin with $T(dN)$, turn, flip, turn back, "
         "move back. It equals the closed form for every rotation and every $d$.",
         "reflect.h", corrected, M);

  // A normal that is not a unit vector: the seed's conditions on U, N, V allow it.
  frame3<term> scaled = frame;
  for (auto& x : scaled.rows[1]) x = lambda * x;
  const mat Nl = mat::named("\\lambda N", column(scaled.rows[1][0], scaled.rows[1][1], scaled.rows[1][2]));
  D.refute("the seed never requires |N| = 1",
           "The seed fixes $U$ and $V$ by $\\langle U, U \\rangle = \\langle V, V \\rangle = 1$ and "
           "$\\langle U, V \\rangle = \\langle U, N \\rangle = \\langle N, V \\rangle = 0$, but not "
           "$\\langle N, N \\rangle = 1$, and $N = (a, b, c)$ read off $ax + by + cz + d = 0$ is not a unit vector "
           "in general. With rows $(U, \\lambda N, V)$ even the corrected product is no reflection. The smallest "
           "counterexample: $N = (0, 2, 0)$, $d = 0$, $U = (1, 0, 0)$, $V = (0, 0, 1)$: the product is "
           "$\\operatorname{diag}(1, -4, 1, 1)$ and sends $(0, 1, 0)$ to $(0, -4, 0)$ instead of $(0, -1, 0)$ "
           "(with $d = -2$, the mirror $y = 1$, it sends the origin to $(0, 20, 0)$). Read with row vectors the "
           "product is the transpose of this one and fails the same way.",
           "column or row vectors",
           from_library(reflection_by_frame(scaled, d), code_tex("reflection_by_frame") + "(U, \\lambda N, V; d)"),
           mirror_closed_form(Nl, d, "M(\\lambda N, d)"), {{qw, 1}, {qx, 0}, {qy, 0}, {qz, 0}, {lambda, 2}, {d, 0}});

  const mat on_axis = column(0, y, 0, 1).as("\\left(0, y, 0, 1\\right)", tex_precedence::atom);
  D.refute("S(1, -1, 1) reflects about the Y axis",
           "The seed calls $S(1, -1, 1)$ the reflection about the Y axis (the N axis). A reflection about an axis "
           "in space, the half-turn $\\operatorname{diag}(-1, 1, -1)$, leaves the points of the axis where they "
           "are; $S(1, -1, 1)$ sends $(0, 1, 0)$ to $(0, -1, 0)$. It is the reflection *in* the xz-plane, the "
           "plane $y = 0$ whose normal is the Y axis: the matrix is right, the words are not.",
           "column or row vectors (S is diagonal)", S * on_axis, on_axis, {{y, 1}});
  D.conclusion =
      "Read with column vectors, seed 003's composition must be $T(-dN)\\,R^{\\mathsf T} S(1, -1, 1)\\,R\\,T(dN)$; "
      "read with row vectors, as its steps are listed, it is right as printed. Either way $N$ must be a unit "
      "vector, and $S(1, -1, 1)$ mirrors in the plane $y = 0$.";
  return D;
}

}  // namespace shadowproof::proofs
