// The frustum projection (glFrustum's parameters) in any depth convention, finite or infinite far,
// and the library's frustum and perspective against it.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof::proofs {

namespace {

mat frustum_matrix(const term& l, const term& r, const term& b, const term& t, const term& n, const term& A,
                   const term& B, const std::string& tex) {
  return mat::named(tex, mat{{2 * n / (r - l), 0, (r + l) / (r - l), 0},
                             {0, 2 * n / (t - b), (t + b) / (t - b), 0},
                             {0, 0, A, B},
                             {0, 0, -1, 0}});
}

}  // namespace

derivation frustum() {
  const term l = var("l", "l"), r = var("r", "r"), b = var("b", "b"), t = var("t", "t"), n = var("n", "n"),
             f = var("f", "f");
  const term zn = var("zn", "z_{\\text{near}}"), zf = var("zf", "z_{\\text{far}}");
  const term x = var("x", "x"), y = var("y", "y"), z = var("z", "z");
  const term A = var("A", "A"), B = var("B", "B");
  const term c = var("c", "c"), aspect = var("aspect", "a");

  derivation D;
  D.slug = "frustum";
  D.title = "The frustum projection in any depth convention";
  D.intro =
      "The eye looks down $-z$. The window $[l, r] \\times [b, t]$ lies on the near plane $z = -n$ and the far "
      "plane is $z = -f$ (distances $n, f > 0$). The depth convention says where the planes land: "
      "$z_{\\text{near}}$ and $z_{\\text{far}}$ are $-1, 1$ (OpenGL), $0, 1$ (Direct3D, Vulkan, Metal) or "
      "$1, 0$ (reverse-Z). `perspective` is the symmetric case with focal scale $c = \\cot(\\text{fovy}/2) > 0$ "
      "and aspect ratio $a > 0$. This is what `shadowproof explain perspective` evaluates when given a window.";
  D.assume_nonzero(r - l);
  D.assume_nonzero(t - b);
  D.assume_positive(n);
  D.assume_positive(f);
  D.assume_nonzero(f - n);
  D.assume_nonzero(z);
  D.assume_positive(c);
  D.assume_positive(aspect);

  const term xn = n * x / -z;
  D.show("the window maps onto [-1, 1]",
         "A point seen from the eye meets the near plane at $x_n = n x/(-z)$, and the window $[l, r]$ goes to "
         "$[-1, 1]$. Over the common denominator $-z$ this is linear in $x$ and $z$: row 1 of a matrix whose last "
         "row $(0, 0, -1, 0)$ makes $w = -z$.",
         2 * (xn - l) / (r - l) - 1, (2 * n / (r - l) * x + (r + l) / (r - l) * z) / -z);
  const auto depth = [](const term& a, const term& bb, const term& zz) { return (a * zz + bb) / -zz; };
  D.show("depth is (Az + B)/(-z)", "Row 3 is $(0, 0, A, B)$; the near condition is linear in $A$ and $B$.",
         n * depth(A, B, -n), -n * A + B);
  const term A0 = (n * zn - f * zf) / (f - n);
  const term B0 = n * zn + n * A0;
  D.show("subtracting the two conditions gives A",
         "$-nA + B = n z_{\\text{near}}$ and $-fA + B = f z_{\\text{far}}$; subtracting, "
         "$(f - n) A = n z_{\\text{near}} - f z_{\\text{far}}$.",
         (f - n) * A0, n * zn - f * zf);
  D.show("then B", "From the near condition $B = n z_{\\text{near}} + nA$; in closed form:", B0,
         n * f * (zn - zf) / (f - n));
  D.show("the near plane lands on z_near", "Substituting $A$ and $B$.", depth(A0, B0, -n), zn);
  D.show("the far plane lands on z_far", "And at the far plane.", depth(A0, B0, -f), zf);
  const term Ainf = -zf, Binf = n * (zn - zf);
  D.show("infinite far plane: the depth formula",
         "With $A = -z_{\\text{far}}$ and $B = n(z_{\\text{near}} - z_{\\text{far}})$ the depth tends to "
         "$z_{\\text{far}}$ as $z \\to -\\infty$.",
         depth(Ainf, Binf, z), zf + n * (zn - zf) / -z);
  D.show("infinite far plane: the near plane still lands on z_near", "At $z = -n$.", depth(Ainf, Binf, -n), zn);

  const mat M = frustum_matrix(l, r, b, t, n, A0, B0, "M");
  D.show("the near corner", "$(l, b, -n)$ goes to $(-1, -1, z_{\\text{near}})$.", affine(M * column(l, b, -n, 1)),
         column(-1, -1, zn));
  D.show("the far corner", "The far corner over $(r, t)$ is $(rf/n, tf/n, -f)$; it goes to $(1, 1, z_{\\text{far}})$.",
         affine(M * column(r * f / n, t * f / n, -f, 1)), column(1, 1, zf));
  D.show("the image of any point", "The x coordinate after division by $w$ is the window mapping of step 1.",
         affine(M * column(x, y, z, 1)).entry(0), 2 * (xn - l) / (r - l) - 1);

  const auto decide = comparisons_from(D.facts);
  const scoped_comparisons installed(*decide);
  const std::vector<std::pair<depth_convention, std::pair<int, int>>> conventions = {
      {depth_convention::gl, {-1, 1}}, {depth_convention::d3d, {0, 1}}, {depth_convention::reverse_z, {1, 0}}};
  for (const auto& [conv, z_range] : conventions) {
    const std::string name(to_string(conv));
    const std::vector<std::pair<term, term>> at{{zn, z_range.first}, {zf, z_range.second}};
    const term An = A0.substitute(at), Bn = B0.substitute(at);
    D.code("the library's frustum, " + name, "The template equals $M$ with the convention's depths.", "project.h",
           from_library(shadowproof::frustum(l, r, b, t, n, f, conv), code_tex("frustum") + "(l, r, b, t, n, f, \\texttt{" + name + "})"),
           frustum_matrix(l, r, b, t, n, An, Bn, "M\\big|_{\\texttt{" + name + "}}"));
    D.code("the library's frustum, " + name + ", infinite far plane", "The limit $f \\to \\infty$.", "project.h",
           from_library(shadowproof::frustum(l, r, b, t, n, f, conv, true),
                        code_tex("frustum") + "(l, r, b, t, n, \\infty, \\texttt{" + name + "})"),
           frustum_matrix(l, r, b, t, n, Ainf.substitute(at), Binf.substitute(at), "M_{\\infty}\\big|_{\\texttt{" + name + "}}"));
    const term top = n / c, right = top * aspect;
    D.code("the library's perspective, " + name,
           "The symmetric frustum with top $= n/c$ and right $=$ top $\\cdot\\, a$.", "project.h",
           from_library(shadowproof::perspective(c, aspect, n, f, conv), code_tex("perspective") + "(c, a, n, f, \\texttt{" + name + "})"),
           frustum_matrix(-right, right, -top, top, n, An, Bn, "M\\big|_{l = -r,\\ b = -t}"));
  }
  D.conclusion =
      "So $M$ has rows $(\\frac{2n}{r-l}, 0, \\frac{r+l}{r-l}, 0)$, $(0, \\frac{2n}{t-b}, \\frac{t+b}{t-b}, 0)$, "
      "$(0, 0, A, B)$, $(0, 0, -1, 0)$ with $A = \\frac{n z_{\\text{near}} - f z_{\\text{far}}}{f - n}$ and "
      "$B = \\frac{n f (z_{\\text{near}} - z_{\\text{far}})}{f - n}$, or $A = -z_{\\text{far}}$, "
      "$B = n (z_{\\text{near}} - z_{\\text{far}})$ for an infinite far plane; the library computes exactly these.";
  return D;
}

}  // namespace shadowproof::proofs
