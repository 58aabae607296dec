// Seed 002: the perspective normalisation N(α, β), α and β solved from the near/far conditions,
// and the library's perspective_normalization.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof::proofs {

derivation perspective_normalisation() {
  const term n = var("n", "n"), f = var("f", "f");
  const term x = var("x", "x"), y = var("y", "y"), z = var("z", "z");
  const term alpha = var("alpha", "\\alpha"), beta = var("beta", "\\beta");

  const auto N = [](const term& a, const term& b, const std::string& tex) {
    return mat::named(tex, mat{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, a, b}, {0, 0, -1, 0}});
  };
  const mat X = column(x, y, z, 1).as("\\left(x, y, z, 1\\right)", tex_precedence::atom);

  derivation D;
  D.slug = "perspective_normalisation";
  D.title = "Perspective normalisation N(alpha, beta)";
  D.source = "seed 002";
  D.intro =
      "The 45° frustum $|x| \\leq -z$, $|y| \\leq -z$ between the planes $z = -n$ and $z = -f$ ($n, f > 0$ are "
      "distances in front of the eye) is mapped onto the cube $[-1, 1]^3$ by $N(\\alpha, \\beta)$ followed by "
      "division by $w$. The near plane must go to depth $-1$ and the far plane to $+1$; these two conditions "
      "fix $\\alpha$ and $\\beta$.";
  D.assume_positive(n);
  D.assume_positive(f);
  D.assume_nonzero(f - n);
  D.assume_nonzero(z);

  const mat Nab = N(alpha, beta, "N(\\alpha, \\beta)");
  D.define("N", "Seed 002's matrix: x and y kept, $\\alpha z + \\beta$ in z and $-z$ in w.", Nab, Nab.written());
  D.define("the image of a point", "Division by $w = -z$ divides by the distance in front of the eye.", Nab * X,
           column(x, y, alpha * z + beta, -z));
  const mat side_point = column(-z, y, z, 1).as("\\left(-z, y, z, 1\\right)", tex_precedence::atom);
  D.show("the side x = -z of the frustum goes to x = 1", "A point on the right side ($z < 0$) has $x/w = 1$.",
         (Nab * side_point).entry(0) / (Nab * side_point).entry(3), 1);
  D.show("the near condition is linear in alpha and beta",
         "Depth $(\\alpha z + \\beta)/(-z) = -1$ at $z = -n$, multiplied by $n$: $-n\\alpha + \\beta = -n$.",
         n * ((alpha * -n + beta) / n + 1), -n * alpha + beta + n);
  D.show("the far condition is linear in alpha and beta", "Depth $+1$ at $z = -f$: $-f\\alpha + \\beta = f$.",
         f * ((alpha * -f + beta) / f - 1), -f * alpha + beta - f);
  const mat system = mat::named("A", mat{{-n, 1}, {-f, 1}});
  D.define("the system has exactly one solution", "Its determinant is $f - n$, non-zero when the planes differ.",
         det(system), f - n);
  const term a0 = det(mat{{-n, 1}, {f, 1}}) / det(system);
  const term b0 = det(mat{{-n, -n}, {-f, f}}) / det(system);
  D.show("Cramer's rule for alpha", "Replace the first column by the right-hand side $(-n, f)$.", a0, (n + f) / (n - f));
  D.show("Cramer's rule for beta", "Replace the second column by the right-hand side.", b0, 2 * n * f / (n - f));
  const mat Ns = N((n + f) / (n - f), 2 * n * f / (n - f), "N");
  const mat near_point = column(x, y, -n, 1).as("\\left(x, y, -n, 1\\right)", tex_precedence::atom);
  const mat far_point = column(x, y, -f, 1).as("\\left(x, y, -f, 1\\right)", tex_precedence::atom);
  D.show("check: the near plane goes to depth -1", "Substituting the seed's $\\alpha$, $\\beta$.",
         (Ns * near_point).entry(2) / (Ns * near_point).entry(3), -1);
  D.show("check: the far plane goes to depth +1", "And at the far plane.",
         (Ns * far_point).entry(2) / (Ns * far_point).entry(3), 1);
  D.show("depth after division by w",
         "In between, depth is $-\\alpha - \\beta/z$: a function of $1/z$, which is why depth precision is spent "
         "near the camera.",
         (Ns * X).entry(2) / (Ns * X).entry(3), -((n + f) / (n - f)) - 2 * n * f / ((n - f) * z));

  const auto decide = comparisons_from(D.facts);
  const scoped_comparisons installed(*decide);
  const mat code = from_library(perspective_normalization(n, f), code_tex("perspective_normalization") + "(n, f)");
  D.code("the library's perspective_normalization", "The template instantiated with symbols.", "project.h", code, Ns);
  D.code("it is the 45-degree frustum in the gl convention",
         "`frustum` with the window $[-n, n]^2$ on the near plane gives the same matrix.", "project.h", code,
         from_library(shadowproof::frustum(-n, n, -n, n, n, f, depth_convention::gl), code_tex("frustum") + "(-n, n, -n, n, n, f, \\texttt{gl})"));
  D.conclusion = "So $\\alpha = \\frac{n + f}{n - f}$ and $\\beta = \\frac{2nf}{n - f}$, as the seed states.";
  return D;
}

}  // namespace shadowproof::proofs
