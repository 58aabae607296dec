// The planar shadow matrix for any homogeneous light, from the line/plane intersection, and the
// library's shadow_matrix and shadow_image against it.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof::proofs {

derivation shadow_matrix() {
  const term a = var("a", "a"), b = var("b", "b"), c = var("c", "c"), d = var("d", "d");
  const term Lx = var("Lx", "L_x"), Ly = var("Ly", "L_y"), Lz = var("Lz", "L_z"), Lw = var("Lw", "L_w");
  const term Vx = var("Vx", "V_x"), Vy = var("Vy", "V_y"), Vz = var("Vz", "V_z");
  const term Wx = var("Wx", "W_x"), Wy = var("Wy", "W_y"), Wz = var("Wz", "W_z"), Ww = var("Ww", "W_w");
  const term k = var("k", "k");

  const mat P = mat::named("P", column(a, b, c, d));
  const mat L = mat::named("L", column(Lx, Ly, Lz, Lw));
  const mat V = mat::named("V", column(Vx, Vy, Vz, 1));
  const mat W = mat::named("W", column(Wx, Wy, Wz, Ww));
  const term PL = dot(P, L), PV = dot(P, V), PW = dot(P, W);

  derivation D;
  D.slug = "shadow_matrix";
  D.title = "The shadow matrix for any homogeneous light";
  D.intro =
      "The receiver is the plane $P = (a, b, c, d)$, the points $X$ with $P \\cdot X = 0$. The light "
      "is $L = (L_x, L_y, L_z, L_w)$: a point light when $L_w \\neq 0$, a directional light (pointing "
      "towards the light) when $L_w = 0$. Vectors are columns and a matrix acts as $M V$. The shadow "
      "of the point $V = (V_x, V_y, V_z, 1)$ is where the line through $V$ and $L$ meets the plane; "
      "$W = (W_x, W_y, W_z, W_w)$ is any homogeneous vector.";
  D.assume_nonzero(PL);

  D.define("the plane value of L", "The dot product of the plane with the light.", PL, a * Lx + b * Ly + c * Lz + d * Lw);
  D.define("the plane value of V", "The dot product with $V = (V_x, V_y, V_z, 1)$.", PV, a * Vx + b * Vy + c * Vz + d);
  D.show("the line meets the plane where a linear equation in k holds",
         "The points of the line are $V + kL$; the plane equation is linear, so it splits into two dot "
         "products.",
         dot(P, V + k * L), PV + k * PL);
  const mat image = V - (PV / PL) * L;
  D.show("k = -(P.V)/(P.L) puts the point on the plane",
         "Solving $P \\cdot V + k\\,(P \\cdot L) = 0$ for $k$ needs $P \\cdot L \\neq 0$; substituting "
         "the solution back gives zero.",
         dot(P, image), 0);
  D.show("the projected point over a common denominator", "Bring $V + kL$ with that $k$ over the denominator $P \\cdot L$.",
         image, (1 / PL) * (PL * V - PV * L));
  D.show("drop the denominator: the same homogeneous point",
         "A homogeneous vector and any non-zero multiple of it name the same point, so multiply by "
         "$P \\cdot L$; this also keeps the formula valid when the image is a point at infinity.",
         PL * image, PL * V - PV * L);

  const mat M_value = PL * identity(4) - L * transpose(P);
  const mat M = mat::named("M", M_value);
  D.define("the shadow matrix", "Blinn's shadow matrix; its action on $V$ is the numerator above.", M, M_value);
  D.show("the numerator is linear in V: a matrix",
         "$(P \\cdot V)\\,L = L\\,(P^{\\mathsf T} V)$, so the numerator is $M V$.", M * V, PL * V - PV * L);
  const mat M_written{{b * Ly + c * Lz + d * Lw, -(b * Lx), -(c * Lx), -(d * Lx)},
                      {-(a * Ly), a * Lx + c * Lz + d * Lw, -(c * Ly), -(d * Ly)},
                      {-(a * Lz), -(b * Lz), a * Lx + b * Ly + d * Lw, -(d * Lz)},
                      {-(a * Lw), -(b * Lw), -(c * Lw), a * Lx + b * Ly + c * Lz}};
  D.define("the shadow matrix entry by entry",
           "Entry $(i, j)$ is $(P \\cdot L)\\,\\delta_{ij} - L_i P_j$; on the diagonal the term $L_i P_i$ "
           "cancels against one term of $P \\cdot L$.",
           M, M_written);
  D.show("every image lies on the plane",
         "For any homogeneous $W$, points and directions alike, whatever the light.", dot(P, M * W), 0);
  D.show("P annihilates M from the left", "The same fact as a row vector.", transpose(P) * M, mat(1, 4));
  D.show("points of the plane stay where they are",
         "$M W - (P \\cdot L) W$ is a multiple of $L$ by $P \\cdot W$, which is zero exactly when $W$ lies on "
         "the plane: the receiver is fixed (up to the scale $P \\cdot L$).",
         M * W - PL * W, -(PW * L));
  D.show("the light itself has no image",
         "The zero vector is no point: the light casts no shadow of itself.", M * L, mat(4, 1));

  const mat code_M = from_library(shadowproof::shadow_matrix(to_plane(P), to_light(L)), code_tex("shadow_matrix") + "(P, L)");
  D.code("the library's shadow_matrix maps every W as derived",
         "The template instantiated with symbols: its matrix applied to a general homogeneous $W$ is "
         "$(P \\cdot L) W - (P \\cdot W) L$, so it is $M$.",
         "shadow.h", code_M * W, PL * W - PW * L);
  const mat code_image =
      from_library(shadowproof::shadow_image(to_plane(P), to_light(L), to_vec4(W)), code_tex("shadow_image") + "(P, L, W)");
  D.code("the library's shadow_image is M W", "The image computed without forming the matrix.", "shadow.h", code_image, M * W);
  D.conclusion =
      "So $M = (P \\cdot L)\\,I - L P^{\\mathsf T}$ maps every point to its shadow on $P$, for point and "
      "directional lights alike; dividing by the last coordinate gives the affine point.";
  return D;
}

}  // namespace shadowproof::proofs
