// Seed 004: GAMES101's perspective as persp->ortho, translate, scale; the printed third row of
// persp->ortho is wrong.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

namespace {

// (x/w, y/w, z/w) of a homogeneous column.
matrix affine(const matrix& v) {
  return column(at(v, 0) / at(v, 3), at(v, 1) / at(v, 3), at(v, 2) / at(v, 3));
}

}  // namespace

derivation games101_perspective() {
  const auto n = symbol("n", "n"), f = symbol("f", "f");
  const auto l = symbol("l", "l"), r = symbol("r", "r"), b = symbol("b", "b"), t = symbol("t", "t");
  const auto x = symbol("x", "x"), y = symbol("y", "y");
  const auto A = symbol("A", "A"), B = symbol("B", "B");

  const auto persp = [&](const ex& a33, const ex& a34) {
    return matrix{{n, 0, 0, 0}, {0, n, 0, 0}, {0, 0, a33, a34}, {0, 0, 1, 0}};
  };

  derivation D;
  D.slug = "games101_perspective";
  D.title = "GAMES101: squeeze the frustum into a box";
  D.source = "seed 004";
  D.intro =
      "The near plane is $z = n$ and the far plane $z = f$ (in GAMES101 both are negative, the camera "
      "looking down $-z$). The matrix $M_{p \\to o}$ squeezes the frustum into the box over the near "
      "rectangle: points of the near plane stay put, the centre of the far plane stays put, and x, y "
      "are scaled by $n/z$. Its first, second and fourth rows follow from the scaling; the third row "
      "$(0, 0, A, B)$ is unknown. (Its first two entries are 0 because the near-plane condition holds "
      "for every $x$ and $y$.)";
  D.assume(n, "n \\neq 0");
  D.assume(f, "f \\neq 0");
  D.assume(n - f, "n - f \\neq 0");
  D.assume(r - l, "r - l \\neq 0");
  D.assume(t - b, "t - b \\neq 0");

  D.show("near plane: the third coordinate",
         "$(x, y, n, 1)$ must map to $(nx, ny, n^2, n)$, the same point scaled by $n$; the third "
         "coordinate of the image is $An + B$.",
         {at(persp(A, B) * column(x, y, n, 1), 2), "(M_{p \\to o}\\,(x, y, n, 1))_z"}, A * n + B);
  D.show("far centre: the third coordinate",
         "$(0, 0, f, 1)$ must map to $(0, 0, f^2, f)$; the third coordinate is $Af + B$.",
         {at(persp(A, B) * column(0, 0, f, 1), 2), "(M_{p \\to o}\\,(0, 0, f, 1))_z"}, A * f + B);
  D.show("the two conditions have one solution",
         "$An + B = n^2$ and $Af + B = f^2$ form a linear system with determinant $n - f \\neq 0$.",
         {matrix{{n, 1}, {f, 1}}.determinant(), "\\det\\begin{pmatrix} n & 1 \\\\ f & 1 \\end{pmatrix}"},
         n - f);
  D.show("subtracting the equations gives A",
         "$A(n - f) = n^2 - f^2$, so $A = n + f$.", {(n * n - f * f) / (n - f), "\\frac{n^2 - f^2}{n - f}"},
         n + f);
  D.show("then B", "$B = n^2 - An = n^2 - (n + f)n$.", {n * n - (n + f) * n, "n^2 - An"}, -n * f);
  const matrix M = persp(n + f, -n * f);
  D.show("check: the near plane is fixed", "With the third row $(0, 0, n + f, -nf)$.",
         {M * column(x, y, n, 1), "M_{p \\to o}\\,(x, y, n, 1)"}, {n * column(x, y, n, 1), "n\\,(x, y, n, 1)"});
  D.show("check: the far centre is fixed", "And the far plane's centre.",
         {M * column(0, 0, f, 1), "M_{p \\to o}\\,(0, 0, f, 1)"}, {f * column(0, 0, f, 1), "f\\,(0, 0, f, 1)"});

  const matrix M_printed = persp(n * f, -n * f);
  D.refute("the seed's third row (0, 0, nf, -nf)",
           "The seed solves the same two conditions but prints $nf$ where $n + f$ belongs. The smallest "
           "counterexample is $n = 1$, $f = 2$: the near-plane point $(0, 0, 1, 1)$ should stay put "
           "(image $(0, 0, 1, 1)$), but the printed matrix gives $(0, 0, 0, 1)$.",
           {M_printed * column(0, 0, n, 1), "M_{\\text{printed}}\\,(0, 0, n, 1)"},
           {n * column(0, 0, n, 1), "n\\,(0, 0, n, 1)"},
           {{n, 1}, {f, 2}});
  D.show("the printed row is right only when nf = n + f",
         "The two rows differ by $(nf - n - f, 0)$ in their last two entries, which vanishes only on "
         "the curve $nf = n + f$ (for example $n = 3$, $f = 3/2$).",
         {M_printed - M, "M_{\\text{printed}} - M_{p \\to o}"},
         matrix{{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, n * f - n - f, 0}, {0, 0, 0, 0}});

  const matrix to_origin = translation(-(r + l) / 2, -(t + b) / 2, -(n + f) / 2);
  const matrix ortho = scaling(2 / (r - l), 2 / (t - b), 2 / (n - f));
  const matrix projection = ortho * to_origin * M;
  D.show("the whole projection: near corner",
         "$\\text{projection} = \\text{orth} \\cdot \\text{orth\\_to\\_origin} \\cdot M_{p \\to o}$ sends "
         "the near corner $(l, b, n)$ to $(-1, -1, 1)$ after division by $w$.",
         {affine(projection * column(l, b, n, 1)), "\\text{projection}\\,(l, b, n, 1) / w"},
         column(-1, -1, 1));
  D.show("the whole projection: far corner",
         "The far corner of the frustum over $(r, t)$ is $(rf/n, tf/n, f)$; it goes to $(1, 1, -1)$.",
         {affine(projection * column(r * f / n, t * f / n, f, 1)), "\\text{projection}\\,(rf/n, tf/n, f, 1) / w"},
         column(1, 1, -1));
  D.conclusion =
      "The persp$\\to$ortho matrix is $\\begin{pmatrix} n & 0 & 0 & 0 \\\\ 0 & n & 0 & 0 \\\\ 0 & 0 & n + f "
      "& -nf \\\\ 0 & 0 & 1 & 0 \\end{pmatrix}$. With the seed's scale $2/(n - f)$ in z, the near plane "
      "ends at depth $+1$ and the far plane at $-1$.";
  return D;
}

}  // namespace shadowproof::proofs
