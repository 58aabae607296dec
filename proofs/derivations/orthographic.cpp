// The orthographic projection in any depth convention, seed 002's S·T (with its misprinted sign),
// and the library's orthographic and orthographic_normalization_seed002.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof::proofs {

namespace {

// The orthographic matrix with the near plane at NDC depth zn and the far plane at zf.
mat orthographic_matrix(const term& l, const term& r, const term& b, const term& t, const term& n, const term& f,
                        const term& zn, const term& zf, const std::string& tex) {
  const term A = (zn - zf) / (f - n);
  return mat::named(tex, mat{{2 / (r - l), 0, 0, -(r + l) / (r - l)},
                             {0, 2 / (t - b), 0, -(t + b) / (t - b)},
                             {0, 0, A, zn + A * n},
                             {0, 0, 0, 1}});
}

}  // namespace

derivation orthographic() {
  const term l = var("l", "l"), r = var("r", "r"), b = var("b", "b"), t = var("t", "t"), n = var("n", "n"),
             f = var("f", "f");
  const term x = var("x", "x"), z = var("z", "z");
  const term zn = var("zn", "z_{\\text{near}}"), zf = var("zf", "z_{\\text{far}}");

  derivation D;
  D.slug = "orthographic";
  D.title = "The orthographic projection and seed 002's normalisation S T";
  D.source = "seed 002";
  D.intro =
      "The view box is $[l, r] \\times [b, t]$ in x and y and $z \\in [-f, -n]$ (the camera looks down $-z$, "
      "near plane $z = -n$). Normalisation maps it onto the canonical volume: x and y onto $[-1, 1]$, the near "
      "plane to NDC depth $z_{\\text{near}}$ and the far plane to $z_{\\text{far}}$: $-1$ and $1$ for OpenGL "
      "(`gl`), $0$ and $1$ for Direct3D, Vulkan and Metal (`d3d`), $1$ and $0$ for reverse-Z. Nothing divides "
      "by $w$, so any $n \\neq f$ works.";
  D.assume_nonzero(r - l);
  D.assume_nonzero(t - b);
  D.assume_nonzero(f - n);

  D.show("x: the window onto [-1, 1]", "The affine map with $l \\mapsto -1$ and $r \\mapsto 1$, as one row of a matrix.",
         2 * (x - l) / (r - l) - 1, 2 / (r - l) * x - (r + l) / (r - l));
  const term A = (zn - zf) / (f - n);
  D.show("depth: subtracting the two conditions gives A",
         "Depth is affine, $A z + B$, with $-A n + B = z_{\\text{near}}$ and $-A f + B = z_{\\text{far}}$; "
         "their difference is $A (f - n) = z_{\\text{near}} - z_{\\text{far}}$.",
         A * (f - n), zn - zf);
  D.define("depth: B from the near condition", "$B = z_{\\text{near}} + A n$ puts the near plane at $z_{\\text{near}}$.",
           A * -n + (zn + A * n), zn);
  D.show("depth: the far plane lands on z_far", "The second condition holds with that $A$ and $B$.",
         A * -f + (zn + A * n), zf);
  const mat M = orthographic_matrix(l, r, b, t, n, f, zn, zf, "M_{\\text{ortho}}");
  D.define("the orthographic matrix", "Rows 1 and 2 from the window, row 3 from the depth conditions.", M, M.written());
  D.show("the near corner", "$(l, b, -n)$ goes to $(-1, -1, z_{\\text{near}})$.",
         M * column(l, b, -n, 1), column(-1, -1, zn, 1));
  D.show("the far corner", "$(r, t, -f)$ goes to $(1, 1, z_{\\text{far}})$.", M * column(r, t, -f, 1),
         column(1, 1, zf, 1));

  const std::vector<std::pair<depth_convention, std::pair<int, int>>> conventions = {
      {depth_convention::gl, {-1, 1}}, {depth_convention::d3d, {0, 1}}, {depth_convention::reverse_z, {1, 0}}};
  {
    const auto decide = comparisons_from(D.facts);
    const scoped_comparisons installed(*decide);
    for (const auto& [c, z_range] : conventions) {
      const std::string name(to_string(c));
      D.code("the library's orthographic, " + name,
             "The template for the `" + name + "` convention equals the matrix with $z_{\\text{near}} = " +
                 std::to_string(z_range.first) + "$, $z_{\\text{far}} = " + std::to_string(z_range.second) + "$.",
             "project.h",
             from_library(shadowproof::orthographic(l, r, b, t, n, f, c),
                          code_tex("orthographic") + "(l, r, b, t, n, f, \\texttt{" + name + "})"),
             orthographic_matrix(l, r, b, t, n, f, z_range.first, z_range.second,
                                 "M_{\\text{ortho}}\\big|_{\\texttt{" + name + "}}"));
    }
  }

  // Seed 002's S T.
  const mat T = translation(-(r + l) / 2, -(t + b) / 2, (f + n) / 2, "T");
  const mat S = scaling(2 / (r - l), 2 / (t - b), -2 / (f - n), "S");
  D.define("T moves the centre of the box to the origin", "The centre is $((l + r)/2, (b + t)/2, -(n + f)/2)$.",
         T * column((l + r) / 2, (b + t) / 2, -(n + f) / 2, 1), column(0, 0, 0, 1));
  const mat M_gl = orthographic_matrix(l, r, b, t, n, f, -1, 1, "M_{\\text{ortho}}\\big|_{\\texttt{gl}}");
  D.show("S T is the gl matrix", "Multiplying the scale into the translation.", S * T, M_gl);
  const mat ST_printed = mat::named("(S\\,T)_{\\text{printed}}", mat{{2 / (r - l), 0, 0, -(r + l) / (r - l)},
                                                                     {0, 2 / (t - b), 0, -(t + b) / (t - b)},
                                                                     {0, 0, -2 / (f - n), (f + n) / (f - n)},
                                                                     {0, 0, 0, 1}});
  D.refute("the seed's S T with +(f+n)/(f-n)",
           "The seed prints $+\\frac{f + n}{f - n}$ in row 3, column 4 (twice), but its own $S$ and $T$ give "
           "$-\\frac{f + n}{f - n}$. With the printed sign the near plane does not go to $z = -1$: for the unit box "
           "($l = b = -1$, $r = t = 1$) with $n = 1$, $f = 2$, the point $(0, 0, -1)$ maps to $z = 5$.",
           "column vectors, X' = M X (the translation is the last column)", ST_printed, S * T,
           {{l, -1}, {r, 1}, {b, -1}, {t, 1}, {n, 1}, {f, 2}});
  D.show("what the printed sign does to the near plane",
         "The printed matrix sends depth $-n$ to $(3n + f)/(f - n)$ instead of $-1$.",
         (ST_printed * column(0, 0, -n, 1)).entry(2), (3 * n + f) / (f - n));
  D.code("the library's S T", "`orthographic_normalization_seed002` builds the product of the seed's two factors.",
         "project.h",
         [&] {
           const auto decide = comparisons_from(D.facts);
           const scoped_comparisons installed(*decide);
           return from_library(orthographic_normalization_seed002(l, r, b, t, n, f),
                               code_tex("orthographic_normalization_seed002") + "(l, r, b, t, n, f)");
         }(),
         M_gl);
  D.conclusion =
      "Row 3 of seed 002's $S T$ must end in $-\\frac{f + n}{f - n}$; the library's `orthographic` is the "
      "derived matrix in all three depth conventions.";
  return D;
}

}  // namespace shadowproof::proofs
