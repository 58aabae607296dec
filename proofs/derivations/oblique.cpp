// Seed 002's oblique projection: the angles θ and φ, the two signs of cot in the shear H(θ, φ),
// and the library's oblique_shear, oblique and the seed's normalised form.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof::proofs {

derivation oblique() {
  const term x = var("x", "x"), y = var("y", "y"), z = var("z", "z");
  const term ct = var("ct", "\\cot\\theta"), cp = var("cp", "\\cot\\phi");
  const term l = var("l", "l"), r = var("r", "r"), b = var("b", "b"), t = var("t", "t"), n = var("n", "n"),
             f = var("f", "f");

  const mat X = column(x, y, z, 1).as("\\left(x, y, z, 1\\right)", tex_precedence::atom);
  const mat M_orth = mat::named("M_{\\text{orth}}", mat{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 1}});
  const mat H_plus = mat::named("H_{+}", mat{{1, 0, ct, 0}, {0, 1, cp, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}});
  const mat H_minus = mat::named("H_{-}", mat{{1, 0, -ct, 0}, {0, 1, -cp, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}});

  derivation D;
  D.slug = "oblique";
  D.title = "Oblique projection: the angles and the two signs of cot";
  D.source = "seed 002";
  D.intro =
      "An oblique parallel projection sends every point along one fixed direction, the projector, onto the "
      "plane $z = 0$. Seed 002 defines the angles by $\\tan\\theta = z/(x_p - x)$: $\\theta$ is the angle, "
      "seen in the xz-plane, between the plane $z = 0$ and the projector that carries $(x, y, z)$ to its image "
      "$(x_p, y_p, 0)$, and $\\phi$ is the same angle in the yz-plane. Then $x_p = x + z\\cot\\theta$ and "
      "$y_p = y + z\\cot\\phi$: the projector runs along $(\\cot\\theta, \\cot\\phi, -1)$, and $\\theta = "
      "\\phi = 90°$ is the orthographic projection. The shear $H_{+}$ has $+\\cot$ (the seed's first slide); "
      "$H_{-}$ has $-\\cot$ (its later slide, Angel's textbook and the library's `oblique_shear`), which "
      "measures the angles from the other side: $\\theta' = 180° - \\theta$, projector $(\\cot\\theta, "
      "\\cot\\phi, 1)$. Both are right for their own angles; they are not the same map for the same "
      "$\\theta$.";
  D.assume_nonzero(z);
  D.assume_nonzero(ct);
  D.assume_nonzero(r - l);
  D.assume_nonzero(t - b);
  D.assume_nonzero(f - n);

  const term xp = x + z * ct;
  D.show("the seed's angle gives x_p = x + z cot(theta)", "The seed's $\\tan\\theta = z/(x_p - x)$ holds for that $x_p$.",
         z / (xp - x), 1 / ct);
  D.define("the seed's product", "Line 72 multiplies $M_{\\text{orth}}$ by $H_{+}$; $M_{\\text{orth}}$ drops z.",
           M_orth * H_plus, mat{{1, 0, ct, 0}, {0, 1, cp, 0}, {0, 0, 0, 0}, {0, 0, 0, 1}});
  D.define("the image of a point, with H+", "As the seed's formulas for $x_p$, $y_p$, $z_p$.", M_orth * H_plus * X,
           column(x + z * ct, y + z * cp, 0, 1));
  const mat projector_plus = column(ct, cp, -1, 0).as("\\left(\\cot\\theta, \\cot\\phi, -1, 0\\right)", tex_precedence::atom);
  D.define("H+ turns the projector into the z axis", "So $M_{\\text{orth}} H_{+}$ collapses each projector to one point.",
           H_plus * projector_plus, column(0, 0, -1, 0));
  D.refute("the seed's later H(theta, phi) with -cot",
           "The slide headed *Oblique* writes $H(\\theta, \\phi)$ with $-\\cot\\theta$ and $-\\cot\\phi$ for the same "
           "angles. With $\\theta$ as the seed defined it, that shear sends the projector "
           "$(\\cot\\theta, \\cot\\phi, -1)$ to $(2\\cot\\theta, 2\\cot\\phi, -1)$, not to the z axis, and "
           "$M_{\\text{orth}} H_{-}$ projects along the mirror-image direction. The smallest counterexample: "
           "$\\theta = 45°$, $\\phi = 90°$ ($\\cot\\theta = 1$, $\\cot\\phi = 0$) and the point $(0, 0, 1)$, which "
           "the seed's own $x_p = x + z\\cot\\theta$ sends to $(1, 0, 0)$ and $M_{\\text{orth}} H_{-}$ to "
           "$(-1, 0, 0)$. (With the other angle convention, $\\theta' = 180° - \\theta$, the slide is right.)",
           "column vectors, X' = M X, with theta from tan(theta) = z/(x_p - x)", M_orth * H_minus * X,
           column(x + z * ct, y + z * cp, 0, 1), {{x, 0}, {y, 0}, {z, 1}, {ct, 1}, {cp, 0}});
  const mat projector_minus = column(ct, cp, 1, 0).as("\\left(\\cot\\theta, \\cot\\phi, 1, 0\\right)", tex_precedence::atom);
  D.define("H- turns its own projector into the z axis", "The projector of the angles measured from the other side.",
           H_minus * projector_minus, column(0, 0, 1, 0));

  const auto decide = comparisons_from(D.facts);
  const scoped_comparisons installed(*decide);
  const mat shear = from_library(oblique_shear(ct, cp), code_tex("oblique_shear") + "(\\cot\\theta, \\cot\\phi)");
  D.code("the library's oblique_shear is H-", "The library follows the $-\\cot$ convention.", "project.h", shear, H_minus);
  D.code("the library's oblique_parallel_projection", "$M_{\\text{orth}} H_{-}$: the image of $(x, y, z)$.", "project.h",
         from_library(oblique_parallel_projection(ct, cp), code_tex("oblique_parallel_projection") + "(\\cot\\theta, \\cot\\phi)") * X,
         column(x - z * ct, y - z * cp, 0, 1));
  // The library's oblique keeps depth: orthographic(…) · H-. The sheared box has corners
  // (x + z cot θ, y + z cot φ, z) over the box corners (x, y, z).
  const mat O = from_library(shadowproof::oblique(l, r, b, t, n, f, ct, cp, depth_convention::gl),
                             code_tex("oblique") + "(l, r, b, t, n, f, \\cot\\theta, \\cot\\phi, \\texttt{gl})");
  D.code("the library's oblique: near corner", "The sheared box's corner over $(l, b, -n)$ goes to $(-1, -1, -1)$.",
         "project.h", affine(O * column(l - n * ct, b - n * cp, -n, 1)), column(-1, -1, -1));
  D.code("the library's oblique: far corner", "The corner over $(r, t, -f)$ goes to $(1, 1, 1)$.", "project.h",
         affine(O * column(r - f * ct, t - f * cp, -f, 1)), column(1, 1, 1));
  const mat T = translation(-(r + l) / 2, -(t + b) / 2, (f + n) / 2, "T");
  const mat S = scaling(2 / (r - l), 2 / (t - b), -2 / (f - n), "S");
  D.code("the library's normalised oblique projection", "Seed 002's $M_{\\text{orth}} S T H(\\theta, \\phi)$ with its $-\\cot$ shear.",
         "project.h",
         from_library(oblique_normalized_projection_seed002(l, r, b, t, n, f, ct, cp),
                      code_tex("oblique_normalized_projection_seed002") + "(\\ldots)"),
         M_orth * S * T * H_minus);
  D.conclusion =
      "Seed 002's two shears are the same construction for two angle conventions: with $\\theta$ from "
      "$\\tan\\theta = z/(x_p - x)$ the shear has $+\\cot$; the library, like Angel and the seed's later slide, "
      "uses $-\\cot$ with the projector $(\\cot\\theta, \\cot\\phi, 1)$. `shadowproof explain oblique` "
      "takes `--cot-sign plus` or `minus` to pick one.";
  return D;
}

}  // namespace shadowproof::proofs
