// Seed 004: GAMES101's perspective as persp->ortho, translate, scale, and what the seed gets wrong
// about it (the third row, "affine", rows that do not follow, [-2, 2]^3, a negative top); the
// library's games101 functions against the derivation.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof::proofs {

derivation games101_perspective() {
  const term n = var("n", "n"), f = var("f", "f");
  const term l = var("l", "l"), r = var("r", "r"), b = var("b", "b"), t = var("t", "t");
  const term x = var("x", "x"), y = var("y", "y"), z = var("z", "z");
  const term A = var("A", "A"), B = var("B", "B");
  const term c = var("c", "c"), aspect = var("aspect", "a");

  const auto persp = [&](const term& a33, const term& a34, const std::string& tex) {
    return mat::named(tex, mat{{n, 0, 0, 0}, {0, n, 0, 0}, {0, 0, a33, a34}, {0, 0, 1, 0}});
  };
  const mat X = column(x, y, z, 1).as("\\left(x, y, z, 1\\right)", tex_precedence::atom);
  const mat near_point = column(x, y, n, 1).as("\\left(x, y, n, 1\\right)", tex_precedence::atom);
  const mat far_centre = column(0, 0, f, 1).as("\\left(0, 0, f, 1\\right)", tex_precedence::atom);

  derivation D;
  D.slug = "games101_perspective";
  D.title = "GAMES101: squeeze the frustum into a box";
  D.source = "seed 004";
  D.intro =
      "GAMES101 works with z coordinates: the near plane is $z = n$ and the far plane $z = f$, both negative "
      "($f < n < 0$, the camera looking down $-z$). $M_{p \\to o}$ squeezes the frustum into the box over the "
      "near rectangle: every point $(x, y, z)$ is moved towards the axis to $(n x/z, n y/z)$ (similar "
      "triangles), points of the near plane stay put and the centre of the far plane stays put. Then the box "
      "is centred and scaled onto the canonical cube. $c = \\cot(\\text{fovy}/2) > 0$ and $a > 0$ is the aspect "
      "ratio. Vectors are columns, as in the seed, which multiplies its matrices by columns.";
  D.assume_negative(n);
  D.assume_negative(f);
  D.assume_positive(n - f);
  D.assume_nonzero(r - l);
  D.assume_nonzero(t - b);
  D.assume_positive(c);
  D.assume_positive(aspect);

  const mat Mab = persp(A, B, "M_{p \\to o}");
  D.define("the squeeze fixes rows 1, 2 and 4", "For every point, $x$ becomes $n x/z$: rows 1 and 2 are $(n, 0, 0, 0)$ and "
           "$(0, n, 0, 0)$ and row 4 is $(0, 0, 1, 0)$, so that $w = z$. Row 3, $(0, 0, A, B)$, is unknown.",
           affine(Mab * X).entry(0), n * x / z);
  D.under({{z, nonzero}});
  D.define("near plane: the third coordinate", "$(x, y, n, 1)$ must map to $(nx, ny, n^2, n)$.",
           (Mab * near_point).entry(2), A * n + B);
  D.define("far centre: the third coordinate", "$(0, 0, f, 1)$ must map to $(0, 0, f^2, f)$.",
           (Mab * far_centre).entry(2), A * f + B);
  D.define("the two conditions have one solution",
         "$A n + B = n^2$ and $A f + B = f^2$ form a linear system with determinant $n - f \\neq 0$.",
         det(mat{{n, 1}, {f, 1}}), n - f);
  D.show("subtracting the equations gives A", "$A(n - f) = n^2 - f^2$.", (n * n - f * f) / (n - f), n + f);
  D.show("then B", "$B = n^2 - A n$.", n * n - (n + f) * n, -(n * f));
  const mat M = persp(n + f, -(n * f), "M_{p \\to o}");
  D.show("check: the near plane is fixed", "With the third row $(0, 0, n + f, -nf)$.", M * near_point, n * near_point);
  D.show("check: the far centre is fixed", "And the far plane's centre.", M * far_centre, f * far_centre);

  const mat M_printed = persp(n * f, -(n * f), "M_{\\text{printed}}");
  D.refute("the seed's third row (0, 0, nf, -nf)",
           "The seed solves the same two conditions but prints $nf$ where $n + f$ belongs. With $n = -1$, "
           "$f = -2$ the near-plane centre $(0, 0, -1, 1)$ should stay put (up to the factor $n$), but the printed "
           "matrix gives $(0, 0, -4, -1)$, depth 4.",
           "column vectors, X' = M X", M_printed * near_point, n * near_point, {{n, -1}, {f, -2}, {x, 0}, {y, 0}});
  D.define("the printed row is right only when nf = n + f",
         "The two matrices differ by $nf - n - f$ in row 3, column 3, which vanishes only on the curve $nf = n + f$.",
         M_printed - M, mat{{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, n * f - n - f, 0}, {0, 0, 0, 0}});

  const mat K = mat::named("K", mat{{n, 0, 1, -n}, {0, n, 0, 0}, {0, 0, n + f, -(n * f)}, {0, 0, 0, n}});
  D.show("another matrix keeps the near plane",
         "The seed writes rows 1, 2 and 4 right after asking only that $(x, y, n, 1) \\mapsto (nx, ny, n^2, n)$. "
         "That condition leaves them open: this $K$, affine in its last row, satisfies it as well.",
         K * near_point, n * near_point);
  D.refute("rows 1, 2 and 4 follow from the near-plane point",
           "$K$ meets the seed's first condition but is not $M_{p \\to o}$: rows 1 and 4 come from the squeeze of "
           "*every* point, $x \\mapsto n x/z$ (and the far centre rules out $K$ too).",
           "column vectors, X' = M X", K, M, {{n, -1}, {f, -2}});
  D.refute("persp->ortho is an affine transformation",
           "The seed sets out to find \"a 4x4 affine transformation\". An affine map has last row $(0, 0, 0, 1)$ "
           "and keeps $w = 1$; $M_{p \\to o}$ has last row $(0, 0, 1, 0)$, so $w = z$: it sends the eye $(0, 0, 0)$ "
           "to the point at infinity $(0, 0, -nf, 0)$. It is a projective transformation.",
           "column vectors, X' = M X", (M * X).entry(3), 1, {{x, 0}, {y, 0}, {z, 0}});

  const mat to_origin = translation(-(r + l) / 2, -(t + b) / 2, -(n + f) / 2, "T_{\\text{origin}}");
  const mat ortho = scaling(2 / (r - l), 2 / (t - b), 2 / (n - f), "S_{\\text{orth}}");
  const mat projection = mat::named("P_{\\text{proj}}", ortho * to_origin * M);
  D.define("the projection", "The seed's $\\text{orth} \\cdot \\text{orth\\_to\\_origin} \\cdot M_{p \\to o}$.", projection,
           ortho * to_origin * M);
  D.show("the whole projection: near corner", "The near corner $(l, b, n)$ goes to $(-1, -1, 1)$ after division by $w$.",
         affine(projection * column(l, b, n, 1)), column(-1, -1, 1));
  D.show("the whole projection: far corner",
         "The far corner of the frustum over $(r, t)$ is $(rf/n, tf/n, f)$; it goes to $(1, 1, -1)$.",
         affine(projection * column(r * f / n, t * f / n, f, 1)), column(1, 1, -1));
  D.refute("the seed squeezes the box into [-2, 2]^3",
           "The seed says the box is compressed into $[-2, 2]^3$ (\"$[-1, 1]$ also works\"), but its own scale "
           "$2/(\\text{right} - \\text{left})$ halves the width $r - l$ to 2: the corner $(r, t, n)$ of the centred "
           "box lands on $(1, 1, 1)$, not $(2, 2, 2)$. The matrix is the $[-1, 1]^3$ one.",
           "column vectors, X' = M X", ortho * to_origin * column(r, t, n, 1), column(2, 2, 2, 1),
           {{l, -1}, {r, 1}, {b, -1}, {t, 1}, {n, -1}, {f, -2}});

  // Lines 33-35: top = tan(fovy/2)·zNear with GAMES101's negative zNear.
  const term top_seed = n / c, top = -n / c;
  const mat ortho_seed = scaling(1 / (top_seed * aspect), 1 / top_seed, 2 / (n - f), "S_{\\text{seed}}");
  const mat top_edge = column(0, top, n, 1).as("\\left(0, -n/c, n, 1\\right)", tex_precedence::atom);
  D.refute("top = tan(fovy/2) zNear with the negative zNear",
           "The seed's code takes $\\text{top} = \\tan(\\text{fovy}/2)\\,z_{\\text{near}} = n/c$, negative for "
           "GAMES101's $n < 0$, so $\\text{bottom} = -\\text{top} > \\text{top}$ and the scale $2/(\\text{top} - "
           "\\text{bottom})$ is negative, as is the one for x: the image is turned upside down and mirrored. The top "
           "edge of the view, $y = -n/c$ on the near plane, lands at NDC $y = -1$ instead of $+1$. The smallest "
           "counterexample: $\\text{fovy} = 90°$ ($c = 1$), $a = 1$, $n = -1$, $f = -2$.",
           "column vectors, X' = M X, y up", affine(ortho_seed * M * top_edge).entry(1), 1,
           {{n, -1}, {f, -2}, {c, 1}});

  const auto decide = comparisons_from(D.facts);
  const scoped_comparisons installed(*decide);
  D.code("the library's games101_persp_to_ortho", "The template instantiated with symbols.", "project.h",
         from_library(games101_persp_to_ortho(n, f), code_tex("games101_persp_to_ortho") + "(n, f)"), M);
  D.code("the library's copy of the printed matrix", "Kept to exhibit the misprint.", "project.h",
         from_library(games101_persp_to_ortho_as_printed(n, f), code_tex("games101_persp_to_ortho_as_printed") + "(n, f)"),
         M_printed);
  const mat G = from_library(games101_projection(n, f, c, aspect), code_tex("games101_projection") + "(n, f, c, a)");
  const term right = top * aspect;
  D.code("the library's games101_projection: near corner",
         "With $\\text{top} = -n/c > 0$ the near corner $(-\\text{right}, -\\text{top}, n)$ goes to $(-1, -1, 1)$.",
         "project.h", affine(G * column(-right, -top, n, 1)), column(-1, -1, 1));
  D.code("the library's games101_projection: far corner", "The far corner goes to $(1, 1, -1)$.", "project.h",
         affine(G * column(right * f / n, top * f / n, f, 1)), column(1, 1, -1));
  D.code("the library's games101_projection keeps the top edge on top", "The top edge lands on NDC $y = +1$.",
         "project.h", affine(G * top_edge).entry(1), 1);
  D.conclusion =
      "The persp$\\to$ortho matrix is $\\begin{pmatrix} n & 0 & 0 & 0 \\\\ 0 & n & 0 & 0 \\\\ 0 & 0 & n + f & "
      "-nf \\\\ 0 & 0 & 1 & 0 \\end{pmatrix}$, a projective map whose rows 1, 2 and 4 come from the squeeze of "
      "every point. With the scale $2/(n - f)$ in z the near plane ends at depth $+1$ and the far plane at "
      "$-1$, in $[-1, 1]^3$; with $n < 0$ the window's top is $-n/c$.";
  return D;
}

}  // namespace shadowproof::proofs
