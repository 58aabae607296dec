// Seed 003: the shadow-polygon point Q = L - (V - L)(<N,L> + d)/<N, V - L>, the stray t, and the
// library's shadow_point_by_ray.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof::proofs {

derivation seed003_shadow_polygon() {
  const term a = var("a", "a"), b = var("b", "b"), c = var("c", "c"), d = var("d", "d");
  const term Lx = var("Lx", "L_x"), Ly = var("Ly", "L_y"), Lz = var("Lz", "L_z");
  const term Vx = var("Vx", "V_x"), Vy = var("Vy", "V_y"), Vz = var("Vz", "V_z");
  const term t = var("t", "t");

  const mat N = mat::named("N", column(a, b, c));
  const mat L = mat::named("L", column(Lx, Ly, Lz));
  const mat V = mat::named("V", column(Vx, Vy, Vz));
  const term NL = inner(N, L);
  const term ND = inner(N, V - L);

  derivation D;
  D.slug = "seed003_shadow_polygon";
  D.title = "The shadow-polygon formula for a point light";
  D.source = "seed 003";
  D.intro =
      "The light is the point $L$, the receiver $\\langle N, Q \\rangle + d = 0$ with $N = (a, b, c)$, "
      "and the ray from the light through the point $V$ (the seed calls it $P$) is "
      "$r(t) = L + (V - L)\\,t$.";
  D.assume_nonzero(ND);
  D.assume_nonzero(NL + d);

  const mat r = L + t * (V - L);
  D.show("the plane equation along the ray is linear in t", "Substitute $r(t)$ into $\\langle N, Q \\rangle + d$ and expand.",
         inner(N, r) + d, NL + t * ND + d);
  const term t0 = -(NL + d) / ND;
  D.show("the parameter of the shadow point",
         "Solving for $t$, $t_0 = -(\\langle N, L \\rangle + d)/\\langle N, V - L \\rangle$ makes the plane "
         "equation vanish.",
         NL + t0 * ND + d, 0);
  const term printed = -(NL + d) / inner(N, t0 * (V - L));
  D.refute("the seed's formula for t with a stray t",
           "The seed prints $t = -(\\langle N, L \\rangle + d)/\\langle N, (V - L)t \\rangle$, with $t$ left inside "
           "the denominator. Read as an equation it is not solved for $t$, and the true parameter $t_0$ does "
           "not satisfy it: its right side at $t = t_0$ is identically 1. The smallest counterexample is the "
           "light $(0, 2, 0)$, the point $(0, 1, 0)$ and the plane $y = 0$, where $t_0 = 2$.",
           "no matrix is involved", t0, printed,
           {{a, 0}, {b, 1}, {c, 0}, {d, 0}, {Lx, 0}, {Ly, 2}, {Lz, 0}, {Vx, 0}, {Vy, 1}, {Vz, 0}});
  D.show("the printed right side is always 1",
         "Because $\\langle N, (V - L)t_0 \\rangle = t_0 \\langle N, V - L \\rangle = -(\\langle N, L \\rangle + d)$.",
         printed, 1);
  const mat Q = L - ((NL + d) / ND) * (V - L);
  D.show("the seed's Q is the ray at t_0",
         "The seed's $Q = L - (V - L)(\\langle N, L \\rangle + d)/\\langle N, V - L \\rangle$, as printed, is "
         "$r(t_0)$.",
         L + t0 * (V - L), Q);

  const mat P4 = mat::named("P", column(a, b, c, d)), L4 = mat::named("(L, 1)", column(Lx, Ly, Lz, 1)),
            V4 = mat::named("(V, 1)", column(Vx, Vy, Vz, 1));
  const mat M = mat::named("M", dot(P4, L4) * identity(4) - L4 * transpose(P4));
  D.show("the shadow matrix gives w = -<N, V - L>",
         "For the point light $(L, 1)$ and the plane $P = (N, d)$, the last coordinate of $M (V, 1)$ is "
         "$P \\cdot (L, 1) - P \\cdot (V, 1)$: non-zero exactly when the ray is not parallel to the plane.",
         (M * V4).entry(3), -ND);
  D.show("Q is the affine image under the shadow matrix", "Dividing $M (V, 1)$ by its last coordinate gives the seed's $Q$.",
         affine(M * V4), Q);
  D.code("the library's shadow_point_by_ray", "The seed's formula as the library computes it, instantiated with symbols.",
         "shadow.h",
         from_library(shadow_point_by_ray(to_plane(P4), to_array(L), to_array(V)), code_tex("shadow_point_by_ray") + "(P, L, V)"),
         affine(M * V4));
  D.conclusion =
      "The seed's final formula for $Q$ is right; the line before it must read "
      "$t = -(\\langle N, L \\rangle + d)/\\langle N, V - L \\rangle$.";
  return D;
}

}  // namespace shadowproof::proofs
