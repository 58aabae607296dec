#pragma once
// What both region builders share: the validated receiver in its chart, the half-spaces that
// keep the part of a caster that can cast, the exact projection into the chart, the validation
// of one caster face and the classification of a projected piece.
#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "shadowproof/clip/shadow_region.h"

namespace shadowproof::detail {

/// The named cases met so far.
using case_set = std::set<shadow_case>;

/// "/casters/2/polygon" for a polygon caster, "/casters/2/mesh/faces/7" for a mesh face.
std::string face_name(const caster& c, std::size_t f);

/// Throws scene.too_large / scene.bad_index for a scene beyond `limits` or with a face index
/// out of range, before any geometry is computed.
void validate_sizes(const scene& s, const scene_limits& limits);

/// The plane through the receiver's outer ring (Newell-free: the first non-collinear triple);
/// throws scene.empty_polygon for fewer than 3 distinct or collinear vertices.
plane<rational> derived_plane(const scene& s);

/// The receiver, the light and the clip half-spaces of one computation.
struct clip_setup {
  const scene* sc = nullptr;
  plane<rational> P;
  receiver_chart chart;
  std::vector<point2> receiver_outer;              ///< counter-clockwise
  std::vector<std::vector<point2>> receiver_holes; ///< clockwise
  std::array<rational, 4> view_box{};
  rational s{0};                                   ///< P·L
  /// h·(V, 1) ≥ 0 for every h keeps the part that can cast: f ≥ 0 and the light's cone over
  /// the view box when P·L ≠ 0; P·V ≥ 0 and −P·V ≥ 0 (the receiver plane itself) when P·L = 0.
  std::vector<vec4<rational>> halfspaces;
  /// f(V): 0 on P, 1 at a point light's height, growing towards the light (P·L ≠ 0 only).
  vec4<rational> height;
  /// +1 or −1: the sign of P·V on the light's side (+1 when P·L = 0, by convention).
  int light_side = 1;

  bool grazing() const { return sgn(s) == 0; }
  bool point_light() const { return sc->light_source.is_point(); }
  /// The chart point of the shadow image M V = (P·L) V − (P·V) L (P·L ≠ 0, V not at the
  /// light's height), or V's own chart point when P·L = 0 (V in P).
  point2 project(const point3& V) const;
  /// Sutherland–Hodgman against every half-space, exactly: the part of the convex polygon
  /// `poly` that casts (empty, a point, a segment or a convex polygon).
  std::vector<point3> clip(std::vector<point3> poly) const;
  /// True when V is a point light's position (f(V) = 1); only the cone's apex in the clip.
  bool at_light(const point3& V) const;
  /// A region with this setup's chart, light, receiver and view box and nothing in it yet:
  /// what both region builders start from.
  shadow_region empty_region() const;
};

/// Validates the receiver (planar, simple rings, holes inside) in the chart of P and builds
/// the clip half-spaces; notes light_parallel / light_on_plane.
clip_setup make_clip_setup(const scene& s, const plane<rational>& P, case_set& cases);

/// Sutherland–Hodgman against one half-space h(X) ≥ 0, exactly.
std::vector<point3> clip_to_halfspace(const std::vector<point3>& poly, const vec4<rational>& h);

/// One caster face after validation.
struct face_geometry {
  /// Vertices with repeats and straight vertices dropped, counter-clockwise in `chart`; for
  /// a collinear face the two extreme vertices {lo, hi}.
  std::vector<point3> v;
  std::vector<point2> chart;  ///< v in the face's own chart (drop its largest normal axis)
  bool collinear = false;     ///< every vertex on one line (a segment or a point)
  bool edge_on = false;       ///< the face's plane contains the light (P·L ≠ 0 only)
};

/// Validates face f of caster c exactly and notes coincident_vertices, collinear_vertices and
/// caster_in_receiver_plane. Throws scene.empty_polygon, scene.caster_not_planar or
/// scene.self_intersecting (also for a face folding back on itself).
face_geometry validate_face(const clip_setup& setup, const caster& c, std::size_t f, case_set& cases);

/// Which sides of P the vertices used by a caster's faces lie on, for the caster cases.
struct caster_sides {
  bool front = false, back = false, on = false, high = false;
  /// Adds vertex V (exact).
  void add(const clip_setup& setup, const point3& V);
  /// Notes caster_crosses_receiver, caster_behind_receiver, caster_touches_receiver and
  /// caster_reaches_light_height (P·L ≠ 0 only).
  void note(const clip_setup& setup, case_set& cases) const;
};

/// A projected piece: a counter-clockwise convex polygon with area, or a zero-area segment
/// [lo, hi] (lo = hi for a point).
struct projected_piece {
  std::vector<point2> polygon;             ///< empty for a zero-area piece
  std::array<point2, 2> segment{};
  bool empty = true;                       ///< nothing casts
};

/// Clips the convex piece `poly` (3D, in order), projects what casts and classifies it.
/// Notes caster_edge_on (when `edge_on` and something casts) and caster_contains_light.
projected_piece cast_convex_piece(const clip_setup& setup, std::vector<point3> poly, bool edge_on, case_set& cases);

/// The zero-area and polygon pieces of one validated face (its convex pieces clipped and
/// projected one by one).
void cast_face(const clip_setup& setup, const face_geometry& g, case_set& cases,
               std::vector<std::vector<point2>>& polygons, std::vector<std::array<point2, 2>>& degenerate);

}  // namespace shadowproof::detail
