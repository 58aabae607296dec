// Seed 002: a point light onto y = 0 as T(l) N T(-l).
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation seed002_point_light_ground() {
  const auto xl = symbol("xl", "x_l"), yl = symbol("yl", "y_l"), zl = symbol("zl", "z_l");
  const auto x = symbol("x", "x"), y = symbol("y", "y"), z = symbol("z", "z");

  const matrix N{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, -1 / yl, 0, 0}};
  const matrix V = column(x, y, z, 1);
  const matrix ground = column(0, 1, 0, 0);
  const matrix L = column(xl, yl, zl, 1);

  derivation D;
  D.slug = "seed002_point_light_ground";
  D.title = "Point light onto y = 0 through T(l) N T(-l)";
  D.source = "seed 002";
  D.intro =
      "The light is the point $\\ell = (x_l, y_l, z_l)$ and the receiver the ground $y = 0$. The seed "
      "moves the light to the origin with $T(-\\ell)$, projects from the origin with $N$, and moves back "
      "with $T(\\ell)$. The point is $V = (x, y, z, 1)$.";
  D.assume(yl, "y_l \\neq 0");
  D.assume(y - yl, "y - y_l \\neq 0");

  const matrix NV = N * V;
  D.show("N projects from the origin onto the plane y = -y_l",
         "$N V = (x, y, z, -y/y_l)$: dividing by $w$ scales the point from the origin until its height "
         "is $-y_l$, which is where the ground is once the light sits at the origin.",
         {at(NV, 1) / at(NV, 3), "\\frac{(N V)_y}{(N V)_w}"}, -yl);
  const matrix composed = translation(xl, yl, zl) * N * translation(-xl, -yl, -zl);
  D.show("the composition written out",
         "Multiplying the three matrices.", {composed, "T(\\ell)\\,N\\,T(-\\ell)"},
         matrix{{1, -xl / yl, 0, 0}, {0, 0, 0, 0}, {0, -zl / yl, 1, 0}, {0, -1 / yl, 0, 1}});
  const matrix M = dot(ground, L) * identity(4) - outer(L, ground);
  D.show("it is the general shadow matrix up to the scale 1/y_l",
         "With $P = (0, 1, 0, 0)$ and $L = (x_l, y_l, z_l, 1)$, $P \\cdot L = y_l$; every entry of "
         "$T(\\ell) N T(-\\ell)$ is $1/y_l$ times the entry of $M$, so both are the same projective map.",
         {composed, "T(\\ell)\\,N\\,T(-\\ell)"},
         {(1 / yl) * M, "\\frac{1}{y_l}\\left((P \\cdot L)\\,I - L P^{\\mathsf T}\\right)"});
  const matrix MV = M * V;
  D.show("the seed's x_p",
         "The seed's $x_p = x_l - (x - x_l)/((y - y_l)/y_l)$ is the x coordinate of $M V$ divided by "
         "its $w = y_l - y$ (this needs $y \\neq y_l$: a point level with the light has its shadow at "
         "infinity).",
         {at(MV, 0) / at(MV, 3), "\\frac{(M V)_x}{(M V)_w}"},
         {xl - (x - xl) / ((y - yl) / yl), "x_l - \\frac{x - x_l}{(y - y_l)/y_l}"});
  D.show("the seed's y_p", "The image lies on the ground.",
         {at(MV, 1) / at(MV, 3), "\\frac{(M V)_y}{(M V)_w}"}, 0);
  D.show("the seed's z_p", "The same as $x_p$ with $z$ in place of $x$.",
         {at(MV, 2) / at(MV, 3), "\\frac{(M V)_z}{(M V)_w}"},
         {zl - (z - zl) / ((y - yl) / yl), "z_l - \\frac{z - z_l}{(y - y_l)/y_l}"});
  D.conclusion = "The seed's construction is correct: $T(\\ell) N T(-\\ell) = \\frac{1}{y_l} M$.";
  return D;
}

}  // namespace shadowproof::proofs
