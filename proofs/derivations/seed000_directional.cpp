// Seed 000: directional light onto a general plane, its misprinted "V + kL = 0", and the
// library's closed form of the seed's matrix.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof::proofs {

derivation seed000_directional() {
  const term a = var("a", "a"), b = var("b", "b"), c = var("c", "c"), d = var("d", "d");
  const term Lx = var("Lx", "L_x"), Ly = var("Ly", "L_y"), Lz = var("Lz", "L_z");
  const term Vx = var("Vx", "V_x"), Vy = var("Vy", "V_y"), Vz = var("Vz", "V_z");
  const term Wx = var("Wx", "W_x"), Wy = var("Wy", "W_y"), Wz = var("Wz", "W_z"), Ww = var("Ww", "W_w");

  const mat P = mat::named("P", column(a, b, c, d));
  const mat L = mat::named("L", column(Lx, Ly, Lz, 0));
  const mat V = mat::named("V", column(Vx, Vy, Vz, 1));
  const mat W = mat::named("W", column(Wx, Wy, Wz, Ww));
  const term PL = dot(L, P), PV = dot(V, P);
  const mat hit = V - (PV / PL) * L;

  derivation D;
  D.slug = "seed000_directional";
  D.title = "Directional light onto a general plane";
  D.source = "seed 000";
  D.intro =
      "The light is the direction $L = (L_x, L_y, L_z, 0)$, the receiver $P = (a, b, c, d)$ and the "
      "point $V = (V_x, V_y, V_z, 1)$; $W$ is any homogeneous vector. The seed starts from the ray "
      "$V + kL$ and ends in a 4x4 matrix written out entry by entry; both ends are right, one line in "
      "between is not.";
  D.assume_nonzero(PL);

  D.refute("the seed's condition V + kL = 0",
           "The seed writes that for some $k$ the ray point $V + kL$ *is the zero vector*. Its last coordinate "
           "is $1 + k \\cdot 0 = 1$ for every $k$, so this never holds; what is meant is that the ray point lies "
           "on the plane. Shown here at the seed's own $k = -(V \\cdot P)/(L \\cdot P)$.",
           "no matrix is involved", hit, mat(4, 1),
           {{a, 0}, {b, 1}, {c, 0}, {d, 0}, {Lx, 0}, {Ly, 1}, {Lz, 0}, {Vx, 0}, {Vy, 0}, {Vz, 0}});
  D.show("corrected: the ray point lies on the plane",
         "With $k = -(V \\cdot P)/(L \\cdot P)$, which the seed derives next from exactly this condition.",
         dot(hit, P), 0);
  D.show("the numerator of the projected point", "The seed's ($\\ddagger$), multiplied by $L \\cdot P$.",
         PL * hit, PL * V - PV * L);
  const mat numerator = PL * V - PV * L;
  D.show("the x component as the seed expands it",
         "The seed's line for the x component: the terms $a L_x V_x$ cancel.", numerator.entry(0),
         Vx * (b * Ly + c * Lz) - Vy * (b * Lx) - Vz * (c * Lx) - d * Lx);
  D.define("the w coordinate is the denominator",
           "The last coordinate of the numerator is $L \\cdot P$ (as $L_w = 0$ and $V_w = 1$), so dividing by "
           "$w$ is dividing by $L \\cdot P$, as the seed remarks.",
           numerator.entry(3), a * Lx + b * Ly + c * Lz);

  const mat M_seed = mat::named("M_{\\text{shadow}}", mat{{b * Ly + c * Lz, -(b * Lx), -(c * Lx), -(d * Lx)},
                                                         {-(a * Ly), a * Lx + c * Lz, -(c * Ly), -(d * Ly)},
                                                         {-(a * Lz), -(b * Lz), a * Lx + b * Ly, -(d * Lz)},
                                                         {0, 0, 0, a * Lx + b * Ly + c * Lz}});
  D.define("the seed's matrix", "As printed.", M_seed, M_seed.written());
  D.show("the seed's matrix maps V to the numerator", "So $M_{\\text{shadow}} V$ is the projected point in homogeneous form.",
         M_seed * V, PL * V - PV * L);
  D.show("the seed's matrix is the general shadow matrix with L_w = 0",
         "On every homogeneous $W$ it acts as $(P \\cdot L) I - L P^{\\mathsf T}$, so the two matrices are equal, "
         "entry for entry, with no scale factor.",
         M_seed * W, PL * W - dot(W, P) * L);
  const mat code = from_library(shadow_matrix_directional_closed_form(to_plane(P), Lx, Ly, Lz),
                                code_tex("shadow_matrix_directional_closed_form") + "(P, L_x, L_y, L_z)");
  D.code("the library's closed form is the seed's matrix",
         "The library keeps the seed's closed form; on every $W$ it is the general shadow matrix.", "shadow.h",
         code * W, PL * W - dot(W, P) * L);
  D.conclusion = "The seed's matrix is right; only its first equation should read $(V + kL) \\cdot P = 0$.";
  return D;
}

}  // namespace shadowproof::proofs
