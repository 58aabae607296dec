#pragma once
/// Projection matrices in the common conventions (OpenGL, Direct3D/Vulkan/Metal, reverse-Z,
/// infinite far plane), the seed derivations' normalisation matrices and GAMES101's
/// construction, written once over the number type T (exact for rationals).
///
/// Eye space is right-handed and the camera looks down −z (as OpenGL): `n` and `f` are the
/// *distances* of the near and far planes, the visible depths are z_eye ∈ [−f, −n], except in
/// the GAMES101 functions, where n and f are the (negative) z coordinates themselves.
/// Column vectors: the clip-space image of X is M X; NDC = (x, y, z) / w.
/// Float instances evaluate the same formulas with one rounding per operation (no FMA under
/// -ffp-contract=off): exact only when every intermediate is representable (dyadic inputs of
/// moderate size); otherwise no error bound is claimed (the tests see a few ulps).
#include <array>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

#include "shadowproof/core/error.h"
#include "shadowproof/core/homogeneous.h"

namespace shadowproof {

// ===========================================================================================
// Depth conventions

/// Where the near and far planes land in NDC depth:
///   gl        : z_ndc ∈ [−1, 1], near → −1, far → 1   (OpenGL default)
///   d3d       : z_ndc ∈ [0, 1],  near → 0,  far → 1   (Direct3D, Vulkan, Metal)
///   reverse_z : z_ndc ∈ [0, 1],  near → 1,  far → 0   (d3d range, reversed for precision)
/// x_ndc and y_ndc ∈ [−1, 1] in every convention.
enum class depth_convention { gl, d3d, reverse_z };

/// "gl", "d3d" or "reverse-z" (the CLI spelling).
inline std::string_view to_string(depth_convention c) {
  switch (c) {
    case depth_convention::gl: return "gl";
    case depth_convention::d3d: return "d3d";
    case depth_convention::reverse_z: return "reverse-z";
  }
  return "?";
}

/// Parses "gl", "d3d" or "reverse-z" ("reverse_z" also accepted).
/// Throws error "project.convention" for anything else.
inline depth_convention parse_depth_convention(std::string_view text) {
  if (text == "gl") return depth_convention::gl;
  if (text == "d3d") return depth_convention::d3d;
  if (text == "reverse-z" || text == "reverse_z") return depth_convention::reverse_z;
  throw error(errc::project_convention,
              "unknown depth convention '" + std::string(text) + "': expected gl, d3d or reverse-z");
}

/// NDC depths of the near and far planes in a convention (see depth_convention).
template <class T>
struct depth_range {
  T near_ndc;
  T far_ndc;
};

/// gl: (−1, 1); d3d: (0, 1); reverse_z: (1, 0).
template <class T>
depth_range<T> ndc_depth_range(depth_convention c) {
  switch (c) {
    case depth_convention::gl: return {T(-1), T(1)};
    case depth_convention::d3d: return {T(0), T(1)};
    case depth_convention::reverse_z: return {T(1), T(0)};
  }
  return {T(0), T(1)};
}

namespace detail {

template <class T>
std::string number_text(const T& x) {
  if constexpr (std::is_same_v<T, rational>) {
    return to_string(x);
  } else {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
  }
}

// Throws "project.degenerate_volume" when two opposite planes of the view volume coincide:
// the matrix would divide by zero.
template <class T>
void require_distinct(const T& a, const T& b, const char* name_a, const char* name_b,
                      const char* extent) {
  if (a == b)
    throw error(errc::project_degenerate_volume, std::string(name_a) + " = " + name_b + " = " +
                                                 number_text(a) + ": the view volume has zero " +
                                                 extent + ", no projection maps it onto a cube");
}

template <class T>
void require_positive(const T& x, errc id, const char* name, const char* why) {
  if (!(x > T(0)))
    throw error(id, std::string(name) + " = " + number_text(x) + " must be > 0: " + why);
}

template <class T>
void check_box(const T& l, const T& r, const T& b, const T& t, const T& n, const T& f) {
  require_distinct(l, r, "left", "right", "width");
  require_distinct(b, t, "bottom", "top", "height");
  require_distinct(n, f, "near", "far", "depth");
}

// Rows 2 and 3 of a central projection looking down −z: z_clip = A z + B, w_clip = −z, with
// A, B solving (−A n + B)/n = z_near and (−A f + B)/f = z_far:
//   A = (n z_near − f z_far)/(f − n),  B = n f (z_near − z_far)/(f − n);
// as f → ∞: A = −z_far, B = n (z_near − z_far).
template <class T>
void set_perspective_depth_rows(mat4<T>& M, const T& n, const T& f, depth_convention c,
                                bool infinite_far) {
  const depth_range<T> z = ndc_depth_range<T>(c);
  require_positive(n, errc::project_near_not_positive, "near",
                   "the near plane of a perspective projection lies in front of the eye");
  if (infinite_far) {
    M(2, 2) = -z.far_ndc;
    M(2, 3) = n * (z.near_ndc - z.far_ndc);
  } else {
    require_positive(f, errc::project_far_not_positive, "far",
                     "the far plane of a perspective projection lies in front of the eye");
    require_distinct(n, f, "near", "far", "depth");
    M(2, 2) = (n * z.near_ndc - f * z.far_ndc) / (f - n);
    M(2, 3) = n * f * (z.near_ndc - z.far_ndc) / (f - n);
  }
  M(3, 2) = T(-1);
  M(3, 3) = T(0);
}

}  // namespace detail

// ===========================================================================================
// Orthographic (parallel) projections

/// Orthographic projection of the box [l, r] × [b, t] × [−f, −n] (n, f distances along −z)
/// onto the canonical volume of convention c:
///   [ 2/(r−l)  0        0   −(r+l)/(r−l) ]
///   [ 0        2/(t−b)  0   −(t+b)/(t−b) ]      A = (z_near − z_far)/(f − n)
///   [ 0        0        A   z_near + A n ]      (gl: A = −2/(f−n), A n + z_near = −(f+n)/(f−n))
///   [ 0        0        0   1            ]
/// Any n ≠ f is allowed (a parallel projection needs no positive near plane).
/// Throws "project.degenerate_volume" when l = r, b = t or n = f.
template <class T>
mat4<T> orthographic(const T& l, const T& r, const T& b, const T& t, const T& n, const T& f,
                     depth_convention c) {
  detail::check_box(l, r, b, t, n, f);
  const depth_range<T> z = ndc_depth_range<T>(c);
  const T a = (z.near_ndc - z.far_ndc) / (f - n);
  mat4<T> M = identity4<T>();
  M(0, 0) = T(2) / (r - l);
  M(0, 3) = -(r + l) / (r - l);
  M(1, 1) = T(2) / (t - b);
  M(1, 3) = -(t + b) / (t - b);
  M(2, 2) = a;
  M(2, 3) = z.near_ndc + a * n;
  return M;
}

/// Seed 002's normalisation S·T, built as the product of its two factors:
///   T(−(r+l)/2, −(t+b)/2, (f+n)/2) centres the box, S(2/(r−l), 2/(t−b), −2/(f−n)) scales it.
/// Equals orthographic(l, r, b, t, n, f, gl); its (2,3) entry is −(f+n)/(f−n). (The seed's
/// printed product shows +(f+n)/(f−n) there: a misprint, see tests/test_project.cpp.)
/// Throws "project.degenerate_volume" when l = r, b = t or n = f.
template <class T>
mat4<T> orthographic_normalization_seed002(const T& l, const T& r, const T& b, const T& t,
                                           const T& n, const T& f) {
  detail::check_box(l, r, b, t, n, f);
  const mat4<T> S = scaling<T>(T(2) / (r - l), T(2) / (t - b), T(-2) / (f - n));
  const mat4<T> Tr = translation<T>(-(r + l) / T(2), -(t + b) / T(2), (f + n) / T(2));
  return S * Tr;
}

/// M_orth = diag(1, 1, 0, 1): drops z (projection onto z = 0 along z).
template <class T>
mat4<T> orthographic_flatten() {
  mat4<T> M = identity4<T>();
  M(2, 2) = T(0);
  return M;
}

/// Oblique shear H(θ, φ) (seed 002, Angel's convention), given cot θ and cot φ exactly:
///   [ 1 0 −cot θ 0 ]
///   [ 0 1 −cot φ 0 ]
///   [ 0 0  1     0 ]
///   [ 0 0  0     1 ]
/// It maps the projector direction (cot θ, cot φ, 1, 0) to (0, 0, 1, 0) and fixes z = 0, so an
/// orthographic projection after H projects along (cot θ, cot φ, 1). (The seed's first slide
/// writes +cot θ, projecting along (−cot θ, −cot φ, 1): that is θ ↦ π − θ, not a second map.)
/// cot θ = cot φ = 0 gives the identity. Never degenerate (det H = 1).
template <class T>
mat4<T> oblique_shear(const T& cot_theta, const T& cot_phi) {
  mat4<T> H = identity4<T>();
  H(0, 2) = -cot_theta;
  H(1, 2) = -cot_phi;
  return H;
}

/// Oblique parallel projection onto z = 0, P = M_orth · H(θ, φ) (seed 002, unnormalised).
template <class T>
mat4<T> oblique_parallel_projection(const T& cot_theta, const T& cot_phi) {
  return orthographic_flatten<T>() * oblique_shear(cot_theta, cot_phi);
}

/// Seed 002's normalised oblique projection P = M_orth · S · T · H(θ, φ): the sheared box
/// {X : H X ∈ [l, r] × [b, t] × [−f, −n]} goes to x, y ∈ [−1, 1] and everything to z = 0.
/// Throws "project.degenerate_volume" when l = r, b = t or n = f.
template <class T>
mat4<T> oblique_normalized_projection_seed002(const T& l, const T& r, const T& b, const T& t,
                                              const T& n, const T& f, const T& cot_theta,
                                              const T& cot_phi) {
  return orthographic_flatten<T>() * orthographic_normalization_seed002(l, r, b, t, n, f) *
         oblique_shear(cot_theta, cot_phi);
}

/// Oblique projection keeping depth, orthographic(l, r, b, t, n, f, c) · H(θ, φ): maps the
/// parallelepiped {X : H X ∈ [l, r] × [b, t] × [−f, −n]} (corners (x + z cot θ, y + z cot φ, z)
/// for the box corners (x, y, z)) onto the canonical volume of c. Depth depends on z only.
/// Throws "project.degenerate_volume" when l = r, b = t or n = f.
template <class T>
mat4<T> oblique(const T& l, const T& r, const T& b, const T& t, const T& n, const T& f,
                const T& cot_theta, const T& cot_phi, depth_convention c) {
  return orthographic(l, r, b, t, n, f, c) * oblique_shear(cot_theta, cot_phi);
}

// ===========================================================================================
// Perspective (central) projections

/// Seed 002's perspective normalisation of the 45° frustum |x|, |y| ≤ −z, z ∈ [−f, −n]:
///   N(α, β) = [1 0 0 0; 0 1 0 0; 0 0 α β; 0 0 −1 0],  α = (n+f)/(n−f),  β = 2nf/(n−f).
/// Near plane → z_ndc = −1, far → 1 (OpenGL). Throws "project.degenerate_volume" when n = f.
template <class T>
mat4<T> perspective_normalization(const T& n, const T& f) {
  detail::require_distinct(n, f, "near", "far", "depth");
  mat4<T> N = identity4<T>();
  N(2, 2) = (n + f) / (n - f);
  N(2, 3) = T(2) * n * f / (n - f);
  N(3, 2) = T(-1);
  N(3, 3) = T(0);
  return N;
}

/// Perspective projection of the frustum with near-plane window [l, r] × [b, t] at distance n
/// and far plane at distance f (glFrustum's parameters), onto the canonical volume of c:
///   [ 2n/(r−l)  0         (r+l)/(r−l)  0 ]
///   [ 0         2n/(t−b)  (t+b)/(t−b)  0 ]     A = (n z_near − f z_far)/(f − n)
///   [ 0         0         A            B ]     B = n f (z_near − z_far)/(f − n)
///   [ 0         0         −1           0 ]
/// gl: A = −(f+n)/(f−n), B = −2fn/(f−n); d3d: A = −f/(f−n), B = −fn/(f−n);
/// reverse_z: A = n/(f−n), B = fn/(f−n). With infinite_far (f ignored) the f → ∞ limit:
/// A = −z_far, B = n (z_near − z_far), so directions (x, y, −1, 0) reach z_far.
/// Throws "project.degenerate_volume" (l = r, b = t, n = f), "project.near_not_positive"
/// (n ≤ 0), "project.far_not_positive" (f ≤ 0, finite far only).
template <class T>
mat4<T> frustum(const T& l, const T& r, const T& b, const T& t, const T& n, const T& f,
                depth_convention c, bool infinite_far = false) {
  detail::require_distinct(l, r, "left", "right", "width");
  detail::require_distinct(b, t, "bottom", "top", "height");
  mat4<T> M;
  detail::set_perspective_depth_rows(M, n, f, c, infinite_far);
  M(0, 0) = T(2) * n / (r - l);
  M(0, 2) = (r + l) / (r - l);
  M(1, 1) = T(2) * n / (t - b);
  M(1, 2) = (t + b) / (t - b);
  return M;
}

/// Symmetric perspective (gluPerspective) with the exact focal scale c = cot(fovy/2) and
/// aspect = width/height: frustum(−n·aspect/c, n·aspect/c, −n/c, n/c, n, f, conv), i.e.
///   [ c/aspect 0 0 0; 0 c 0 0; 0 0 A B; 0 0 −1 0 ] with A, B as in frustum.
/// Throws "project.focal_not_positive" (c ≤ 0), "project.aspect_not_positive" (aspect ≤ 0) and
/// the errors of frustum for n and f.
template <class T>
mat4<T> perspective(const T& cot_half_fovy, const T& aspect, const T& n, const T& f,
                    depth_convention c, bool infinite_far = false) {
  detail::require_positive(cot_half_fovy, errc::project_focal_not_positive, "cot(fovy/2)",
                           "the field of view must lie in (0°, 180°)");
  detail::require_positive(aspect, errc::project_aspect_not_positive, "aspect",
                           "width/height of the image");
  mat4<T> M;
  detail::set_perspective_depth_rows(M, n, f, c, infinite_far);
  M(0, 0) = cot_half_fovy / aspect;
  M(1, 1) = cot_half_fovy;
  return M;
}

// ===========================================================================================
// GAMES101 (seed 004): n and f are the z coordinates of the near and far planes, both
// negative (f < n < 0); NDC near → +1, far → −1, and w_clip = z_eye < 0 in front of the eye.

namespace detail {
template <class T>
void check_games101_planes(const T& n, const T& f) {
  if (!(n < T(0)))
    throw error(errc::project_games101_sign, "near = " + number_text(n) +
                                             " must be < 0: GAMES101 looks down −z and takes the "
                                             "z coordinates of the planes, not their distances");
  if (!(f < T(0)))
    throw error(errc::project_games101_sign, "far = " + number_text(f) +
                                             " must be < 0: GAMES101 looks down −z and takes the "
                                             "z coordinates of the planes, not their distances");
  require_distinct(n, f, "near", "far", "depth");
}
}  // namespace detail

/// GAMES101's "squish" of the frustum into the box, correct third row:
///   [ n 0 0 0; 0 n 0 0; 0 0 n+f −nf; 0 0 1 0 ]
/// Fixes every point of z = n and the centre (0, 0, f) of the far plane, and keeps z = f in
/// z = f. Throws "project.games101_sign" (n ≥ 0 or f ≥ 0), "project.degenerate_volume" (n = f).
template <class T>
mat4<T> games101_persp_to_ortho(const T& n, const T& f) {
  detail::check_games101_planes(n, f);
  return make_mat4<T>({n, T(0), T(0), T(0),  //
                       T(0), n, T(0), T(0),  //
                       T(0), T(0), T(n + f), T(-n * f),  //
                       T(0), T(0), T(1), T(0)});
}

/// Seed 004's matrix exactly as printed, third row (0, 0, nf, −nf): WRONG (it sends the near
/// plane z = n to z = (n² f − n f)/n = nf − f ≠ n in general). Kept only to exhibit the misprint;
/// do not use it. Same preconditions as games101_persp_to_ortho.
template <class T>
mat4<T> games101_persp_to_ortho_as_printed(const T& n, const T& f) {
  detail::check_games101_planes(n, f);
  return make_mat4<T>({n, T(0), T(0), T(0),  //
                       T(0), n, T(0), T(0),  //
                       T(0), T(0), T(n * f), T(-n * f),  //
                       T(0), T(0), T(1), T(0)});
}

/// GAMES101 projection = ortho · translate · persp with top = −n/c (c = cot(fovy/2)),
/// bottom = −top, right = top·aspect, left = −right:
///   translate = T(−(r+l)/2, −(t+b)/2, −(n+f)/2), ortho = S(2/(r−l), 2/(t−b), 2/(n−f)).
/// NDC: x, y ∈ [−1, 1], near z = n → +1, far z = f → −1.
/// Throws as games101_persp_to_ortho, plus "project.focal_not_positive" / "project.aspect_not_positive".
template <class T>
mat4<T> games101_projection(const T& n, const T& f, const T& cot_half_fovy, const T& aspect) {
  detail::check_games101_planes(n, f);
  detail::require_positive(cot_half_fovy, errc::project_focal_not_positive, "cot(fovy/2)",
                           "the field of view must lie in (0°, 180°)");
  detail::require_positive(aspect, errc::project_aspect_not_positive, "aspect",
                           "width/height of the image");
  const T top = -n / cot_half_fovy, bottom = -top;
  const T right = top * aspect, left = -right;
  const mat4<T> translate =
      translation<T>(-(right + left) / T(2), -(top + bottom) / T(2), -(n + f) / T(2));
  const mat4<T> ortho = scaling<T>(T(2) / (right - left), T(2) / (top - bottom), T(2) / (n - f));
  return ortho * translate * games101_persp_to_ortho(n, f);
}

// ===========================================================================================
// Depth along the view axis and the canonical volume

/// The depth part of a projection whose depth depends on z_eye alone:
///   z_ndc(z) = (a z + b) / (c z + d),  (a, b) = (M₂₂, M₂₃), (c, d) = (M₃₂, M₃₃).
/// Its derivative is (a d − b c)/(c z + d)²: on each side of the pole c z + d = 0 it is strictly
/// monotonic when a d − b c ≠ 0 (increasing for > 0) and constant when a d − b c = 0.
template <class T>
struct depth_function {
  T a, b, c, d;

