// The planar shadow matrix for any homogeneous light, from the line/plane intersection.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation shadow_matrix() {
  const auto a = symbol("a", "a"), b = symbol("b", "b"), c = symbol("c", "c"), d = symbol("d", "d");
  const auto Lx = symbol("Lx", "L_x"), Ly = symbol("Ly", "L_y"), Lz = symbol("Lz", "L_z"),
             Lw = symbol("Lw", "L_w");
  const auto Vx = symbol("Vx", "V_x"), Vy = symbol("Vy", "V_y"), Vz = symbol("Vz", "V_z");
  const auto Wx = symbol("Wx", "W_x"), Wy = symbol("Wy", "W_y"), Wz = symbol("Wz", "W_z"),
             Ww = symbol("Ww", "W_w");
  const auto k = symbol("k", "k");

  const matrix P = column(a, b, c, d);
  const matrix L = column(Lx, Ly, Lz, Lw);
  const matrix V = column(Vx, Vy, Vz, 1);
  const matrix W = column(Wx, Wy, Wz, Ww);
  const ex PL = dot(P, L), PV = dot(P, V);

  derivation D;
  D.slug = "shadow_matrix";
  D.title = "The shadow matrix for any homogeneous light";
  D.intro =
      "The receiver is the plane $P = (a, b, c, d)$, the points $X$ with $P \\cdot X = 0$. The light "
      "is $L = (L_x, L_y, L_z, L_w)$: a point light when $L_w \\neq 0$, a directional light (pointing "
      "towards the light) when $L_w = 0$. Vectors are columns and a matrix acts as $M V$. The shadow "
      "of the point $V = (V_x, V_y, V_z, 1)$ is where the line through $V$ and $L$ meets the plane.";
  D.assume(PL, "P \\cdot L \\neq 0");

  D.show("the line meets the plane where a linear equation in k holds",
         "The points of the line are $V + kL$; the plane equation is linear, so it splits into two dot "
         "products.",
         {dot(P, V + k * L), "P \\cdot (V + kL)"}, {PV + k * PL, "P \\cdot V + k\\,(P \\cdot L)"});
  D.show("the plane value of V, written out",
         "The dot product with $V = (V_x, V_y, V_z, 1)$.", {PV, "P \\cdot V"},
         a * Vx + b * Vy + c * Vz + d);
  D.show("the plane value of L, written out",
         "The dot product with $L$; it is the denominator below, assumed non-zero (a light in the "
         "plane's direction casts no shadow onto it).",
         {PL, "P \\cdot L"}, a * Lx + b * Ly + c * Lz + d * Lw);

  const ex k0 = -PV / PL;
  D.show("k = -(P.V)/(P.L) puts the point on the plane",
         "Solving $P \\cdot V + k\\,(P \\cdot L) = 0$ for $k$ needs $P \\cdot L \\neq 0$; substituting "
         "the solution back gives zero.",
         {dot(P, V + k0 * L), "P \\cdot \\left(V - \\frac{P \\cdot V}{P \\cdot L}\\,L\\right)"}, 0);
  D.show("the projected point over a common denominator",
         "Bring $V + kL$ with that $k$ over the denominator $P \\cdot L$.",
         {V + k0 * L, "V - \\frac{P \\cdot V}{P \\cdot L}\\,L"},
         {(1 / PL) * (PL * V - PV * L),
          "\\frac{(P \\cdot L)\\,V - (P \\cdot V)\\,L}{P \\cdot L}"});
  D.show("drop the denominator: the same homogeneous point",
         "A homogeneous vector and any non-zero multiple of it name the same point, so multiply by "
         "$P \\cdot L$; this also keeps the formula valid when the image is a point at infinity.",
         {PL * (V + k0 * L), "(P \\cdot L)\\left(V + kL\\right)"},
         {PL * V - PV * L, "(P \\cdot L)\\,V - (P \\cdot V)\\,L"});

  const matrix M = PL * identity(4) - outer(L, P);
  D.show("the numerator is linear in V: a matrix",
         "$(P \\cdot V)\\,L = L\\,(P^{\\mathsf T} V) = (L P^{\\mathsf T})\\,V$, so the numerator is "
         "$M V$ with $M = (P \\cdot L)\\,I - L P^{\\mathsf T}$ (Blinn's shadow matrix).",
         {M * V, "\\left((P \\cdot L)\\,I - L P^{\\mathsf T}\\right) V"},
         {PL * V - PV * L, "(P \\cdot L)\\,V - (P \\cdot V)\\,L"});

  // Written out by hand entry by entry, independently of the formula above.
  const matrix M_written{{b * Ly + c * Lz + d * Lw, -b * Lx, -c * Lx, -d * Lx},
                         {-a * Ly, a * Lx + c * Lz + d * Lw, -c * Ly, -d * Ly},
                         {-a * Lz, -b * Lz, a * Lx + b * Ly + d * Lw, -d * Lz},
                         {-a * Lw, -b * Lw, -c * Lw, a * Lx + b * Ly + c * Lz}};
  D.show("the shadow matrix entry by entry",
         "Entry $(i, j)$ is $(P \\cdot L)\\,\\delta_{ij} - L_i P_j$; on the diagonal the term $L_i P_i$ "
         "cancels against one term of $P \\cdot L$.",
         {M, "M"}, M_written);
  D.show("every image lies on the plane",
         "For any homogeneous $W$: $P^{\\mathsf T} M W = (P \\cdot L)(P \\cdot W) - (P \\cdot L)(P "
         "\\cdot W)$. This holds for points and directions alike, whatever the light.",
         {dot(P, M * W), "P \\cdot (M W)"}, 0);
  D.show("P annihilates M from the left",
         "The same fact as a row vector: $P^{\\mathsf T} M = (P \\cdot L) P^{\\mathsf T} - (P^{\\mathsf T} "
         "L) P^{\\mathsf T} = 0$.",
         {P.transpose() * M, "P^{\\mathsf T} M"}, matrix(1, 4));
  D.show("points of the plane stay where they are",
         "$M W - (P \\cdot L) W = -(P \\cdot W) L$, which is zero exactly when $W$ lies on the plane: "
         "the receiver is fixed (up to the scale $P \\cdot L$).",
         {M * W - PL * W, "M W - (P \\cdot L)\\,W"}, {(-dot(P, W)) * L, "-(P \\cdot W)\\,L"});
  D.show("the light itself has no image",
         "$M L = (P \\cdot L) L - L (P \\cdot L) = 0$: the zero vector is no point, so the light casts "
         "no shadow of itself.",
         {M * L, "M L"}, matrix(4, 1));
  D.conclusion =
      "So $M = (P \\cdot L)\\,I - L P^{\\mathsf T}$ maps every point to its shadow on $P$, for point and "
      "directional lights alike; dividing by the last coordinate gives the affine point.";
  return D;
}

}  // namespace shadowproof::proofs
