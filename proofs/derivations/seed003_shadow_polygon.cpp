// Seed 003: the shadow-polygon point Q = L - (V - L)(<N,L> + d)/<N, V - L>, and the stray t.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation seed003_shadow_polygon() {
  const auto a = symbol("a", "a"), b = symbol("b", "b"), c = symbol("c", "c"), d = symbol("d", "d");
  const auto Lx = symbol("Lx", "L_x"), Ly = symbol("Ly", "L_y"), Lz = symbol("Lz", "L_z");
  const auto Vx = symbol("Vx", "V_x"), Vy = symbol("Vy", "V_y"), Vz = symbol("Vz", "V_z");
  const auto t = symbol("t", "t");

  const matrix N = column(a, b, c);
  const matrix L = column(Lx, Ly, Lz);
  const matrix V = column(Vx, Vy, Vz);
  const ex NL = dot(N, L);
  const ex ND = dot(N, V - L);

  derivation D;
  D.slug = "seed003_shadow_polygon";
  D.title = "The shadow-polygon formula for a point light";
  D.source = "seed 003";
  D.intro =
      "The light is the point $L$, the receiver $\\langle N, Q \\rangle + d = 0$ with $N = (a, b, c)$, "
      "and the ray from the light through the point $V$ (the seed calls it $P$) is "
      "$r(t) = L + (V - L)\\,t$.";
  D.assume(ND, "\\langle N, V - L \\rangle \\neq 0");
  D.assume(NL + d, "\\langle N, L \\rangle + d \\neq 0");

  D.show("the plane equation along the ray is linear in t",
         "Substitute $r(t)$ into $\\langle N, Q \\rangle + d$ and expand.",
         {dot(N, L + t * (V - L)) + d, "\\langle N, L + (V - L)t \\rangle + d"},
         {NL + t * ND + d, "\\langle N, L \\rangle + t\\,\\langle N, V - L \\rangle + d"});
  const ex t0 = -(NL + d) / ND;
  D.show("the parameter of the shadow point",
         "Solving for $t$: $t_0 = -(\\langle N, L \\rangle + d)/\\langle N, V - L \\rangle$ makes the "
         "plane equation vanish.",
         {dot(N, L + t0 * (V - L)) + d, "\\langle N, r(t_0) \\rangle + d"}, 0);
  D.refute("the seed's formula for t with a stray t",
           "The seed prints $t = -(\\langle N, L \\rangle + d)/\\langle N, (V - L)t \\rangle$, with $t$ "
           "left inside the denominator. Read as an equation it is not solved for $t$, and the true "
           "parameter $t_0$ does not satisfy it: its right side at $t = t_0$ is identically 1.",
           {t0, "t_0"},
           {-(NL + d) / dot(N, t0 * (V - L)),
            "-\\frac{\\langle N, L \\rangle + d}{\\langle N, (V - L)\\,t_0 \\rangle}"},
           {{a, 0}, {b, 1}, {c, 0}, {d, 0}, {Lx, 0}, {Ly, 2}, {Lz, 0}, {Vx, 0}, {Vy, 1}, {Vz, 0}});
  D.show("the printed right side is always 1",
         "Because $\\langle N, (V - L)t_0 \\rangle = t_0 \\langle N, V - L \\rangle = -(\\langle N, L "
         "\\rangle + d)$.",
         {-(NL + d) / dot(N, t0 * (V - L)),
          "-\\frac{\\langle N, L \\rangle + d}{\\langle N, (V - L)\\,t_0 \\rangle}"},
         1);
  D.show("corrected: t without the stray factor",
         "The linear equation $\\langle N, L \\rangle + t \\langle N, V - L \\rangle + d = 0$ gives "
         "$t = -(\\langle N, L \\rangle + d)/\\langle N, V - L \\rangle$.",
         {NL + t0 * ND + d, "\\langle N, L \\rangle + t_0 \\langle N, V - L \\rangle + d"}, 0);

  const matrix Q = L - ((NL + d) / ND) * (V - L);
  D.show("the seed's Q is the ray at t_0",
         "The seed's $Q = L - (V - L)(\\langle N, L \\rangle + d)/\\langle N, V - L \\rangle$ is "
         "$r(t_0)$, as printed.",
         {L + t0 * (V - L), "r(t_0)"},
         {Q, "L - (V - L)\\,\\frac{\\langle N, L \\rangle + d}{\\langle N, V - L \\rangle}"});

  const matrix P4 = column(a, b, c, d), L4 = column(Lx, Ly, Lz, 1), V4 = column(Vx, Vy, Vz, 1);
  const matrix MV = dot(P4, L4) * V4 - dot(P4, V4) * L4;
  D.show("the shadow matrix gives w = -<N, V - L>",
         "For the point light $(L, 1)$ and plane $(N, d)$, the last coordinate of $M V$ is $(P \\cdot L) "
         "- (P \\cdot V) = -\\langle N, V - L \\rangle$: non-zero exactly when the ray is not parallel "
         "to the plane.",
         {at(MV, 3), "(M V)_w"}, -ND);
  const matrix affine = column(at(MV, 0) / at(MV, 3), at(MV, 1) / at(MV, 3), at(MV, 2) / at(MV, 3));
  D.show("Q is the affine image under the shadow matrix",
         "Dividing $M V$ by its last coordinate gives the seed's $Q$.",
         {affine, "\\text{affine}(M V)"}, {Q, "Q"});
  D.conclusion =
      "The seed's final formula for $Q$ is right; the line before it must read "
      "$t = -(\\langle N, L \\rangle + d)/\\langle N, V - L \\rangle$.";
  return D;
}

}  // namespace shadowproof::proofs
