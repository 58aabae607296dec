// Entry points of the clip subsystem: the chart, case names, compute_shadow_region (which
// picks a region builder) and point location in a region.
#include "shadowproof/clip/shadow_region.h"

#include <algorithm>

#include "builders.h"
#include "polygon_set.h"
#include "region_setup.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/vec3.h"

namespace shadowproof {

namespace {

shadow_region build(const scene& s, const plane<rational>& P, const clip_options& options) {
  switch (options.method) {
    case clip_method::union_of_pieces: return detail::union_of_pieces_region(s, P, options);
    case clip_method::automatic:
    case clip_method::silhouette:
    case clip_method::arrangement: break;
  }
  return detail::silhouette_region(s, P, options);
}

}  // namespace

// ===========================================================================================
// receiver_chart

point2 receiver_chart::to_chart(const point3& X) const {
  return {X[(dropped_axis + 1) % 3], X[(dropped_axis + 2) % 3]};
}

point3 receiver_chart::lift(const point2& q) const {
  const int k = dropped_axis, i = (k + 1) % 3, j = (k + 2) % 3;
  point3 X;
  X[i] = q[0];
  X[j] = q[1];
  const auto& p = receiver_plane.p;
  // Zero coefficients skipped: receivers are often axis-aligned.
  rational w = p[3];
  if (sgn(p[i]) != 0) w += p[i] * q[0];
  if (sgn(p[j]) != 0) w += p[j] * q[1];
  X[k] = -w / p[k];
  return X;
}

std::string_view receiver_chart::axis_name(int i) const {
  static constexpr std::string_view names[3] = {"x", "y", "z"};
  return names[(dropped_axis + 1 + i) % 3];
}

std::string_view to_string(shadow_case c) {
  switch (c) {
    case shadow_case::empty: return "empty";
    case shadow_case::light_parallel: return "light_parallel";
    case shadow_case::light_on_plane: return "light_on_plane";
    case shadow_case::caster_in_receiver_plane: return "caster_in_receiver_plane";
    case shadow_case::caster_touches_receiver: return "caster_touches_receiver";
    case shadow_case::caster_crosses_receiver: return "caster_crosses_receiver";
    case shadow_case::caster_behind_receiver: return "caster_behind_receiver";
    case shadow_case::caster_reaches_light_height: return "caster_reaches_light_height";
    case shadow_case::caster_contains_light: return "caster_contains_light";
    case shadow_case::caster_edge_on: return "caster_edge_on";
    case shadow_case::coincident_vertices: return "coincident_vertices";
    case shadow_case::collinear_vertices: return "collinear_vertices";
    case shadow_case::shadows_overlap: return "shadows_overlap";
    case shadow_case::shadow_outside_receiver: return "shadow_outside_receiver";
    case shadow_case::shadow_touches_receiver_boundary: return "shadow_touches_receiver_boundary";
    case shadow_case::degenerate_shadow: return "degenerate_shadow";
  }
  return "unknown";
}

bool shadow_region::has(shadow_case c) const { return std::find(cases.begin(), cases.end(), c) != cases.end(); }

shadow_region compute_shadow_region(const scene& s, const clip_options& options) {
  if (is_zero(s.light_source.l))
    throw zero_light_error();
  return build(s, detail::derived_plane(s), options);
}

shadow_region compute_shadow_region(const scene& s, const plane<rational>& P, const clip_options& options) {
  if (sgn(P.a()) == 0 && sgn(P.b()) == 0 && sgn(P.c()) == 0)
    throw zero_normal_error();
  if (is_zero(s.light_source.l))
    throw zero_light_error();
  // The given plane must be a multiple of the receiver's own plane.
  for (std::size_t i = 0; i < s.receiver.outer.vertices.size(); ++i) {
    const auto& v = s.receiver.outer.vertices[i];
    if (sgn(plane_value(P.p, v)) != 0)
      throw error(errc::scene_receiver_not_in_plane, "/receiver/polygon/" + std::to_string(i) + " is not in the given plane");
  }
  return build(s, P, options);
}

region_side locate(const shadow_region& r, const point2& q) {
  if (r.polygons.empty()) return region_side::outside;
  std::vector<detail::ring_with_holes> polygons;
  for (const auto& p : r.polygons) polygons.push_back({p.outer, p.holes});
  return detail::polygon_set(polygons).side(q);
}

}  // namespace shadowproof
