#pragma once
/// Derivations with the user's numbers: the same steps as docs/derivations.md, each evaluated
/// exactly over rationals, ending in the matrix the other commands (or the library) build, with a
/// figure of the user's own case drawn from the same exact numbers.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/constructions/classify.h"
#include "shadowproof/constructions/project.h"
#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/plane.h"
#include "shadowproof/explain/figure.h"

namespace shadowproof {

/// One step: a sentence saying why, then lines of exact arithmetic and optionally a matrix.
struct explanation_step {
  std::string why;
  std::vector<std::string> lines;
  std::optional<mat4<rational>> matrix;
};

/// A worked derivation. `result` is the final matrix; `result_name` says what it is; `picture`
/// draws the case (empty panels when there is nothing to draw).
struct explanation {
  std::string title;
  std::vector<explanation_step> steps;
  std::string result_name;
  mat4<rational> result;
  figure picture;
};

/// What a point class means geometrically, as explain prints it: "a real shadow: V lies between
/// the light and the receiver", "a false shadow: V is behind the receiver", ...
std::string_view meaning_of(point_class c);

/// Shadow matrix M = (P·L) I − L Pᵀ from the line/plane intersection, with P·L, L Pᵀ and M
/// evaluated, the check Pᵀ M = 0, and for each finite point V (w = 1): P·V, k = −(P·V)/(P·L)
/// when P·L ≠ 0, M V, its affine image and its class with the parameter that decides it
/// (λ* = s/(s − w t) on the line from a point light, μ = t/s for a directional one). P·L = 0 is
/// explained as the degenerate case (M = −L Pᵀ, rank 1), not an error. result equals
/// shadow_matrix(P, L). The figure shows the receiver, the light, each point, its ray and image.
explanation explain_shadow(const plane<rational>& P, const light<rational>& L,
                           const std::vector<vec4<rational>>& points = {});

/// Reflection about n·X + d = 0, n = (a, b, c) not normalised: X' = X − 2 (n·X + d)/(n·n) n, so
/// M = [I − 2nnᵀ/(n·n), −2dn/(n·n); 0 0 0 1], with the checks M² = I and det M = −1, and each
/// point followed to its image. result equals reflection_matrix(P).
explanation explain_reflection(const plane<rational>& P, const std::vector<vec4<rational>>& points = {});

/// Seed 003's reflection by a change of frame, for the mirror ⟨N, X⟩ + d = 0 where N is the
/// second row of the rotation R of the quaternion q = (w, x, y, z) ≠ 0 (frame_from_quaternion):
/// R, the checks R Rᵀ = I and R N = e_y, then T(dN), R, S(1, −1, 1), Rᵀ, T(−dN) applied in turn
/// to each point, the product, and the seed's printed order read with column and with row
/// vectors. result equals reflection_by_frame(R, d) = reflection_matrix(⟨N, X⟩ + d = 0).
/// Throws error "geometry.zero_quaternion" when q = 0.
explanation explain_reflection_by_frames(const std::array<rational, 4>& q, const rational& d,
                                         const std::vector<vec4<rational>>& points = {});

/// Seed 002's N(α, β): α, β solved by Cramer's rule from z = −n → −1 and z = −f → +1, giving
/// α = (n+f)/(n−f), β = 2nf/(n−f), then the two conditions checked. result equals
/// perspective_normalization(n, f). Throws "project.near_not_positive" (n ≤ 0),
/// "project.far_not_positive" (f ≤ 0), "project.degenerate_volume" (n = f).
explanation explain_perspective_normalization(const rational& n, const rational& f,
                                              const std::vector<vec4<rational>>& points = {});

/// glFrustum-style projection of the window [l, r] × [b, t] at distance n, far plane at f, in
/// depth convention c: x and y rows from the perspective divide and the window, the depth row
/// A, B solved from near → z_near and far → z_far (or the limit f → ∞), and the corners checked.
/// result equals frustum(l, r, b, t, n, f, c, infinite_far); throws frustum's errors.
explanation explain_frustum(const rational& l, const rational& r, const rational& b, const rational& t,
                            const rational& n, const rational& f, depth_convention c, bool infinite_far,
                            const std::vector<vec4<rational>>& points = {});

/// Orthographic projection of the box [l, r] × [b, t] × [−f, −n] onto the canonical volume of c:
/// the x and y rows from the window, the depth row A = (z_near − z_far)/(f − n), B = z_near + A n,
/// the corners checked. result equals orthographic(l, r, b, t, n, f, c); throws its errors.
explanation explain_orthographic(const rational& l, const rational& r, const rational& b, const rational& t,
                                 const rational& n, const rational& f, depth_convention c,
                                 const std::vector<vec4<rational>>& points = {});

/// The sign of cot in the oblique shear. `minus`: H = [1 0 −cot θ 0; 0 1 −cot φ 0; ...], the
/// projector is (cot θ, cot φ, 1) (Angel, seed 002's later slide, the library's oblique_shear).
/// `plus`: H = [1 0 cot θ 0; 0 1 cot φ 0; ...], θ from tan θ = z/(x_p − x), projector
/// (cot θ, cot φ, −1) (seed 002's first slide).
enum class cot_sign { minus, plus };

/// "minus" or "plus"; throws error "explain.cot_sign" for anything else.
cot_sign parse_cot_sign(std::string_view text);

/// The box an oblique projection normalises, with its depth convention.
struct view_box {
  rational l, r, b, t, n, f;
  depth_convention c = depth_convention::gl;
};

/// Oblique parallel projection with the angles given by cot θ and cot φ in convention `sign`:
/// x_p = x ∓ z cot θ, the shear H, the projector sent to the z axis, and either the projection
/// onto z = 0, M_orth·H (no box: result equals oblique_parallel_projection(±cot θ, ±cot φ)), or
/// the box kept with depth, orthographic(box)·H (result equals oblique(box, ±cot θ, ±cot φ, c)).
/// Throws the box's errors.
explanation explain_oblique(const rational& cot_theta, const rational& cot_phi, cot_sign sign,
                            const std::optional<view_box>& box, const std::vector<vec4<rational>>& points = {});

/// GAMES101's projection (seed 004) for near and far z coordinates n and f (f < n < 0), the focal
/// scale c = cot(fovy/2) and the aspect ratio: persp→ortho from the squeeze of every point and
/// the near/far conditions, top = −n/c (the seed's tan·zNear is negative), the translation, the
/// scale, and the corners checked. result equals games101_projection(n, f, c, aspect).
/// Throws games101_projection's errors.
explanation explain_games101(const rational& n, const rational& f, const rational& cot_half_fovy,
                             const rational& aspect, const std::vector<vec4<rational>>& points = {});

/// Normal matrix G = (M⁻¹)ᵀ from tᵀ n = 0 being preserved: det M, the cofactor matrix
/// cof(M) = adj(M)ᵀ, G = cof(M)/det M and the check Mᵀ G = I; each normal (x, y, z, 0) followed
/// by G and by M (which is wrong unless M is a rotation times a uniform scale). result equals
/// normal_matrix(M). Throws error "matrix.singular" when det M = 0.
explanation explain_normal_matrix(const mat4<rational>& M, const std::vector<vec4<rational>>& normals = {});

/// Change of basis from a child frame with axes X_c, Y_c, Z_c and origin O_c (parent
/// coordinates): the child → parent matrix with those columns, its inverse (the exact
/// parent → child matrix), whether the axes are orthonormal and then the transpose shortcut,
/// and each child point (a, b, c) followed to the parent. result equals child_to_parent(...).
/// Throws error "matrix.singular" when the axes are linearly dependent.
explanation explain_change_of_basis(const std::array<rational, 3>& x_axis, const std::array<rational, 3>& y_axis,
                                    const std::array<rational, 3>& z_axis, const std::array<rational, 3>& origin,
                                    const std::vector<vec4<rational>>& points = {});

/// Plain text: the title, numbered steps (sentence, indented arithmetic, aligned matrices) and the
/// result matrix in the same layout as the other commands print it.
std::string to_text(const explanation& e);

}  // namespace shadowproof
