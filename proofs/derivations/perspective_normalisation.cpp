// Seed 002: the perspective normalisation N(α, β), α and β solved from the near/far conditions.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation perspective_normalisation() {
  const auto n = symbol("n", "n"), f = symbol("f", "f");
  const auto x = symbol("x", "x"), y = symbol("y", "y"), z = symbol("z", "z");
  const auto alpha = symbol("alpha", "\\alpha"), beta = symbol("beta", "\\beta");

  derivation D;
  D.slug = "perspective_normalisation";
  D.title = "Perspective normalisation N(alpha, beta)";
  D.source = "seed 002";
  D.intro =
      "The 45° frustum $x = \\pm z$, $y = \\pm z$ between the planes $z = -n$ and $z = -f$ is mapped "
      "onto the cube $[-1, 1]^3$ by $N = \\begin{pmatrix} 1 & 0 & 0 & 0 \\\\ 0 & 1 & 0 & 0 \\\\ 0 & 0 & "
      "\\alpha & \\beta \\\\ 0 & 0 & -1 & 0 \\end{pmatrix}$ followed by division by $w$. The near plane "
      "must go to depth $-1$ and the far plane to $+1$; these two conditions fix $\\alpha$ and "
      "$\\beta$.";
  D.assume(n, "n \\neq 0");
  D.assume(f, "f \\neq 0");
  D.assume(f - n, "f - n \\neq 0");
  D.assume(z, "z \\neq 0");

  const auto N = [](const ex& a, const ex& b) {
    return matrix{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, a, b}, {0, 0, -1, 0}};
  };
  D.show("the image of a point",
         "$N$ keeps x and y, puts $\\alpha z + \\beta$ in z and $-z$ in w, so division by w divides by "
         "the distance in front of the camera.",
         {N(alpha, beta) * column(x, y, z, 1), "N\\,(x, y, z, 1)"}, column(x, y, alpha * z + beta, -z));
  D.show("the sides of the frustum go to x = 1",
         "A point on $x = -z$ (the right side, as $z < 0$) has $x/w = 1$.",
         {at(N(alpha, beta) * column(-z, y, z, 1), 0) / at(N(alpha, beta) * column(-z, y, z, 1), 3),
          "\\frac{x}{w}\\Big|_{x = -z}"},
         1);
  D.show("the near condition is linear in alpha and beta",
         "Depth $(\\alpha z + \\beta)/(-z) = -1$ at $z = -n$ is, multiplied by $n$, "
         "$-n\\alpha + \\beta = -n$.",
         {(alpha * (-n) + beta) / n + 1, "\\frac{-n\\alpha + \\beta}{n} + 1"},
         {(-n * alpha + beta + n) / n, "\\frac{-n\\alpha + \\beta + n}{n}"});
  D.show("the far condition is linear in alpha and beta",
         "Depth $+1$ at $z = -f$: $-f\\alpha + \\beta = f$.",
         {(alpha * (-f) + beta) / f - 1, "\\frac{-f\\alpha + \\beta}{f} - 1"},
         {(-f * alpha + beta - f) / f, "\\frac{-f\\alpha + \\beta - f}{f}"});
  const matrix system{{-n, 1}, {-f, 1}};
  D.show("the system has exactly one solution",
         "Its determinant is $f - n$, non-zero when the near and far planes differ.",
         {system.determinant(), "\\det \\begin{pmatrix} -n & 1 \\\\ -f & 1 \\end{pmatrix}"}, f - n);
  const ex a0 = matrix{{-n, 1}, {f, 1}}.determinant() / (f - n);
  const ex b0 = matrix{{-n, -n}, {-f, f}}.determinant() / (f - n);
  D.show("Cramer's rule for alpha", "Replace the first column by the right-hand side $(-n, f)$.",
         {a0, "\\alpha"}, {(n + f) / (n - f), "\\frac{n + f}{n - f}"});
  D.show("Cramer's rule for beta", "Replace the second column by the right-hand side.",
         {b0, "\\beta"}, {2 * n * f / (n - f), "\\frac{2nf}{n - f}"});
  const matrix Ns = N((n + f) / (n - f), 2 * n * f / (n - f));
  D.show("check: the near plane goes to depth -1", "Substituting the seed's $\\alpha$, $\\beta$.",
         {at(Ns * column(x, y, -n, 1), 2) / at(Ns * column(x, y, -n, 1), 3), "\\frac{z'}{w'}\\Big|_{z = -n}"},
         -1);
  D.show("check: the far plane goes to depth +1", "And at the far plane.",
         {at(Ns * column(x, y, -f, 1), 2) / at(Ns * column(x, y, -f, 1), 3), "\\frac{z'}{w'}\\Big|_{z = -f}"},
         1);
  D.show("depth after division by w",
         "In between, depth is $-\\alpha - \\beta/z$: a function of $1/z$, which is why depth precision "
         "is spent near the camera.",
         {at(Ns * column(x, y, z, 1), 2) / at(Ns * column(x, y, z, 1), 3), "\\frac{z'}{w'}"},
         {-(n + f) / (n - f) - 2 * n * f / ((n - f) * z), "-\\alpha - \\frac{\\beta}{z}"});
  D.conclusion =
      "So $\\alpha = \\frac{n + f}{n - f}$ and $\\beta = \\frac{2nf}{n - f}$, as the seed states.";
  return D;
}

}  // namespace shadowproof::proofs
