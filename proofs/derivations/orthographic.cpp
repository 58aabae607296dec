// Seed 002: orthographic normalisation S T (with the misprinted sign) and the oblique H(θ, φ).
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation orthographic() {
  const auto l = symbol("l", "l"), r = symbol("r", "r"), b = symbol("b", "b"), t = symbol("t", "t"),
             n = symbol("n", "n"), f = symbol("f", "f");
  const auto x = symbol("x", "x"), y = symbol("y", "y"), z = symbol("z", "z");
  const auto ct = symbol("ct", "\\cot\\theta"), cp = symbol("cp", "\\cot\\phi");

  derivation D;
  D.slug = "orthographic";
  D.title = "Orthographic normalisation and the oblique projection";
  D.source = "seed 002";
  D.intro =
      "The view box is $[l, r] \\times [b, t]$ in x and y and $z \\in [-f, -n]$ (the camera looks down "
      "$-z$, near plane $z = -n$). Normalisation maps it onto the cube $[-1, 1]^3$ with the near plane "
      "at $z = -1$: first $T$ moves the box's centre to the origin, then $S$ scales it. Angles of the "
      "oblique projection enter only through $\\cot\\theta$ and $\\cot\\phi$, treated as numbers.";
  D.assume(r - l, "r - l \\neq 0");
  D.assume(t - b, "t - b \\neq 0");
  D.assume(f - n, "f - n \\neq 0");
  D.assume(z, "z \\neq 0");
  D.assume(ct, "\\cot\\theta \\neq 0");

  const matrix T = translation(-(r + l) / 2, -(t + b) / 2, (f + n) / 2);
  const matrix S = scaling(2 / (r - l), 2 / (t - b), -2 / (f - n));
  const matrix ST = S * T;
  D.show("T moves the centre of the box to the origin",
         "The centre is $((l + r)/2, (b + t)/2, -(n + f)/2)$.",
         {T * column((l + r) / 2, (b + t) / 2, -(n + f) / 2, 1), "T\\,(\\text{centre})"},
         column(0, 0, 0, 1));
  D.show("S T written out", "Multiply the scale into the translation.", {ST, "S\\,T"},
         matrix{{2 / (r - l), 0, 0, -(r + l) / (r - l)},
                {0, 2 / (t - b), 0, -(t + b) / (t - b)},
                {0, 0, -2 / (f - n), -(f + n) / (f - n)},
                {0, 0, 0, 1}});
  D.show("the near corner maps to (-1, -1, -1)", "The corner $(l, b, -n)$ of the box.",
         {ST * column(l, b, -n, 1), "S\\,T\\,(l, b, -n, 1)"}, column(-1, -1, -1, 1));
  D.show("the far corner maps to (1, 1, 1)", "The opposite corner $(r, t, -f)$.",
         {ST * column(r, t, -f, 1), "S\\,T\\,(r, t, -f, 1)"}, column(1, 1, 1, 1));

  const matrix ST_printed{{2 / (r - l), 0, 0, -(r + l) / (r - l)},
                          {0, 2 / (t - b), 0, -(t + b) / (t - b)},
                          {0, 0, -2 / (f - n), (f + n) / (f - n)},
                          {0, 0, 0, 1}};
  D.refute("the seed's S T with +(f+n)/(f-n)",
           "The seed prints $+\\frac{f + n}{f - n}$ in row 3, column 4, but its own $S$ and $T$ give "
           "$-\\frac{f + n}{f - n}$. With the printed sign the near plane does not go to $z = -1$: for "
           "the unit box ($l = b = -1$, $r = t = 1$) with $n = 1$, $f = 2$, the point $(0, 0, -1)$ "
           "maps to $z = 5$.",
           {ST_printed, "(S\\,T)_{\\text{printed}}"}, {ST, "S\\,T"},
           {{l, -1}, {r, 1}, {b, -1}, {t, 1}, {n, 1}, {f, 2}});
  D.show("what the printed sign does to the near plane",
         "The printed matrix sends depth $-n$ to $(3n + f)/(f - n)$ instead of $-1$.",
         {at(ST_printed * column(0, 0, -n, 1), 2), "(S\\,T)_{\\text{printed}}\\,(0, 0, -n, 1)\\big|_z"},
         (3 * n + f) / (f - n));

  D.show("oblique: the projector makes angle theta with the plane",
         "The seed's $\\tan\\theta = z/(x_p - x)$ holds for $x_p = x + z\\cot\\theta$.",
         {z / ((x + z * ct) - x), "\\frac{z}{x_p - x}"}, {1 / ct, "\\tan\\theta"});
  const matrix H{{1, 0, ct, 0}, {0, 1, cp, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  const matrix M_orth{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 1}};
  D.show("oblique projection = orthographic after a shear",
         "$H(\\theta, \\phi)$ shears x and y in proportion to z; then $M_{\\text{orth}}$ drops z. The "
         "product is the seed's $P_{\\text{oblique}}$.",
         {M_orth * H, "M_{\\text{orth}}\\,H(\\theta, \\phi)"},
         matrix{{1, 0, ct, 0}, {0, 1, cp, 0}, {0, 0, 0, 0}, {0, 0, 0, 1}});
  D.show("the image of a point",
         "$(x + z\\cot\\theta,\\ y + z\\cot\\phi,\\ 0)$, as the seed's formulas for $x_p$, $y_p$, $z_p$.",
         {M_orth * H * column(x, y, z, 1), "M_{\\text{orth}}\\,H\\,(x, y, z, 1)"},
         column(x + z * ct, y + z * cp, 0, 1));
  D.show("the projectors collapse",
         "The direction $(\\cot\\theta, \\cot\\phi, -1)$ maps to zero: every point of a projector lands "
         "on the same image.",
         {M_orth * H * column(ct, cp, -1, 0), "M_{\\text{orth}}\\,H\\,(\\cot\\theta, \\cot\\phi, -1, 0)"},
         matrix(4, 1));
  D.conclusion =
      "Row 3 of seed 002's $ST$ must end in $-\\frac{f + n}{f - n}$. (The seed's later slide writes "
      "$H$ with $-\\cot$; that is the same shear for angles measured from the other side.)";
  return D;
}

}  // namespace shadowproof::proofs
