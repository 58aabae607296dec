#pragma once
// Helpers shared by the explanations (private to src/explain/): exact text of numbers, vectors
// and matrices, step builders, and the geometry the figures need (plane patches, views of
// volumes), all exact.
#include <array>
#include <string>
#include <vector>

#include "shadowproof/core/homogeneous.h"
#include "shadowproof/explain/explain.h"

namespace shadowproof::detail {

std::string str(const rational& q);
/// A factor in a product: negative numbers and fractions get brackets, "(-2)·(1/3)".
std::string factor(const rational& q);
std::string list_text(const std::vector<rational>& v);
std::string vec_text(const vec4<rational>& v);
std::string point_text(const point3& p);
std::vector<rational> xyz(const vec4<rational>& v);
point3 xyz3(const vec4<rational>& v);
/// "a0·b0 + a1·b1 + ... = value" over the first `count` coordinates.
std::string dot_text(const vec4<rational>& a, const vec4<rational>& b, std::size_t count);
/// Rows of an aligned matrix, the layout `shadowproof shadow` uses.
std::vector<std::string> matrix_lines(const std::vector<std::vector<rational>>& rows);
std::vector<std::string> matrix_lines(const mat4<rational>& m);
explanation_step text_step(std::string why, std::vector<std::string> lines = {});
explanation_step matrix_step(std::string why, const mat4<rational>& m, std::vector<std::string> lines = {});
std::string holds(bool ok);
/// (x/w, y/w, z/w) of a homogeneous vector with w ≠ 0.
point3 affine_point(const vec4<rational>& v);
/// "M (x, y, z, 1) = (...), NDC (...)" for a projection; "w = 0" when the image is at infinity.
std::string projected_line(const std::string& name, const mat4<rational>& M, const vec4<rational>& X);

// --- figure geometry -------------------------------------------------------------------------

point3 add(const point3& a, const point3& b);
point3 sub(const point3& a, const point3& b);
point3 scale(const rational& s, const point3& a);
rational dot3(const point3& a, const point3& b);
point3 cross(const point3& a, const point3& b);
/// The largest absolute coordinate (the ∞-norm), a rational stand-in for a length.
rational max_norm(const point3& a);
/// `a` scaled to ∞-norm `length` (a ≠ 0).
point3 with_length(const point3& a, const rational& length);

/// A patch of the plane n·X + d = 0 (n ≠ 0) around `centre` (on the plane) that contains the
/// orthogonal projections of `keep` with a margin: the four corners centre ± α u ± β v for the
/// rational orthogonal in-plane directions u = n × e, v = n × u.
std::vector<point3> plane_patch(const point3& n, const rational& d, const point3& centre, const std::vector<point3>& keep);
/// The point of n·X + d = 0 closest to p.
point3 foot_on_plane(const point3& n, const rational& d, const point3& p);

/// The 8 corners of the box [x0, x1] × [y0, y1] × [z0, z1] in the order of figure_panel::hexahedron.
std::array<point3, 8> box_corners(const rational& x0, const rational& x1, const rational& y0, const rational& y1,
                                  const rational& z0, const rational& z1);
/// The panel of the canonical volume of convention c with the NDC images of `points`.
figure_panel canonical_panel(depth_convention c, const mat4<rational>& M, const std::vector<vec4<rational>>& points,
                             const std::string& title);
/// The NDC depth range [z_min, z_max] of convention c.
std::array<rational, 2> ndc_depth_span(depth_convention c);

}  // namespace shadowproof::detail
