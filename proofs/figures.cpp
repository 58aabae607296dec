// The document's figures: each derivation's example, drawn by the library's explain code from
// exact numbers. The caption is the explanation's own, so it states the numbers drawn.
#include "figures.h"

#include "shadowproof/explain/explain.h"

namespace shadowproof::proofs {

namespace {

using q = rational;

vec4<rational> pt(const q& x, const q& y, const q& z) { return make_point<rational>(x, y, z); }

std::optional<explanation> example(const std::string& slug) {
  if (slug == "shadow_matrix")
    return explain_shadow(make_plane<q>(0, 1, 0, 0), make_light<q>(2, 5, 1, 1), {pt(1, 2, 3)});
  if (slug == "point_classes")
    return explain_shadow(make_plane<q>(0, 1, 0, 0), make_light<q>(0, 4, 0, 1),
                          {pt(2, 2, 0), pt(-1, -2, 2), pt(1, 6, -2), pt(2, 4, -1)});
  if (slug == "seed000_directional")
    return explain_shadow(make_plane<q>(1, 2, -3, q(1, 2)), make_light<q>(q(-1, 3), 4, 2, 0), {pt(1, 2, -1)});
  if (slug == "seed001_ground_plane")
    return explain_shadow(make_plane<q>(0, 1, 0, -1), make_light<q>(1, 2, 1, 0), {pt(1, 3, 1), pt(1, -1, 1)});
  if (slug == "seed002_point_light_ground")
    return explain_shadow(make_plane<q>(0, 1, 0, 0), make_light<q>(1, 4, 2, 1), {pt(3, 2, 1)});
  if (slug == "seed003_shadow_polygon")
    return explain_shadow(make_plane<q>(1, 1, 1, -1), make_light<q>(2, 3, 1, 1), {pt(1, 2, 1)});
  if (slug == "reflection") return explain_reflection(make_plane<q>(1, 2, 2, -3), {pt(3, 1, 2)});
  if (slug == "seed003_reflection_frames") return explain_reflection_by_frames({2, -1, -1, 0}, 3, {pt(1, 2, 3)});
  if (slug == "orthographic") return explain_orthographic(-2, 2, -1, 1, 1, 5, depth_convention::gl, {pt(1, q(1, 2), -4)});
  if (slug == "oblique") return explain_oblique(1, 0, cot_sign::plus, std::nullopt, {});
  if (slug == "perspective_normalisation") return explain_perspective_normalization(1, 3, {pt(q(1, 2), 0, -2)});
  if (slug == "frustum")
    return explain_frustum(-1, 1, q(-1, 2), q(1, 2), 1, 4, depth_convention::d3d, false, {pt(1, q(1, 2), -2)});
  if (slug == "games101_perspective") return explain_games101(-1, -4, 1, q(4, 3), {pt(q(1, 2), q(1, 4), -2)});
  if (slug == "normal_matrix")
    return explain_normal_matrix(scaling<rational>(2, 1, 1), {make_vec4<rational>(1, 1, 0, 0)});
  if (slug == "change_of_basis") return explain_change_of_basis({0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {2, 1, 0}, {pt(1, 1, 0)});
  return std::nullopt;
}

}  // namespace

std::optional<derivation_figure> figure_for(const std::string& slug) {
  const auto e = example(slug);
  if (!e || e->picture.empty()) return std::nullopt;
  return derivation_figure{to_svg(e->picture), e->picture.caption};
}

}  // namespace shadowproof::proofs
