// Seed 002: a point light onto y = 0 as T(l) N T(-l), and the library's version of it.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof::proofs {

derivation seed002_point_light_ground() {
  const term xl = var("xl", "x_l"), yl = var("yl", "y_l"), zl = var("zl", "z_l");
  const term x = var("x", "x"), y = var("y", "y"), z = var("z", "z");

  const mat N = mat::named("N", mat{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 1 / -yl, 0, 0}});
  const mat V = mat::named("V", column(x, y, z, 1));
  const mat ground = mat::named("P", column(0, 1, 0, 0));
  const mat L = mat::named("L", column(xl, yl, zl, 1));

  derivation D;
  D.slug = "seed002_point_light_ground";
  D.title = "Point light onto y = 0 through T(l) N T(-l)";
  D.source = "seed 002";
  D.intro =
      "The light is the point $\\ell = (x_l, y_l, z_l)$ and the receiver the ground $y = 0$. The seed "
      "moves the light to the origin with $T(-\\ell)$, projects from the origin with $N$, and moves back "
      "with $T(\\ell)$. The point is $V = (x, y, z, 1)$.";
  D.assume_nonzero(yl);
  D.assume_nonzero(y - yl);

  D.define("the seed's N", "As printed: the last row divides by $-y_l$.", N, N.written());
  const mat NV = N * V;
  D.show("N projects from the origin onto the plane y = -y_l",
         "Dividing by $w$ scales the point from the origin until its height is $-y_l$, which is where the ground "
         "is once the light sits at the origin.",
         NV.entry(1) / NV.entry(3), -yl);
  D.under({{y, nonzero}});
  const mat T_plus = translation(xl, yl, zl, "T(\\ell)"), T_minus = translation(-xl, -yl, -zl, "T(-\\ell)");
  const mat composed = T_plus * N * T_minus;
  D.show("the composition written out", "Multiplying the three matrices.", composed,
         mat{{1, -xl / yl, 0, 0}, {0, 0, 0, 0}, {0, -zl / yl, 1, 0}, {0, -1 / yl, 0, 1}});
  const mat M = mat::named("M", dot(ground, L) * identity(4) - L * transpose(ground));
  D.show("it is the general shadow matrix up to the scale 1/y_l",
         "With $P = (0, 1, 0, 0)$ and $L = (x_l, y_l, z_l, 1)$, $P \\cdot L = y_l$; every entry of "
         "$T(\\ell) N T(-\\ell)$ is $1/y_l$ times the entry of $M$, so both are the same projective map.",
         composed, (1 / yl) * M);
  D.not_a_mistake("a non-zero multiple of a homogeneous matrix is the same projective map");
  const mat MV = M * V;
  D.show("the seed's x_p",
         "The x coordinate of $M V$ divided by its $w = y_l - y$; this needs $y \\neq y_l$: a point level with "
         "the light has its shadow at infinity.",
         MV.entry(0) / MV.entry(3), xl - (x - xl) / ((y - yl) / yl));
  D.show("the seed's y_p", "The image lies on the ground.", MV.entry(1) / MV.entry(3), 0);
  D.show("the seed's z_p", "The same as $x_p$ with $z$ in place of $x$.", MV.entry(2) / MV.entry(3),
         zl - (z - zl) / ((y - yl) / yl));
  D.code("the library's T(l) N T(-l)", "`ground_shadow_matrix_by_translation` instantiated with symbols.", "shadow.h",
         from_library(ground_shadow_matrix_by_translation(xl, yl, zl),
                      code_tex("ground_shadow_matrix_by_translation") + "(x_l, y_l, z_l)"),
         (1 / yl) * M);
  D.conclusion = "The seed's construction is correct: $T(\\ell) N T(-\\ell) = \\frac{1}{y_l} M$.";
  return D;
}

}  // namespace shadowproof::proofs
