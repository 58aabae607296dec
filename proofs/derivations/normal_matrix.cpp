// Seed 004: normals transform by G = (M^-1)^T because tangents stay orthogonal to normals; what the
// seed's argument gets wrong on the way; the library's normal_matrix against it.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/normal_matrix.h"

namespace shadowproof::proofs {

namespace {

// The cofactor matrix of a 3x3 matrix: entry (i, j) is (−1)^(i+j) times the minor without row i
// and column j.
mat cofactors3(const mat& m) {
  std::vector<term> e;
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j) {
      const unsigned r0 = i == 0 ? 1 : 0, r1 = i == 2 ? 1 : 2, c0 = j == 0 ? 1 : 0, c1 = j == 2 ? 1 : 2;
      const term minor = m(r0, c0) * m(r1, c1) - m(r0, c1) * m(r1, c0);
      e.push_back((i + j) % 2 == 0 ? minor : -minor);
    }
  return mat(3, 3, std::move(e), "\\operatorname{cof} " + m.tex(tex_precedence::atom), tex_precedence::product);
}

}  // namespace

derivation normal_matrix() {
  std::vector<term> m, m4;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const std::string ij = std::to_string(i + 1) + std::to_string(j + 1);
      m4.push_back(var("a" + ij, "a_{" + ij + "}"));
      if (i < 3 && j < 3) m.push_back(var("m" + ij, "m_{" + ij + "}"));
    }
  const term tx = var("tx", "t_x"), ty = var("ty", "t_y"), tz = var("tz", "t_z");
  const term nx = var("nx", "n_x"), ny = var("ny", "n_y"), nz = var("nz", "n_z");
  const term a = var("a", "a"), b = var("b", "b"), c = var("c", "c");

  const mat M = mat::named("M", mat{{m[0], m[1], m[2]}, {m[3], m[4], m[5]}, {m[6], m[7], m[8]}});
  const term detM = det(M);
  const mat G = mat::named("G", (1 / detM) * cofactors3(M));
  const mat t = mat::named("t", column(tx, ty, tz)), n = mat::named("n", column(nx, ny, nz));
  const mat M4 = mat::named("A", mat{{m4[0], m4[1], m4[2], m4[3]},
                                     {m4[4], m4[5], m4[6], m4[7]},
                                     {m4[8], m4[9], m4[10], m4[11]},
                                     {m4[12], m4[13], m4[14], m4[15]}});

  derivation D;
  D.slug = "normal_matrix";
  D.title = "The normal matrix";
  D.source = "seed 004";
  D.intro =
      "A surface has tangent $t$ and normal $n$ with $t^{\\mathsf T} n = 0$. An invertible linear map $M$ (the "
      "3x3 part of a model matrix; translations do not act on directions) carries tangents to $M t$. Normals "
      "must be carried by some $G$ with $(M t)^{\\mathsf T} (G n) = 0$ whenever $t^{\\mathsf T} n = 0$. Here "
      "$M$ is a general 3x3 matrix of symbols, and vectors are columns.";
  D.assume_nonzero(detM);
  D.assume_nonzero(det(M4));

  D.define("G", "The cofactor matrix over the determinant.", G, (1 / detM) * cofactors3(M));
  D.show("move M across the dot product",
         "For any $G$; so orthogonality is kept for all $t \\perp n$ when $M^{\\mathsf T} G = I$.", dot(M * t, G * n),
         dot(t, (transpose(M) * G) * n));
  D.show("the cofactor matrix over the determinant solves M^T G = I",
         "Laplace expansion: $M^{\\mathsf T} \\operatorname{cof}(M) = \\det(M)\\, I$. Since a normal's length "
         "does not matter, the division-free $\\operatorname{cof} M$ serves as well.",
         transpose(M) * G, identity(3));
  D.show("and from the other side, so G is the inverse transpose", "$G M^{\\mathsf T} = I$ too, hence $G = (M^{-1})^{\\mathsf T}$.",
         G * transpose(M), identity(3));
  D.show("so the dot product is unchanged", "$(M t) \\cdot (G n) = t \\cdot n$ for every $t$ and $n$; in particular it stays 0.",
         dot(M * t, G * n), dot(t, n));
  D.show("M^T G = I is sufficient, not necessary",
         "The seed concludes $M^{\\mathsf T} G = I$ from the orthogonality condition, but $2G$ (any non-zero "
         "multiple) keeps every $t \\perp n$ perpendicular too, with $M^{\\mathsf T} (2G) = 2I$: the condition "
         "forces $M^{\\mathsf T} G = \\lambda I$ only. Not a mistake in the result, since a normal's length and "
         "sign of scale do not matter and $\\lambda = 1$ is a choice.",
         dot(M * t, (2 * G) * n), 2 * dot(t, n));
  D.not_a_mistake("only sufficient, but any multiple of G is as good: a normal's length does not matter");

  const std::vector<std::pair<term, term>> stretch{{m[0], 2}, {m[1], 0}, {m[2], 0}, {m[3], 0}, {m[4], 1},
                                                   {m[5], 0}, {m[6], 0}, {m[7], 0}, {m[8], 1}};
  std::vector<std::pair<term, term>> stretch_and_pair = stretch;
  for (const auto& v : std::vector<std::pair<term, term>>{{tx, 1}, {ty, 1}, {tz, 0}, {nx, 1}, {ny, -1}, {nz, 0}})
    stretch_and_pair.push_back(v);
  D.disprove("M itself carries normals",
             "Transforming the normal by $M$ breaks orthogonality as soon as the scale is not uniform. Stretch x by "
             "2: the tangent $(1, 1, 0)$ and the normal $(1, -1, 0)$ become $(2, 1, 0)$ and $(2, -1, 0)$, whose dot "
             "product is 3.",
             dot(M * t, M * n), dot(t, n), stretch_and_pair);
  D.refute("the seed calls G an orthogonal matrix",
           "Seed 004 says $G$ is the orthogonal matrix that carries normals. $G = (M^{-1})^{\\mathsf T}$ is orthogonal "
           "only when $M$ is; for the same stretch, $G = \\operatorname{diag}(1/2, 1, 1)$ and $G^{\\mathsf T} G = "
           "\\operatorname{diag}(1/4, 1, 1)$.",
           "column or row vectors", transpose(G) * G, identity(3), stretch);

  const mat row = mat::named("(a\\ b\\ c)", mat{{a, b, c}});
  const mat col = mat::named("(x\\ y\\ z)^{\\mathsf T}", column(tx, ty, tz));
  const mat hadamard = mat(3, 1, {a * tx, b * ty, c * tz}, "\\left(a t_x, b t_y, c t_z\\right)^{\\mathsf T}", tex_precedence::atom);
  D.define("a row times a column is one number", "$(a\\ b\\ c)$ times a column is the 1x1 matrix $a t_x + b t_y + c t_z$.",
           row * column(tx, ty, tz).as("t", tex_precedence::atom), mat{{a * tx + b * ty + c * tz}});
  D.refute("the dot product as the componentwise product",
           "The seed explains $T_c^{\\mathsf T} N_c$ by writing a column times a column as the componentwise "
           "$(ax, by, cz)$ and a row times a column as the row $(ax\\ by\\ cz)$. Both are wrong: the dot product "
           "is the single number $ax + by + cz$, and it can vanish while the componentwise product does not. The "
           "smallest counterexample: $(a, b, c) = (1, 1, 0)$ and $t = (1, -1, 0)$, perpendicular, with "
           "componentwise product $(1, -1, 0)$.",
           "a row times a column", hadamard, mat(3, 1), {{a, 1}, {b, 1}, {c, 0}, {tx, 1}, {ty, -1}, {tz, 0}});
  D.under({{a * tx + b * ty + c * tz, zero}});
  D.define("a 3x3 matrix times a 3x1 column is a 3x1 column",
           "The seed says $M_{3 \\times 3} N_c$ with a $3 \\times 1$ column \"certainly cannot be multiplied\"; it "
           "can, and its row form $N_c^{\\mathsf T} G^{\\mathsf T}$, which the seed writes as "
           "$N_c M_{p \\to c}$ with row vectors, is just its transpose.",
           transpose(G * n), transpose(n) * transpose(G));
  D.steps.back().convention = "column vectors; its row form is the transpose";
  D.mistake();

  const auto decide = comparisons_from(D.facts);
  const scoped_comparisons installed(*decide);
  const mat code = from_library(shadowproof::normal_matrix(to_mat4(M4)), code_tex("normal_matrix") + "(A)");
  D.code("the library's normal_matrix is (A^-1)^T", "For a general 4x4 matrix $A$ with $\\det A \\neq 0$, the code's result $G$ satisfies $A^{\\mathsf T} G = I$.",
         "normal_matrix.h", transpose(M4) * code, identity(4));
  D.code("the library's normal_matrix_adjugate is det(A) G", "The division-free form.", "normal_matrix.h",
         from_library(normal_matrix_adjugate(to_mat4(M4)),
                      code_tex("normal_matrix_adjugate") + "(A)"),
         det(M4) * code);
  D.conclusion =
      "Normals transform by $G = (M^{-1})^{\\mathsf T}$ (or by $\\operatorname{cof} M$ and a renormalisation); "
      "$G$ is orthogonal only when $M$ is.";
  return D;
}

}  // namespace shadowproof::proofs
