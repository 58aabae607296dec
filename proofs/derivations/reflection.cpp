// The planar reflection matrix in closed form, without normalising the normal.
#include "../derivations.h"
#include "../notation.h"

namespace shadowproof::proofs {

derivation reflection() {
  const auto a = symbol("a", "a"), b = symbol("b", "b"), c = symbol("c", "c"), d = symbol("d", "d");
  const auto x = symbol("x", "x"), y = symbol("y", "y"), z = symbol("z", "z");
  const auto Wx = symbol("Wx", "W_x"), Wy = symbol("Wy", "W_y"), Wz = symbol("Wz", "W_z"),
             Ww = symbol("Ww", "W_w");
  const auto lambda = symbol("lambda", "\\lambda");

  const matrix n = column(a, b, c);
  const matrix X = column(x, y, z);
  const ex nn = dot(n, n);
  const ex side_value = dot(n, X) + d;

  derivation D;
  D.slug = "reflection";
  D.title = "The reflection matrix";
  D.intro =
      "The mirror is the plane $n \\cdot X + d = 0$ with $n = (a, b, c)$, not necessarily of unit "
      "length, so that rational coefficients stay rational. The mirror image $X'$ of $X = (x, y, z)$ "
      "is found by walking along the normal twice the signed distance.";
  D.assume(nn, "n \\cdot n = a^2 + b^2 + c^2 \\neq 0");
  D.assume(lambda, "\\lambda \\neq 0");

  const matrix Xr = X - (2 * side_value / nn) * n;
  D.show("the midpoint of X and its image lies on the mirror",
         "$X' = X - 2\\,\\frac{n \\cdot X + d}{n \\cdot n}\\,n$ moves $X$ along $n$; halfway there the "
         "plane equation is zero.",
         {dot(n, (1 / ex(2)) * (X + Xr)) + d, "n \\cdot \\tfrac{1}{2}(X + X') + d"}, 0);
  const matrix step = Xr - X;
  D.show("X' - X is perpendicular to the mirror",
         "The step is parallel to $n$: its cross product with $n$ vanishes.",
         {column(at(step, 1) * c - at(step, 2) * b, at(step, 2) * a - at(step, 0) * c,
                 at(step, 0) * b - at(step, 1) * a),
          "(X' - X) \\times n"},
         matrix(3, 1));
  D.show("the signed plane value changes sign",
         "The image is as far from the mirror as $X$, on the other side.",
         {dot(n, Xr) + d, "n \\cdot X' + d"}, {-side_value, "-(n \\cdot X + d)"});

  matrix M = identity(4);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) M(i, j) = M(i, j) - 2 * at(n, i) * at(n, j) / nn;
    M(i, 3) = -2 * d * at(n, i) / nn;
  }
  D.show("the image as a matrix",
         "$X'$ is affine in $X$: $X' = (I - 2 n n^{\\mathsf T}/(n \\cdot n)) X - 2 d\\, n/(n \\cdot n)$.",
         {M * column(x, y, z, 1),
          "\\begin{pmatrix} I - \\frac{2 n n^{\\mathsf T}}{n \\cdot n} & -\\frac{2 d\\, n}{n \\cdot n} \\\\ "
          "0 & 1 \\end{pmatrix} \\begin{pmatrix} X \\\\ 1 \\end{pmatrix}"},
         {column(at(Xr, 0), at(Xr, 1), at(Xr, 2), 1), "\\begin{pmatrix} X' \\\\ 1 \\end{pmatrix}"});
  const matrix M_written{
      {(-a * a + b * b + c * c) / nn, -2 * a * b / nn, -2 * a * c / nn, -2 * a * d / nn},
      {-2 * a * b / nn, (a * a - b * b + c * c) / nn, -2 * b * c / nn, -2 * b * d / nn},
      {-2 * a * c / nn, -2 * b * c / nn, (a * a + b * b - c * c) / nn, -2 * c * d / nn},
      {0, 0, 0, 1}};
  D.show("the reflection matrix entry by entry",
         "On the diagonal $1 - 2a^2/(n \\cdot n) = (b^2 + c^2 - a^2)/(n \\cdot n)$, and so on.",
         {M, "M"}, M_written);
  D.show("reflecting twice is the identity", "A mirror image of a mirror image is the original.",
         {M * M, "M^2"}, identity(4));
  D.show("the determinant is -1", "A reflection reverses orientation.", {M.determinant(), "\\det M"}, -1);
  const matrix A = GiNaC::ex_to<matrix>(GiNaC::sub_matrix(M, 0, 3, 0, 3));
  D.show("the linear part is orthogonal",
         "$A = I - 2nn^{\\mathsf T}/(n \\cdot n)$ satisfies $A^{\\mathsf T} A = I$: lengths and angles are "
         "preserved.",
         {A.transpose() * A, "A^{\\mathsf T} A"},
         identity(3));
  const matrix W = column(Wx, Wy, Wz, Ww);
  D.show("the mirror is fixed",
         "$M W - W = -2\\,\\frac{P \\cdot W}{n \\cdot n}\\,(n, 0)$ with $P = (a, b, c, d)$: zero exactly "
         "for the points $W$ of the plane.",
         {M * W - W, "M W - W"},
         {(-2 * dot(column(a, b, c, d), W) / nn) * column(a, b, c, 0),
          "-2\\,\\frac{P \\cdot W}{n \\cdot n}\\,(n, 0)"});

  matrix M_scaled = identity(4);
  const matrix ln = lambda * n;
  const ex lnn = dot(ln, ln);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) M_scaled(i, j) = M_scaled(i, j) - 2 * at(ln, i) * at(ln, j) / lnn;
    M_scaled(i, 3) = -2 * (lambda * d) * at(ln, i) / lnn;
  }
  D.show("any multiple of (a, b, c, d) gives the same matrix",
         "Scaling the plane by $\\lambda \\neq 0$ scales numerators and denominators by $\\lambda^2$.",
         {M_scaled, "M(\\lambda P)"}, {M, "M(P)"});
  D.conclusion =
      "So $M = \\begin{pmatrix} I - 2nn^{\\mathsf T}/(n \\cdot n) & -2dn/(n \\cdot n) \\\\ 0 & 1 "
      "\\end{pmatrix}$, exact for rational planes without normalising $n$.";
  return D;
}

}  // namespace shadowproof::proofs
