// Seed 000: directional light onto a general plane, and its misprinted "V + kL = 0".
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation seed000_directional() {
  const auto a = symbol("a", "a"), b = symbol("b", "b"), c = symbol("c", "c"), d = symbol("d", "d");
  const auto Lx = symbol("Lx", "L_x"), Ly = symbol("Ly", "L_y"), Lz = symbol("Lz", "L_z");
  const auto Vx = symbol("Vx", "V_x"), Vy = symbol("Vy", "V_y"), Vz = symbol("Vz", "V_z");

  const matrix P = column(a, b, c, d);
  const matrix L = column(Lx, Ly, Lz, 0);
  const matrix V = column(Vx, Vy, Vz, 1);
  const ex PL = dot(P, L), PV = dot(P, V);
  const ex k = -PV / PL;

  derivation D;
  D.slug = "seed000_directional";
  D.title = "Directional light onto a general plane";
  D.source = "seed 000";
  D.intro =
      "The light is the direction $L = (L_x, L_y, L_z, 0)$, the receiver $P = (a, b, c, d)$ and the "
      "point $V = (V_x, V_y, V_z, 1)$. The seed starts from the ray $V + kL$ and ends in a 4x4 matrix "
      "written out entry by entry; both ends are right, one line in between is not.";
  D.assume(PL, "P \\cdot L \\neq 0");

  D.refute("the seed's condition V + kL = 0",
           "The seed writes that for some $k$ the ray point $V + kL$ *is the zero vector*. Its last "
           "coordinate is $1 + k \\cdot 0 = 1$ for every $k$, so this never holds; what it means is that "
           "the ray point lies on the plane.",
           {V + k * L, "V + kL"}, {matrix(4, 1), "0"},
           {{a, 0}, {b, 1}, {c, 0}, {d, 0}, {Lx, 0}, {Ly, 1}, {Lz, 0}, {Vx, 0}, {Vy, 0}, {Vz, 0}});
  D.show("corrected: the ray point lies on the plane",
         "With $k = -(V \\cdot P)/(L \\cdot P)$, which the seed derives next from exactly this "
         "condition, the dot product vanishes.",
         {dot(V + k * L, P), "(V + kL) \\cdot P"}, 0);
  D.show("the numerator of the projected point",
         "As in the general derivation, $(L \\cdot P)(V + kL) = V (L \\cdot P) - (V \\cdot P) L$ (the "
         "seed's ($\\ddagger$)).",
         {PL * (V + k * L), "(L \\cdot P)(V + kL)"},
         {PL * V - PV * L, "V\\,(L \\cdot P) - (V \\cdot P)\\,L"});
  D.show("the x component as the seed expands it",
         "The seed's line for the x component: the terms $a L_x V_x$ cancel.",
         {at(PL * V - PV * L, 0), "\\left(V (L \\cdot P) - (V \\cdot P) L\\right)_x"},
         {Vx * (b * Ly + c * Lz) - Vy * (b * Lx) - Vz * (c * Lx) - d * Lx,
          "V_x(bL_y + cL_z) - V_y(bL_x) - V_z(cL_x) - dL_x"});
  D.show("the w coordinate is the denominator",
         "The last coordinate of the numerator is $L \\cdot P$, so dividing by $w$ is dividing by $L "
         "\\cdot P$, as the seed remarks.",
         {at(PL * V - PV * L, 3), "\\left(V (L \\cdot P) - (V \\cdot P) L\\right)_w"},
         {PL, "L \\cdot P"});

  const matrix M_seed{{b * Ly + c * Lz, -b * Lx, -c * Lx, -d * Lx},
                      {-a * Ly, a * Lx + c * Lz, -c * Ly, -d * Ly},
                      {-a * Lz, -b * Lz, a * Lx + b * Ly, -d * Lz},
                      {0, 0, 0, a * Lx + b * Ly + c * Lz}};
  D.show("the seed's matrix is the general shadow matrix with L_w = 0",
         "The printed $M_{\\text{shadow}}$ equals $(P \\cdot L) I - L P^{\\mathsf T}$ for $L_w = 0$, entry "
         "for entry, with no scale factor.",
         {PL * identity(4) - outer(L, P), "(P \\cdot L)\\,I - L P^{\\mathsf T}"}, M_seed);
  D.show("the seed's matrix maps V to the numerator",
         "So $M_{\\text{shadow}} V$ is the projected point in homogeneous form.",
         {M_seed * V, "M_{\\text{shadow}} V"}, {PL * V - PV * L, "V\\,(L \\cdot P) - (V \\cdot P)\\,L"});
  D.conclusion =
      "The seed's matrix is right; only its first equation should read $(V + kL) \\cdot P = 0$.";
  return D;
}

}  // namespace shadowproof::proofs
