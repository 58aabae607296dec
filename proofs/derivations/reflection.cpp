// The planar reflection matrix in closed form, without normalising the normal, and the library's
// reflection_matrix against it.
#include "../derivations.h"
#include "../library.h"
#include "shadowproof/constructions/reflect.h"

namespace shadowproof::proofs {

derivation reflection() {
  const term a = var("a", "a"), b = var("b", "b"), c = var("c", "c"), d = var("d", "d");
  const term x = var("x", "x"), y = var("y", "y"), z = var("z", "z");
  const term Wx = var("Wx", "W_x"), Wy = var("Wy", "W_y"), Wz = var("Wz", "W_z"), Ww = var("Ww", "W_w");
  const term lambda = var("lambda", "\\lambda");

  const mat n = mat::named("n", column(a, b, c));
  const mat X = mat::named("X", column(x, y, z));
  const mat P = mat::named("P", column(a, b, c, d));
  const mat W = mat::named("W", column(Wx, Wy, Wz, Ww));
  const term nn = dot(n, n);
  const term side_value = dot(n, X) + d;

  derivation D;
  D.slug = "reflection";
  D.title = "The reflection matrix";
  D.intro =
      "The mirror is the plane $n \\cdot X + d = 0$ with $n = (a, b, c)$, not necessarily of unit length, "
      "so that rational coefficients stay rational; $P = (a, b, c, d)$. The mirror image $X'$ of "
      "$X = (x, y, z)$ is found by walking along the normal twice the signed distance.";
  D.assume_nonzero(nn);
  D.assume_nonzero(lambda);

  const mat Xr = mat::named("X'", X - (2 * side_value / nn) * n);
  D.define("the mirror image", "Walk along $n$ by twice the signed distance $(n \\cdot X + d)/|n|$, in units of $|n|$.",
           Xr, X - (2 * side_value / nn) * n);
  D.show("the midpoint of X and its image lies on the mirror", "Halfway along the step the plane equation is zero.",
         dot(n, (term(1) / 2) * (X + Xr)) + d, 0);
  D.show("the signed plane value changes sign", "The image is as far from the mirror as $X$, on the other side.",
         dot(n, Xr) + d, -side_value);

  const mat M = mat::named("M", mat{{1 - 2 * a * a / nn, -(2 * a * b / nn), -(2 * a * c / nn), -(2 * d * a / nn)},
                                    {-(2 * b * a / nn), 1 - 2 * b * b / nn, -(2 * b * c / nn), -(2 * d * b / nn)},
                                    {-(2 * c * a / nn), -(2 * c * b / nn), 1 - 2 * c * c / nn, -(2 * d * c / nn)},
                                    {0, 0, 0, 1}});
  D.define("the reflection matrix", "$[I - 2 n n^{\\mathsf T}/(n \\cdot n),\\ -2 d\\, n/(n \\cdot n);\\ 0,\\ 1]$.", M, M.written());
  D.show("the image as a matrix", "$X'$ is affine in $X$, so it is $M (X, 1)$.", M * column(x, y, z, 1),
         column(Xr[0], Xr[1], Xr[2], 1).as("\\left(X', 1\\right)", tex_precedence::atom));
  const mat M_written{{(b * b + c * c - a * a) / nn, -(2 * a * b) / nn, -(2 * a * c) / nn, -(2 * a * d) / nn},
                      {-(2 * a * b) / nn, (a * a + c * c - b * b) / nn, -(2 * b * c) / nn, -(2 * b * d) / nn},
                      {-(2 * a * c) / nn, -(2 * b * c) / nn, (a * a + b * b - c * c) / nn, -(2 * c * d) / nn},
                      {0, 0, 0, 1}};
  D.show("the reflection matrix over one denominator",
         "On the diagonal $1 - 2a^2/(n \\cdot n) = (b^2 + c^2 - a^2)/(n \\cdot n)$, and so on.", M, M_written);
  D.show("reflecting twice is the identity", "A mirror image of a mirror image is the original.", M * M, identity(4));
  D.show("the determinant is -1", "A reflection reverses orientation.", det(M), -1);
  const mat A = block(M, 3);
  D.show("the linear part is orthogonal", "$A^{\\mathsf T} A = I$: lengths and angles are preserved.", transpose(A) * A,
         identity(3));
  D.show("the mirror is fixed",
         "$M W - W$ is a multiple of $(n, 0)$ by $P \\cdot W$: zero exactly for the points $W$ of the plane.",
         M * W - W, (-2 * dot(P, W) / nn) * column(a, b, c, 0).as("\\left(n, 0\\right)", tex_precedence::atom));

  const mat code = from_library(reflection_matrix(to_plane(P)), code_tex("reflection_matrix") + "(P)");
  D.code("the library's reflection_matrix", "The template instantiated with symbols gives the matrix above.", "reflect.h",
         code, M_written);
  const mat code_scaled =
      from_library(reflection_matrix(to_plane(lambda * P)), code_tex("reflection_matrix") + "(\\lambda P)");
  D.code("any multiple of (a, b, c, d) gives the same matrix",
         "Scaling the plane by $\\lambda \\neq 0$ scales numerators and denominators by $\\lambda^2$.", "reflect.h",
         code_scaled, M_written);
  D.conclusion =
      "So $M = \\begin{pmatrix} I - 2nn^{\\mathsf T}/(n \\cdot n) & -2dn/(n \\cdot n) \\\\ 0 & 1 "
      "\\end{pmatrix}$, exact for rational planes without normalising $n$.";
  return D;
}

}  // namespace shadowproof::proofs
