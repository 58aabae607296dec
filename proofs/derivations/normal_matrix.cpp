// Seed 004: normals transform by G = (M^-1)^T because tangents stay orthogonal to normals; G is
// not orthogonal in general, although the seed calls it so.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation normal_matrix() {
  std::vector<GiNaC::realsymbol> m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const std::string ij = std::to_string(i) + std::to_string(j);
      m.push_back(symbol("m" + ij, "m_{" + ij + "}"));
    }
  const auto tx = symbol("tx", "t_x"), ty = symbol("ty", "t_y"), tz = symbol("tz", "t_z");
  const auto nx = symbol("nx", "n_x"), ny = symbol("ny", "n_y"), nz = symbol("nz", "n_z");
  const auto qw = symbol("qw", "q_w"), qx = symbol("qx", "q_x"), qy = symbol("qy", "q_y"),
             qz = symbol("qz", "q_z");

  const matrix M{{m[0], m[1], m[2]}, {m[3], m[4], m[5]}, {m[6], m[7], m[8]}};
  const ex det = M.determinant();
  matrix cof(3, 3);
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j) {
      const unsigned r0 = i == 0 ? 1 : 0, r1 = i == 2 ? 1 : 2, c0 = j == 0 ? 1 : 0, c1 = j == 2 ? 1 : 2;
      const ex minor = M(r0, c0) * M(r1, c1) - M(r0, c1) * M(r1, c0);
      cof(i, j) = ((i + j) % 2 == 0) ? minor : -minor;
    }
  // G = cof(M)/det M; the steps below show it is (M^-1)^T (M^T G = I and G M^T = I).
  const matrix G = (1 / det) * cof;
  const matrix t = column(tx, ty, tz), n = column(nx, ny, nz);

  derivation D;
  D.slug = "normal_matrix";
  D.title = "The normal matrix";
  D.source = "seed 004";
  D.intro =
      "A surface has tangent $t$ and normal $n$ with $t^{\\mathsf T} n = 0$. An invertible linear map "
      "$M$ (the 3x3 part of a model matrix; translations do not act on directions) carries tangents to "
      "$M t$. Normals must be carried by some $G$ with $(M t)^{\\mathsf T} (G n) = 0$ whenever "
      "$t^{\\mathsf T} n = 0$. Here $M$ is a general 3x3 matrix of symbols.";
  D.assume(det, "\\det M \\neq 0");
  D.assume(qw * qw + qx * qx + qy * qy + qz * qz, "|q|^2 \\neq 0");

  D.show("move M across the dot product",
         "$(M t)^{\\mathsf T} (G n) = t^{\\mathsf T} (M^{\\mathsf T} G)\\, n$ for any $G$; so "
         "orthogonality is kept for all $t \\perp n$ when $M^{\\mathsf T} G = I$.",
         {dot(M * t, G * n), "(M t)^{\\mathsf T} (G n)"},
         {dot(t, (M.transpose() * G) * n), "t^{\\mathsf T} (M^{\\mathsf T} G)\\, n"});
  D.show("the cofactor matrix over the determinant solves M^T G = I",
         "Laplace expansion: $M^{\\mathsf T} \\operatorname{cof}(M) = \\det(M)\\, I$. So "
         "$G = \\operatorname{cof}(M)/\\det M$ works; since a normal's length does not matter, the "
         "division-free $\\operatorname{cof} M$ serves as well.",
         {M.transpose() * G, "M^{\\mathsf T} \\frac{\\operatorname{cof} M}{\\det M}"}, identity(3));
  D.show("and from the other side, so G is the inverse transpose",
         "$G M^{\\mathsf T} = I$ too, hence $G = (M^{\\mathsf T})^{-1} = (M^{-1})^{\\mathsf T}$.",
         {G * M.transpose(), "G\\, M^{\\mathsf T}"}, identity(3));
  D.show("so the dot product is unchanged",
         "$(M t) \\cdot (G n) = t \\cdot n$ for every $t$ and $n$; in particular it stays 0.",
         {dot(M * t, G * n), "(M t) \\cdot (G n)"}, {dot(t, n), "t \\cdot n"});

  const GiNaC::exmap stretch{{m[0], 2}, {m[1], 0}, {m[2], 0}, {m[3], 0}, {m[4], 1},
                             {m[5], 0}, {m[6], 0}, {m[7], 0}, {m[8], 1}};
  GiNaC::exmap stretch_and_pair = stretch;
  for (const auto& [sym, value] : GiNaC::exmap{{tx, 1}, {ty, 1}, {tz, 0}, {nx, 1}, {ny, -1}, {nz, 0}})
    stretch_and_pair[sym] = value;
  D.disprove("M itself carries normals",
           "Transforming the normal by $M$ breaks orthogonality as soon as the scale is not uniform. "
           "Stretch x by 2: the tangent $(1, 1, 0)$ and the normal $(1, -1, 0)$ become $(2, 1, 0)$ and "
           "$(2, -1, 0)$, whose dot product is 3.",
           {dot(M * t, M * n), "(M t) \\cdot (M n)"}, {dot(t, n), "t \\cdot n"}, stretch_and_pair);
  D.refute("the seed calls G an orthogonal matrix",
           "Seed 004 says $G$ is the orthogonal matrix that carries normals. $G = (M^{-1})^{\\mathsf T}$ is "
           "orthogonal only when $M$ is; for the same stretch, $G = \\operatorname{diag}(1/2, 1, 1)$ and "
           "$G^{\\mathsf T} G = \\operatorname{diag}(1/4, 1, 1)$.",
           {G.transpose() * G, "G^{\\mathsf T} G"}, identity(3), stretch);

  const matrix R = quaternion_rotation(qw, qx, qy, qz);
  D.show("for a rotation G is M itself",
         "When $M = R$ is a rotation, $G = R$ solves $R^{\\mathsf T} G = I$, so $(R^{-1})^{\\mathsf T} = R$: "
         "normals and tangents transform alike, which is why the distinction is easy to miss.",
         {R.transpose() * R, "R^{\\mathsf T} R"}, identity(3));
  D.conclusion =
      "Normals transform by $G = (M^{-1})^{\\mathsf T}$ (or by $\\operatorname{cof} M$ and a "
      "renormalisation); $G$ is orthogonal only when $M$ is.";
  return D;
}

}  // namespace shadowproof::proofs
