// Seed 003: reflection as a change of frame, a flip and the frame change back, for every
// rotation (quaternion parametrisation); the printed order of the translations is wrong.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

namespace {

// The closed form [I - 2nnᵀ/(n·n), -2dn/(n·n); 0 1] for the plane n·X + d = 0.
matrix closed_form(const matrix& n, const ex& d) {
  const ex nn = dot(n, n);
  matrix M = identity(4);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) M(i, j) = M(i, j) - 2 * at(n, i) * at(n, j) / nn;
    M(i, 3) = -2 * d * at(n, i) / nn;
  }
  return M;
}

}  // namespace

derivation seed003_reflection_frames() {
  const auto qw = symbol("qw", "q_w"), qx = symbol("qx", "q_x"), qy = symbol("qy", "q_y"),
             qz = symbol("qz", "q_z");
  const auto d = symbol("d", "d");

  const matrix R3 = quaternion_rotation(qw, qx, qy, qz);
  const matrix R = embed(R3);
  const matrix N = column(R3(1, 0), R3(1, 1), R3(1, 2));
  const matrix S = scaling(1, -1, 1);
  const ex q2 = qw * qw + qx * qx + qy * qy + qz * qz;

  derivation D;
  D.slug = "seed003_reflection_frames";
  D.title = "Reflection through a frame change, for every rotation";
  D.source = "seed 003";
  D.intro =
      "The mirror is $\\langle N, X \\rangle + d = 0$ with a unit normal $N$. The seed builds a frame "
      "$R$ with rows $(U, N, V)$, so that $R$ turns $N$ onto the y axis, flips y with "
      "$S(1, -1, 1)$, and undoes the frame. To check this for *every* rotation with polynomial "
      "algebra only, $R$ is the rotation of a quaternion $q = (q_w, q_x, q_y, q_z) \\neq 0$ divided by "
      "$|q|^2$; every rotation arises this way, and $N$ is its second row.";
  D.assume(q2, "|q|^2 = q_w^2 + q_x^2 + q_y^2 + q_z^2 \\neq 0");

  D.show("R(q) is a rotation", "Its rows are orthonormal for every $q \\neq 0$.",
         {R3 * R3.transpose(), "R R^{\\mathsf T}"}, identity(3));
  D.show("its determinant is 1", "So it is a rotation, not a reflection.", {R3.determinant(), "\\det R"}, 1);
  D.show("N is a unit vector", "The second row of an orthogonal matrix.", {dot(N, N), "N \\cdot N"}, 1);
  D.show("R turns N onto the y axis", "The rows of $R$ are orthonormal and $N$ is row 2.",
         {R3 * N, "R N"}, column(0, 1, 0));

  const matrix M = closed_form(N, d);
  const matrix correct = translation(-d * at(N, 0), -d * at(N, 1), -d * at(N, 2)) * R.transpose() * S * R *
                         translation(d * at(N, 0), d * at(N, 1), d * at(N, 2));
  const matrix printed = translation(d * at(N, 0), d * at(N, 1), d * at(N, 2)) * R.transpose() * S * R *
                         translation(-d * at(N, 0), -d * at(N, 1), -d * at(N, 2));
  D.show("T(dN) moves the mirror to the origin",
         "The mirror's point closest to the origin is $-dN$ (as $\\langle N, -dN \\rangle + d = 0$); "
         "$T(dN)$ sends it to the origin.",
         {translation(d * at(N, 0), d * at(N, 1), d * at(N, 2)) *
              column(-d * at(N, 0), -d * at(N, 1), -d * at(N, 2), 1),
          "T(dN)\\,(-dN, 1)"},
         column(0, 0, 0, 1));
  D.refute("the seed's order T(dN) R^T S R T(-dN)",
           "The seed moves the mirror by $T(-dN)$ first, which sends $-dN$ to $-2dN$ instead of the "
           "origin. The smallest counterexample: the mirror $y = 1$ ($N = (0, 1, 0)$, $d = -1$, $R = I$ "
           "from $q = (1, 0, 0, 0)$); the printed matrix sends the origin to $(0, -2, 0)$, but its mirror "
           "image is $(0, 2, 0)$.",
           {printed, "T(dN)\\,R^{\\mathsf T} S\\,R\\,T(-dN)"},
           {M, "\\begin{pmatrix} I - 2NN^{\\mathsf T} & -2dN \\\\ 0 & 1 \\end{pmatrix}"},
           {{qw, 1}, {qx, 0}, {qy, 0}, {qz, 0}, {d, -1}});
  D.show("what the printed order reflects about",
         "It is the reflection about $\\langle N, X \\rangle - d = 0$: the sign of $d$ is flipped, so it "
         "is right only for mirrors through the origin.",
         {printed, "T(dN)\\,R^{\\mathsf T} S\\,R\\,T(-dN)"}, {closed_form(N, -d), "M(N, -d)"});
  D.show("corrected: T(-dN) R^T S R T(dN)",
         "Move the mirror to the origin with $T(dN)$, turn, flip, turn back, move back with $T(-dN)$. "
         "This equals the closed form for every rotation and every $d$.",
         {correct, "T(-dN)\\,R^{\\mathsf T} S\\,R\\,T(dN)"},
         {M, "\\begin{pmatrix} I - 2NN^{\\mathsf T} & -2dN \\\\ 0 & 1 \\end{pmatrix}"});
  D.conclusion =
      "Seed 003's composition must read $T(-dN)\\,R^{\\mathsf T} S(1, -1, 1)\\,R\\,T(dN)$ for the mirror "
      "$\\langle N, X \\rangle + d = 0$.";
  return D;
}

}  // namespace shadowproof::proofs