  /// (a z + b)/(c z + d); precondition c z + d ≠ 0.
  T operator()(const T& z) const { return (a * z + b) / (c * z + d); }
  /// a d − b c: the numerator of the derivative, whose sign is the direction of monotonicity.
  T determinant() const { return a * d - b * c; }
};

/// The depth function of M, or nothing when z_ndc also depends on x or y (M₂₀, M₂₁, M₃₀ or
/// M₃₁ ≠ 0).
template <class T>
std::optional<depth_function<T>> depth_function_of(const mat4<T>& M) {
  if (M(2, 0) != T(0) || M(2, 1) != T(0) || M(3, 0) != T(0) || M(3, 1) != T(0)) return std::nullopt;
  return depth_function<T>{M(2, 2), M(2, 3), M(3, 2), M(3, 3)};
}

/// The canonical clip volume of convention c, tested in homogeneous clip coordinates without
/// division: w > 0, −w ≤ x ≤ w, −w ≤ y ≤ w and −w ≤ z ≤ w (gl) or 0 ≤ z ≤ w (d3d, reverse_z).
/// Requiring w > 0 rejects points behind the eye, which the division alone would fold back.
template <class T>
bool in_clip_volume(const vec4<T>& v, depth_convention c) {
  const T& w = v[3];
  if (!(w > T(0))) return false;
  const T minus_w = -w;
  if (v[0] < minus_w || v[0] > w || v[1] < minus_w || v[1] > w || v[2] > w) return false;
  return c == depth_convention::gl ? !(v[2] < minus_w) : !(v[2] < T(0));
}

/// (x/w, y/w, z/w), or nothing when w = 0 (a point at infinity).
template <class T>
std::optional<std::array<T, 3>> ndc_of(const vec4<T>& v) {
  if (v[3] == T(0)) return std::nullopt;
  return std::array<T, 3>{T(v[0] / v[3]), T(v[1] / v[3]), T(v[2] / v[3])};
}

}  // namespace shadowproof
