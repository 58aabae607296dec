// Seed 001: a directional light onto the ground plane y = h, by intersection and by similar
// triangles, against the general shadow matrix.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation seed001_ground_plane() {
  const auto h = symbol("h", "h");
  const auto Lx = symbol("Lx", "L_x"), Ly = symbol("Ly", "L_y"), Lz = symbol("Lz", "L_z");
  const auto Px = symbol("Px", "P_x"), Py = symbol("Py", "P_y"), Pz = symbol("Pz", "P_z");
  const auto s = symbol("s", "s");

  const matrix plane = column(0, 1, 0, -h);   // y - h = 0
  const matrix L = column(Lx, Ly, Lz, 0);     // towards the light
  const matrix X = column(Px, Py, Pz, 1);
  const matrix p0 = column(0, h, 0), n = column(0, 1, 0), dir = column(Lx, Ly, Lz), X3 = column(Px, Py, Pz);

  derivation D;
  D.slug = "seed001_ground_plane";
  D.title = "Directional light onto the ground plane y = h";
  D.source = "seed 001";
  D.intro =
      "The ground is $y = h$, i.e. the plane $(0, 1, 0, -h)$ through $p_0 = (0, h, 0)$ with normal "
      "$n = (0, 1, 0)$; the light direction is $L = (L_x, L_y, L_z)$, pointing towards the light, and "
      "the point is $P = (P_x, P_y, P_z)$. (Here $P$ is the point, as in the seed, not the plane.) "
      "Method 1 intersects the ray $P + tL$ with the plane; method 2 uses similar triangles.";
  D.assume(Ly, "L_y \\neq 0");
  D.assume(Lx, "L_x \\neq 0");
  D.assume(s, "s \\neq 0");

  const ex t = dot(p0 - X3, n) / dot(dir, n);
  D.show("method 1: the ray parameter",
         "From $(tL + P - p_0) \\cdot n = 0$: $t = ((p_0 - P) \\cdot n)/(L \\cdot n)$; with the ground's "
         "normal this is a height difference over $L_y$.",
         {t, "t = \\frac{(p_0 - P) \\cdot n}{L \\cdot n}"}, (h - Py) / Ly);
  const matrix G1 = X3 + t * dir;
  D.show("method 1: the image lies on the ground",
         "Its y coordinate is $P_y + t L_y = h$.", {at(G1, 1), "(P + tL)_y"}, h);
  D.show("normalising the light direction changes t, not the image",
         "The shader uses $L/|L|$; any non-zero scale $s$ of $L$ divides $t$ by $s$ and multiplies the "
         "step by $s$.",
         {X3 + (dot(p0 - X3, n) / dot(s * dir, n)) * (s * dir), "P + t_{sL}\\,(sL)"}, {G1, "P + tL"});

  const matrix M = dot(plane, L) * identity(4) - outer(L, plane);
  const matrix MX = M * X;
  const matrix affine = column(at(MX, 0) / at(MX, 3), at(MX, 1) / at(MX, 3), at(MX, 2) / at(MX, 3));
  D.show("the shadow matrix for this plane and light",
         "$M = (P_{\\text{ground}} \\cdot L) I - L P_{\\text{ground}}^{\\mathsf T}$ with $P_{\\text{ground}} = "
         "(0, 1, 0, -h)$ and $L_w = 0$.",
         {M, "M"},
         matrix{{Ly, -Lx, 0, h * Lx}, {0, 0, 0, h * Ly}, {0, -Lz, Ly, h * Lz}, {0, 0, 0, Ly}});
  D.show("method 1 agrees with the shadow matrix",
         "Dividing $M (P, 1)$ by its last coordinate $L_y$ gives the intersection point.",
         {affine, "\\text{affine}(M\\,(P, 1))"}, {G1, "P + tL"});

  const ex Gx = Px - Lx * (Py - h) / Ly;
  const ex Gz = Pz - Lz * (Py - h) / Ly;
  D.show("method 2: similar triangles give the seed's G_x",
         "The seed's proportion $-L_y / L_x = (P_y - h)/(G_x - P_x)$ holds for "
         "$G_x = P_x - L_x (P_y - h)/L_y$ (it needs $L_x \\neq 0$ only to be written as a ratio).",
         {-Ly / Lx, "-\\frac{L_y}{L_x}"}, {(Py - h) / (Gx - Px), "\\frac{P_y - h}{G_x - P_x}"});
  D.show("method 2 agrees with method 1 for points above the ground",
         "For $P_y > h$ the clamp is inactive ($\\max(0, P_y - h) = P_y - h$, $\\min(P_y, h) = h$) and "
         "the shader's $(G_x, h, G_z)$ is the intersection point.",
         {column(Gx, h, Gz), "(G_x,\\ h,\\ G_z)"}, {G1, "P + tL"});
  // Below the ground the clamped shader returns P itself.
  D.disprove("the clamped shader agrees with the matrix below the ground",
           "For $P_y < h$ the shader clamps: $\\max(0, P_y - h) = 0$ and $\\min(P_y, h) = P_y$, so it "
           "returns $P$ unchanged, while the matrix still projects $P$ upwards onto $y = h$ (a false "
           "shadow of a point under the floor). This is a deliberate choice of the shader, not a "
           "mistake, but the two methods differ there.",
           {X3, "\\text{shader}(P)\\big|_{P_y < h} = P"}, {affine, "\\text{affine}(M\\,(P, 1))"},
           {{h, 0}, {Lx, 1}, {Ly, 1}, {Lz, 0}, {Px, 0}, {Py, -1}, {Pz, 0}});
  D.conclusion =
      "Both methods are the shadow matrix for points above the ground; below it, method 2 leaves the "
      "point where it is.";
  return D;
}

}  // namespace shadowproof::proofs
