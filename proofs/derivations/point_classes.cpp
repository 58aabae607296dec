// The point classes: where the line from the light through V meets the receiver, and every path
// through the library's classify_point checked against that geometry.
#include <string>

#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/classify.h"

namespace shadowproof::proofs {

namespace {

// The geometric condition each class stands for, in terms of s = P·L, t = P·V, w = L_w and the
// parameter λ* = s/(s − w t) of the receiver on the line X(λ) = ℓ + λ(V − ℓ) from the light ℓ.
std::vector<fact> class_condition(point_class c, const std::vector<fact>& path, const term& s, const term& t,
                                  const term& w, const term& lambda, const term& lambda_minus_1, const term& mu,
                                  const std::vector<term>& light_gap) {
  switch (c) {
    case point_class::line_in_plane: return {{s, zero}, {t, zero}};
    case point_class::light_parallel: return {{s, zero}, {t, nonzero}, {w, zero}};
    case point_class::light_on_plane: return {{s, zero}, {t, nonzero}, {w, nonzero}};
    case point_class::on_receiver: return {{s, nonzero}, {t, zero}};
    case point_class::at_light: return {{w, nonzero}, {light_gap[0], zero}, {light_gap[1], zero}, {light_gap[2], zero}};
    case point_class::at_infinity: {
      // The receiver is parallel to the line (w t = s) and V is not the light: some coordinate
      // of w V − L is non-zero on this path.
      std::vector<fact> r{{w, nonzero}, {w * t - s, zero}};
      for (const auto& g : light_gap)
        for (const auto& p : path)
          if (p.expr.tex() == g.tex() && !(p.signs & zero)) {
            r.push_back({g, nonzero});
            return r;
          }
      return r;
    }
    case point_class::shadow:
    case point_class::behind_receiver:
    case point_class::beyond_light: break;
  }
  bool directional = false;
  for (const auto& p : path)
    if (p.expr.tex() == w.tex() && p.signs == zero) directional = true;
  if (directional) return {{w, zero}, {mu, c == point_class::shadow ? positive : negative}};
  if (c == point_class::shadow) return {{w, nonzero}, {lambda_minus_1, positive}};
  if (c == point_class::behind_receiver) return {{w, nonzero}, {lambda, positive}, {lambda_minus_1, negative}};
  return {{w, nonzero}, {lambda, negative}};
}

}  // namespace

derivation point_classes() {
  const term a = var("a", "a"), b = var("b", "b"), c = var("c", "c"), d = var("d", "d");
  const term Lx = var("Lx", "L_x"), Ly = var("Ly", "L_y"), Lz = var("Lz", "L_z"), Lw = var("Lw", "L_w");
  const term Vx = var("Vx", "V_x"), Vy = var("Vy", "V_y"), Vz = var("Vz", "V_z");
  const term lambda = var("lambda", "\\lambda");

  const mat P = mat::named("P", column(a, b, c, d));
  const mat L = mat::named("L", column(Lx, Ly, Lz, Lw));
  const mat V = mat::named("V", column(Vx, Vy, Vz, 1));
  const term s = term::shown(dot(P, L), "s", tex_precedence::atom);
  const term t = term::shown(dot(P, V), "t", tex_precedence::atom);
  const term w = term::shown(Lw, "w", tex_precedence::atom);
  const mat M = mat::named("M", s * identity(4) - L * transpose(P));

  derivation D;
  D.slug = "point_classes";
  D.title = "Real shadows, false shadows, anti-shadows and points at infinity";
  D.intro =
      "The shadow matrix maps every point somewhere, but only some images are shadows. Take the receiver "
      "$P = (a, b, c, d)$, the light $L = (L_x, L_y, L_z, L_w)$ and a finite point $V = (V_x, V_y, V_z, 1)$, "
      "and write $s = P \\cdot L$, $t = P \\cdot V$ and $w = L_w$. For a point light ($w \\neq 0$) the light "
      "is at $\\ell = L/w$, and the line from the light through $V$ is $X(\\lambda) = \\ell + \\lambda (V - "
      "\\ell)$: $\\lambda = 0$ at the light, $\\lambda = 1$ at $V$. Where it meets the receiver, "
      "$\\lambda = \\lambda^*$, decides what the image is:\n\n"
      "- $\\lambda^* > 1$: the line passes $V$ first and then reaches the receiver; $V$ is between the light "
      "and the receiver and casts a **real shadow** (`shadow`);\n"
      "- $0 < \\lambda^* < 1$: the receiver is crossed between the light and $V$; $V$ is behind the receiver "
      "and the image is a **false shadow** (`behind_receiver`): light would have to pass through the "
      "receiver to make it;\n"
      "- $\\lambda^* < 0$: the line meets the receiver on the far side of the light; the light is between "
      "$V$ and its image, an **anti-shadow** (`beyond_light`);\n"
      "- no $\\lambda^*$ ($s = w t$): the line is parallel to the receiver and the image is a point **at "
      "infinity** (`at_infinity`).\n\n"
      "For a directional light ($w = 0$, pointing towards the light) light travels along $-L$; the image "
      "is $V - \\mu L$ with $\\mu = t/s$, a real shadow when $\\mu > 0$ (downstream of $V$) and a false "
      "shadow when $\\mu < 0$. The remaining classes are the degenerate cases $s = 0$ or $t = 0$.";

  const mat ell = (1 / w) * L;
  const mat X = ell + lambda * (V - ell);
  D.define("the plane values", "The dot products the classes depend on.", s, dot(P, L));
  D.show("the receiver along the line",
         "The plane value of $X(\\lambda)$ is affine in $\\lambda$: $s/w$ at the light, $t$ at $V$.",
         dot(P, X), s / w + lambda * (t - s / w));
  D.under({{w, nonzero}});
  const term lambda_star = s / (s - w * t);
  const mat X_star = ell + lambda_star * (V - ell);
  D.show("the receiver is reached at lambda* = s/(s - w t)",
         "Solving the affine equation; it needs $s \\neq w t$: otherwise the line is parallel to the receiver.",
         dot(P, X_star), 0);
  D.under({{w, nonzero}, {s - w * t, nonzero}});
  D.show("the shadow matrix gives that point",
         "$M V$ is $X(\\lambda^*)$ times $s - w t$, which is its last coordinate: the matrix's image is the "
         "intersection, whichever side of the light or the receiver it lies on.",
         M * V, (s - w * t) * X_star);
  D.under({{w, nonzero}, {s - w * t, nonzero}});
  D.show("where the image lies relative to V",
         "$\\lambda^* - 1$ has the sign of $w t/(s - w t)$: beyond $V$ (real shadow) when it is positive.",
         lambda_star - 1, (w * t) / (s - w * t));
  D.under({{w, nonzero}, {s - w * t, nonzero}});
  D.show("the division-free test",
         "With $u = w t/s$ (the point's plane value relative to the light's, $s/w$), $\\lambda^* = 1/(1 - u)$: "
         "a real shadow is $0 < u < 1$, a false shadow $u < 0$, an anti-shadow $u > 1$, at infinity $u = 1$; "
         "the library tests the signs of $w t$, $s$ and $w t - s$ instead of dividing.",
         lambda_star, 1 / (1 - (w * t) / s));
  D.under({{s, nonzero}, {s - w * t, nonzero}});
  const mat Ld = mat::named("L", column(Lx, Ly, Lz, 0));
  const term sd = term::shown(dot(P, Ld), "s", tex_precedence::atom);
  const mat Md = sd * identity(4) - Ld * transpose(P);
  const term mu = t / s;
  D.show("a directional light",
         "With $L_w = 0$, $M V = s\\,(V - \\mu L)$ with $\\mu = t/s$: the image is $V$ moved by $\\mu$ against "
         "the light's pointing direction, i.e. along the light's travel when $\\mu > 0$.",
         Md * V, sd * (V - (t / sd) * Ld));
  D.under({{sd, nonzero}});

  // Every path through the library's classify_point, with the sign conditions of that path, and
  // the geometric condition of the class it returns checked under them.
  const term light_gap[3] = {w * Vx - Lx, w * Vy - Ly, w * Vz - Lz};
  const std::vector<term> gaps(light_gap, light_gap + 3);
  const plane<term> plane_ = to_plane(P);
  const light<term> light_ = to_light(L);
  const vec4<term> point = to_vec4(V);
  const auto paths = explore(
      {}, [&] { return static_cast<int>(classify_point(plane_, light_, point)); },
      {s, t, w, w * t - s, gaps[0], gaps[1], gaps[2]});
  const term lambda_minus_1 = (w * t) / (s - w * t);
  bool first = true;
  for (const auto& path : paths) {
    const auto cls = static_cast<point_class>(path.outcome);
    D.sign(std::string("`") + std::string(to_string(cls)) + "`",
           first ? "Every path through the library's `classify_point` (classify.h) instantiated with symbols: on "
                   "each, the signs its comparisons found, what it returns, and the class's condition from "
                   "above, checked to follow from those signs."
                 : "",
           path.conditions, class_condition(cls, path.conditions, s, t, w, lambda_star, lambda_minus_1, mu, gaps));
    D.steps.back().header = "classify.h";
    first = false;
  }
  D.conclusion =
      "So `classify_point` returns, on every input, the class whose geometric condition holds: its "
      "division-free sign tests are the conditions on $\\lambda^*$ (or on $\\mu$) above.";
  return D;
}

}  // namespace shadowproof::proofs
