// The frustum projection (glFrustum's parameters) in any depth convention, finite or infinite far.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

namespace {

matrix ndc(const matrix& v) { return column(at(v, 0) / at(v, 3), at(v, 1) / at(v, 3), at(v, 2) / at(v, 3)); }

}  // namespace

derivation frustum() {
  const auto l = symbol("l", "l"), r = symbol("r", "r"), b = symbol("b", "b"), t = symbol("t", "t"),
             n = symbol("n", "n"), f = symbol("f", "f");
  const auto zn = symbol("zn", "z_{\\text{near}}"), zf = symbol("zf", "z_{\\text{far}}");
  const auto x = symbol("x", "x"), y = symbol("y", "y"), z = symbol("z", "z");
  const auto A = symbol("A", "A"), B = symbol("B", "B");

  derivation D;
  D.slug = "frustum";
  D.title = "The frustum projection in any depth convention";
  D.intro =
      "The eye looks down $-z$. The window $[l, r] \\times [b, t]$ lies on the near plane $z = -n$ and "
      "the far plane is $z = -f$ (distances $n, f > 0$). The depth convention says where the planes "
      "land: $z_{\\text{near}}$ and $z_{\\text{far}}$ are $-1, 1$ (OpenGL), $0, 1$ (Direct3D, Vulkan, "
      "Metal) or $1, 0$ (reverse-Z). This is what `shadowproof explain perspective` evaluates when "
      "given a window.";
  D.assume(r - l, "r - l \\neq 0");
  D.assume(t - b, "t - b \\neq 0");
  D.assume(n, "n \\neq 0");
  D.assume(f, "f \\neq 0");
  D.assume(f - n, "f - n \\neq 0");
  D.assume(z, "z \\neq 0");

  const ex xn = n * x / (-z);
  D.show("the window maps onto [-1, 1]",
         "A point seen from the eye meets the near plane at $x_n = n x/(-z)$; the window's x range "
         "$[l, r]$ goes to $[-1, 1]$. Over the common denominator $-z$ this is linear in $x$ and $z$, "
         "so it is row 1 of a matrix whose last row $(0, 0, -1, 0)$ makes $w = -z$.",
         {2 * (xn - l) / (r - l) - 1, "\\frac{2 (x_n - l)}{r - l} - 1"},
         {(2 * n / (r - l) * x + (r + l) / (r - l) * z) / (-z),
          "\\frac{\\frac{2n}{r - l}\\,x + \\frac{r + l}{r - l}\\,z}{-z}"});

  const auto depth = [&](const ex& a, const ex& bb, const ex& zz) { return (a * zz + bb) / (-zz); };
  D.show("depth is (Az + B)/(-z)", "Row 3 is $(0, 0, A, B)$; the near condition is linear in A and B.",
         {depth(A, B, -n) * n, "n \\cdot \\frac{A(-n) + B}{n}"}, -n * A + B);
  const ex A0 = (n * zn - f * zf) / (f - n);
  const ex B0 = n * zn + n * A0;
  D.show("subtracting the two conditions gives A",
         "$-nA + B = n z_{\\text{near}}$ and $-fA + B = f z_{\\text{far}}$; subtracting, "
         "$(f - n) A = n z_{\\text{near}} - f z_{\\text{far}}$.",
         {(f - n) * A0, "(f - n)\\,A"}, n * zn - f * zf);
  D.show("then B", "From the near condition $B = n z_{\\text{near}} + nA$; in closed form:",
         {B0, "B"}, {n * f * (zn - zf) / (f - n), "\\frac{n f (z_{\\text{near}} - z_{\\text{far}})}{f - n}"});
  D.show("the near plane lands on z_near", "Substituting A and B.", {depth(A0, B0, -n), "\\text{depth}(-n)"}, zn);
  D.show("the far plane lands on z_far", "And at the far plane.", {depth(A0, B0, -f), "\\text{depth}(-f)"}, zf);
  D.show("OpenGL: A and B", "With $z_{\\text{near}} = -1$, $z_{\\text{far}} = 1$, the familiar entries.",
         {matrix{{A0.subs(GiNaC::lst{zn == -1, zf == 1}), B0.subs(GiNaC::lst{zn == -1, zf == 1})}},
          "(A,\\ B)_{\\text{gl}}"},
         {matrix{{-(f + n) / (f - n), -2 * f * n / (f - n)}},
          "\\left(-\\frac{f + n}{f - n},\\ -\\frac{2fn}{f - n}\\right)"});
  const ex Ainf = -zf, Binf = n * (zn - zf);
  D.show("infinite far plane: the depth formula",
         "With $A = -z_{\\text{far}}$ and $B = n(z_{\\text{near}} - z_{\\text{far}})$ the depth is "
         "$z_{\\text{far}} + n(z_{\\text{near}} - z_{\\text{far}})/(-z)$, which tends to "
         "$z_{\\text{far}}$ as $z \\to -\\infty$.",
         {depth(Ainf, Binf, z), "\\frac{A z + B}{-z}"},
         {zf + n * (zn - zf) / (-z), "z_{\\text{far}} + \\frac{n (z_{\\text{near}} - z_{\\text{far}})}{-z}"});
  D.show("infinite far plane: the near plane still lands on z_near", "At $z = -n$.",
         {depth(Ainf, Binf, -n), "\\text{depth}_\\infty(-n)"}, zn);

  const matrix M{{2 * n / (r - l), 0, (r + l) / (r - l), 0},
                 {0, 2 * n / (t - b), (t + b) / (t - b), 0},
                 {0, 0, A0, B0},
                 {0, 0, -1, 0}};
  D.show("the near corner", "$(l, b, -n)$ goes to $(-1, -1, z_{\\text{near}})$.",
         {ndc(M * column(l, b, -n, 1)), "\\text{ndc}(M\\,(l, b, -n, 1))"}, column(-1, -1, zn));
  D.show("the far corner", "The far corner over $(r, t)$ is $(rf/n, tf/n, -f)$; it goes to $(1, 1, z_{\\text{far}})$.",
         {ndc(M * column(r * f / n, t * f / n, -f, 1)), "\\text{ndc}(M\\,(rf/n, tf/n, -f, 1))"},
         column(1, 1, zf));
  D.show("the image of any point", "The x coordinate after division by w is the window mapping of step 1.",
         {at(ndc(M * column(x, y, z, 1)), 0), "\\text{ndc}(M\\,(x, y, z, 1))_x"}, 2 * (xn - l) / (r - l) - 1);
  D.conclusion =
      "So $M = \\begin{pmatrix} \\frac{2n}{r-l} & 0 & \\frac{r+l}{r-l} & 0 \\\\ 0 & \\frac{2n}{t-b} & "
      "\\frac{t+b}{t-b} & 0 \\\\ 0 & 0 & A & B \\\\ 0 & 0 & -1 & 0 \\end{pmatrix}$ with "
      "$A = \\frac{n z_{\\text{near}} - f z_{\\text{far}}}{f - n}$, $B = \\frac{n f (z_{\\text{near}} - "
      "z_{\\text{far}})}{f - n}$, or $A = -z_{\\text{far}}$, $B = n (z_{\\text{near}} - z_{\\text{far}})$ "
      "for an infinite far plane.";
  return D;
}

}  // namespace shadowproof::proofs
