// Seed 001: line/plane intersection (with its case list), then a directional light onto the
// ground plane y = h by intersection and by similar triangles, against the general shadow matrix
// and the library's two shader formulas.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof::proofs {

derivation seed001_ground_plane() {
  // A general line and plane for the seed's case list.
  const term px = var("p0x", "p_x"), py = var("p0y", "p_y"), pz = var("p0z", "p_z");
  const term nx = var("nx", "n_x"), ny = var("ny", "n_y"), nz = var("nz", "n_z");
  const term ex = var("ex", "e_x"), ey = var("ey", "e_y"), ez = var("ez", "e_z");
  const term ux = var("ux", "u_x"), uy = var("uy", "u_y"), uz = var("uz", "u_z");
  const term dd = var("dd", "d");
  // The ground plane and the light.
  const term h = var("h", "h");
  const term Lx = var("Lx", "L_x"), Ly = var("Ly", "L_y"), Lz = var("Lz", "L_z");
  const term Px = var("Px", "P_x"), Py = var("Py", "P_y"), Pz = var("Pz", "P_z");
  const term s = var("s", "s");

  derivation D;
  D.slug = "seed001_ground_plane";
  D.title = "Directional light onto the ground plane y = h";
  D.source = "seed 001";
  D.intro =
      "First the seed's general line and plane: the plane through $p_0 = (p_x, p_y, p_z)$ with normal "
      "$n = (n_x, n_y, n_z)$, and the line $L_0 + d\\,u$ with direction $u = (u_x, u_y, u_z)$ through a point "
      "$L_0$ of the plane, written $L_0 = p_0 + n \\times e$ for an arbitrary $e = (e_x, e_y, e_z)$ (every "
      "point of the plane is of this form when $n \\neq 0$). Then the ground $y = h$, i.e. the plane "
      "$(0, 1, 0, -h)$ through $(0, h, 0)$ with normal $(0, 1, 0)$, the light direction "
      "$L = (L_x, L_y, L_z)$ pointing towards the light, and the point $P = (P_x, P_y, P_z)$ (here $P$ is "
      "the point, as in the seed, not the plane). Method 1 intersects the ray $P + tL$ with the plane; "
      "method 2 uses similar triangles.";
  D.assume_nonzero(Ly);
  D.assume_nonzero(Lx);
  D.assume_nonzero(s);
  D.assume_nonzero(Py - h);

  // --- The seed's case list for a line and a plane ------------------------------------------
  const mat p0 = mat::named("p_0", column(px, py, pz));
  const mat n = mat::named("n", column(nx, ny, nz));
  const mat e = mat::named("e", column(ex, ey, ez));
  const mat u = mat::named("u", column(ux, uy, uz));
  const mat cross = mat(3, 1, {ny * ez - nz * ey, nz * ex - nx * ez, nx * ey - ny * ex}, "n \\times e", tex_precedence::product);
  const mat L0 = mat::named("L_0", p0 + cross);
  D.show("L0 lies on the plane", "$(p_0 - L_0) \\cdot n = -(n \\times e) \\cdot n = 0$ for every $e$.",
         dot(p0 - L0, n), 0);
  D.show("the plane along the line", "The plane value of the line's point $L_0 + d\\,u$ is $d$ times $u \\cdot n$.",
         dot(L0 + dd * u - p0, n), dd * dot(u, n));
  D.refute("the seed's second case: (p0 - L0) . n = 0 puts the whole line in the plane",
           "The seed's case list says that when $(p_0 - L_0) \\cdot n = 0$ the line lies in the plane. That only "
           "says $L_0$ is on the plane; the line lies in it only if also $u \\cdot n = 0$ (the first case). The "
           "smallest counterexample is the plane $y = 0$ with the line through the origin along $u = (0, 1, 0)$: "
           "its point at $d = 1$ is $(0, 1, 0)$, off the plane. (With $u \\cdot n \\neq 0$ this line meets the "
           "plane in the single point $L_0$, the seed's third case, so cases 2 and 3 contradict each other.)",
           "no matrix is involved", dot(L0 + dd * u - p0, n), 0,
           {{dd, 1}, {ux, 0}, {uy, 1}, {uz, 0}, {nx, 0}, {ny, 1}, {nz, 0}});

  // --- The ground plane y = h -----------------------------------------------------------------
  const mat ground = mat::named("G", column(0, 1, 0, -h));
  const mat L = mat::named("L", column(Lx, Ly, Lz, 0));
  const mat X = mat::named("(P, 1)", column(Px, Py, Pz, 1));
  const mat g0 = mat::named("p_0", column(0, h, 0)), normal = mat::named("n", column(0, 1, 0));
  const mat dir = mat::named("L", column(Lx, Ly, Lz)), X3 = mat::named("P", column(Px, Py, Pz));

  const term t = dot(g0 - X3, normal) / dot(dir, normal);
  D.define("method 1: the ray parameter",
           "From $(tL + P - p_0) \\cdot n = 0$; with the ground's normal this is a height difference over $L_y$.",
           t, (h - Py) / Ly);
  const mat G1 = X3 + t * dir;
  D.show("method 1: the image lies on the ground", "Its y coordinate is $P_y + t L_y = h$.", G1.entry(1), h);
  D.show("normalising the light direction changes t, not the image",
         "The shader uses $L/|L|$; any non-zero scale $s$ of $L$ divides $t$ by $s$ and multiplies the step by $s$.",
         X3 + (dot(g0 - X3, normal) / dot(s * dir, normal)) * (s * dir), G1);

  const mat M = mat::named("M", dot(ground, L) * identity(4) - L * transpose(ground));
  D.define("the shadow matrix for this plane and light",
           "$M = (G \\cdot L) I - L G^{\\mathsf T}$ with $G = (0, 1, 0, -h)$ and $L_w = 0$.", M,
           mat{{Ly, -Lx, 0, h * Lx}, {0, 0, 0, h * Ly}, {0, -Lz, Ly, h * Lz}, {0, 0, 0, Ly}});
  D.show("method 1 agrees with the shadow matrix", "Dividing $M (P, 1)$ by its last coordinate $L_y$ gives the intersection point.",
         affine(M * X), G1);

  const term Gx = Px - Lx * (Py - h) / Ly;
  const term Gz = Pz - Lz * (Py - h) / Ly;
  D.show("method 2: similar triangles give the seed's G_x",
         "The seed's proportion $-L_y / L_x = (P_y - h)/(G_x - P_x)$ holds for $G_x = P_x - L_x (P_y - h)/L_y$; "
         "as a ratio it needs $L_x \\neq 0$ and $P_y \\neq h$ (a point on the ground has no triangle).",
         -Ly / Lx, (Py - h) / (Gx - Px));
  D.show("method 2 agrees with method 1",
         "For $P_y > h$ the clamp is inactive and the shader's $(G_x, h, G_z)$ is the intersection point.",
         column(Gx, h, Gz), G1);

  const std::array<term, 3> P3 = to_array(X3), dir3 = to_array(dir);
  D.code("the library's method 1 is the shadow matrix's image",
         "`ground_shadow_by_intersection` instantiated with symbols.", "shadow.h",
         from_library(ground_shadow_by_intersection(P3, dir3, h), code_tex("ground_shadow_by_intersection") + "(P, L, h)"),
         affine(M * X));
  {
    const std::vector<fact> above{{Py - h, positive}};
    const auto decide = comparisons_from(above);
    const scoped_comparisons installed(*decide);
    D.code("the library's method 2 above the ground",
           "`ground_shadow_by_similar_triangles` with its comparisons decided by $P_y > h$.", "shadow.h",
           from_library(ground_shadow_by_similar_triangles(P3, dir3, h),
                        code_tex("ground_shadow_by_similar_triangles") + "(P, L, h)"),
           affine(M * X));
    D.under(above);
  }
  {
    const std::vector<fact> below{{Py - h, negative}};
    const auto decide = comparisons_from(below);
    const scoped_comparisons installed(*decide);
    const mat clamped = from_library(ground_shadow_by_similar_triangles(P3, dir3, h),
                                     code_tex("ground_shadow_by_similar_triangles") + "(P, L, h)");
    D.code("the library's method 2 below the ground leaves the point where it is",
           "With $P_y < h$ the clamp sets the height step to 0 and keeps $P_y$.", "shadow.h", clamped, X3);
    D.under(below);
    D.disprove("the clamped shader agrees with the matrix below the ground",
               "Below the ground the shader returns $P$ unchanged while the matrix still projects $P$ up onto "
               "$y = h$ (a false shadow of a point under the floor). A deliberate choice of the shader, not a "
               "mistake, but the two methods differ there.",
               clamped, affine(M * X), {{h, 0}, {Lx, 1}, {Ly, 1}, {Lz, 0}, {Px, 0}, {Py, -1}, {Pz, 0}});
    D.under(below);
    D.not_a_mistake("a deliberate clamp: a point below the ground stays where it is instead of casting a false shadow");
  }
  D.conclusion =
      "Both methods are the shadow matrix for points above the ground; below it, method 2 leaves the point "
      "where it is. The seed's case list needs $u \\cdot n = 0$ in its second case.";
  return D;
}

}  // namespace shadowproof::proofs
