#pragma once
/// Derivations with the user's numbers: the same steps as docs/derivations.md, each evaluated
/// exactly over rationals, ending in the matrix the other commands print.
#include <optional>
#include <string>
#include <vector>

#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/plane.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof {

/// One step: a sentence saying why, then lines of exact arithmetic and optionally a matrix.
struct explanation_step {
  std::string why;
  std::vector<std::string> lines;
  std::optional<mat4<rational>> matrix;
};

/// A worked derivation. `result` is the final matrix; `result_name` says what it is.
struct explanation {
  std::string title;
  std::vector<explanation_step> steps;
  std::string result_name;
  mat4<rational> result;
};

/// Shadow matrix M = (P·L) I − L Pᵀ from the line/plane intersection, with P·L, L Pᵀ and M
/// evaluated, the check Pᵀ M = 0, and for each finite point V (w = 1): P·V, k = −(P·V)/(P·L)
/// when P·L ≠ 0, M V and its affine image. P·L = 0 is explained as the degenerate case (M = −L Pᵀ,
/// rank 1), not an error. result equals shadow_matrix(P, L).
explanation explain_shadow(const plane<rational>& P, const light<rational>& L,
                           const std::vector<vec4<rational>>& points = {});

/// Reflection about n·X + d = 0, n = (a, b, c) not normalised: X' = X − 2 (n·X + d)/(n·n) n, so
/// M = [I − 2nnᵀ/(n·n), −2dn/(n·n); 0 0 0 1], with the checks M² = I and det M = −1.
/// result equals reflection_matrix(P).
explanation explain_reflection(const plane<rational>& P);

/// Seed 002's N(α, β): α, β solved by Cramer's rule from z = −n → −1 and z = −f → +1, giving
/// α = (n+f)/(n−f), β = 2nf/(n−f), then the two conditions checked. result equals
/// perspective_normalization(n, f). Throws error "project.degenerate_volume" when n = f.
explanation explain_perspective_normalization(const rational& n, const rational& f);

/// glFrustum-style projection of the window [l, r] × [b, t] at distance n, far plane at f, in
/// depth convention c: x and y rows from the perspective divide and the window, the depth row
/// A, B solved from near → z_near and far → z_far (or the limit f → ∞), and the corners checked.
/// result equals frustum(l, r, b, t, n, f, c, infinite_far); throws frustum's errors.
explanation explain_frustum(const rational& l, const rational& r, const rational& b, const rational& t,
                           const rational& n, const rational& f, depth_convention c, bool infinite_far);

/// Normal matrix G = (M⁻¹)ᵀ from tᵀ n = 0 being preserved: det M, the cofactor matrix
/// cof(M) = adj(M)ᵀ, G = cof(M)/det M and the check Mᵀ G = I. result equals normal_matrix(M).
/// Throws error "matrix.singular" when det M = 0.
explanation explain_normal_matrix(const mat4<rational>& M);

/// Plain text: the title, numbered steps (sentence, indented arithmetic, aligned matrices) and the
/// result matrix in the same layout as the other commands print it.
std::string to_text(const explanation& e);

}  // namespace shadowproof
