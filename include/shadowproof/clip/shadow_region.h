#pragma once
/// The exact shadow region of casters on a finite receiver polygon.
///
/// Shadow region = the receiver points X that lie on a caster, or whose segment to the light
/// (for a directional light: the ray from X towards the light) meets a caster off the
/// receiver's plane. When P·L ≠ 0 the second condition alone says it (the segment leaves the
/// plane at X); when the light is on the receiver's plane or parallel to it (P·L = 0) the
/// segment stays in the plane and the region is the casters' footprint in it.
///
/// Computed exactly over rationals: every caster face is clipped in 3D to the part that can
/// cast (between the receiver plane and the light, inside the light's cone over a box around
/// the receiver), projected with the shadow matrix M = (P·L) I − L Pᵀ into a 2D chart of the
/// receiver plane, and the projections are combined exactly (docs/clipping.md). CGAL stays
/// inside src/clip/.
#include <array>
#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/core/plane.h"
#include "shadowproof/clip/scene.h"

namespace shadowproof {

/// A point of the receiver's 2D chart.
using point2 = std::array<rational, 2>;

/// The chart of the receiver plane P = (a, b, c, d): drop the coordinate k of the normal
/// component with the largest |n_k| and keep (u, v) = (x_{k+1}, x_{k+2}) (indices mod 3), so
/// the chart is exact and rational both ways and preserves orientation when n_k > 0.
/// Areas: A_3D = A_chart · |n| / |n_k|, so A_3D² = A_chart² · area_scale_squared with
/// area_scale_squared = (n·n) / n_k² (exact; A_3D itself may need a square root).
struct receiver_chart {
  plane<rational> receiver_plane;
  int dropped_axis = 2;             ///< k: 0 = x, 1 = y, 2 = z
  rational area_scale_squared{1};   ///< (n·n) / n_k²

  /// (x_{k+1}, x_{k+2}) of a 3D point (the point need not lie on P).
  point2 to_chart(const point3& X) const;
  /// The point of P above (u, v): x_k = −(d + n_{k+1} u + n_{k+2} v) / n_k.
  point3 lift(const point2& q) const;
  /// Name of chart axis 0 or 1 ("x", "y" or "z").
  std::string_view axis_name(int i) const;
};

/// A polygon with holes, given both in the chart and lifted to 3D (same vertex order).
/// Outer boundaries are counter-clockwise in the chart, holes clockwise.
struct region_polygon {
  std::vector<point2> outer;
  std::vector<std::vector<point2>> holes;
  std::vector<point3> outer_3d;
  std::vector<std::vector<point3>> holes_3d;
};

/// A zero-area piece of shadow: a segment (a ≠ b) or a point (a = b), in the chart and in 3D.
struct degenerate_piece {
  point2 a, b;
  point3 a_3d, b_3d;
  /// True for a point piece (a = b).
  bool is_point() const { return a == b; }
};

/// Named situations met while computing a region. They are results, never errors.
enum class shadow_case {
  empty,                       ///< the shadow region is empty (no area and no degenerate piece)
  light_parallel,              ///< directional light with P·L = 0: only caster parts in P shade
  light_on_plane,              ///< point light on P (P·L = 0): only caster parts in P shade
  caster_in_receiver_plane,    ///< a caster face lies in P (it shades its own footprint)
  caster_touches_receiver,     ///< a caster vertex lies on P, the rest on the light's side
  caster_crosses_receiver,     ///< a caster has vertices on both sides of P: only the light's side casts
  caster_behind_receiver,      ///< a caster lies entirely on the far side of P: it casts nothing
  caster_reaches_light_height, ///< point light: a caster reaches or passes the light's height
                               ///< (its shadow is unbounded and is clipped by the receiver)
  caster_contains_light,       ///< the light lies on a caster (the light itself never shades)
  caster_edge_on,              ///< a caster face's plane contains the light: zero-area shadow
  coincident_vertices,         ///< a face repeats a vertex consecutively (repeats are dropped)
  collinear_vertices,          ///< a face has three consecutive collinear vertices, or is a segment
  shadows_overlap,             ///< shadows of different casters overlap (union < sum of areas)
  shadow_outside_receiver,     ///< some projected shadow lies outside the receiver and is cut off
  shadow_touches_receiver_boundary, ///< a shadow meets the receiver only along a segment or at a point
  degenerate_shadow,           ///< the result has zero-area pieces (segments or points)
};

/// Stable snake_case name of a case, as printed in "cases".
std::string_view to_string(shadow_case c);

/// The exact shadow region.
struct shadow_region {
  receiver_chart chart;
  std::vector<region_polygon> polygons;     ///< the regular part (positive area)
  rational chart_area{0};                   ///< area of `polygons` in the chart
  rational area_squared{0};                 ///< (true 3D area)² = chart_area² · area_scale_squared
  std::vector<degenerate_piece> degenerate; ///< zero-area pieces not inside `polygons`
  std::vector<shadow_case> cases;           ///< sorted, without repeats

  // For pictures and reports.
  std::vector<point2> receiver_outer;              ///< the receiver in the chart (CCW)
  std::vector<std::vector<point2>> receiver_holes; ///< its holes in the chart (CW)
  /// Boundary loops of the union of the projected casters before the receiver clip (cut to
  /// `view_box`), and the zero-area projected pieces before the clip (segments and points).
  std::vector<std::vector<point2>> projected_loops;
  std::vector<std::array<point2, 2>> projected_degenerate;
  std::array<rational, 4> view_box{};  ///< (u_min, v_min, u_max, v_max): receiver box, enlarged
  vec4<rational> light{};              ///< the scene's light (x, y, z, w), for pictures

  // Statistics of the silhouette builder (zero from the union-of-pieces builder).
  std::size_t face_half_edges = 0;   ///< boundary edges of the faces that cast, before cancellation
  std::size_t silhouette_edges = 0;  ///< chart segments left after cancellation (the silhouette)

  /// True when case c was met.
  bool has(shadow_case c) const;
};

/// How compute_shadow_region combines the projected caster faces. Both give the identical
/// region (same polygons, same degenerate pieces, same cases); tests/test_clip.cpp checks it.
enum class clip_method {
  /// The silhouette builder (the default: faster than the reference on every bench scene, by
  /// orders of magnitude on meshes).
  automatic,
  /// Boundary chains: faces classified against the light by filtered predicates, half-edges
  /// shared by two faces cancelled without geometry, the remaining (silhouette) edges
  /// projected exactly and swept with the receiver's edges (every crossing computed once,
  /// winding numbers carried across the sweep line). O(n) before the sweep, which holds
  /// O(silhouette) edges; O((e + k) log e) for e edges with k crossings. Inputs the sweep
  /// declines (coordinates beyond 2^±400, long segments overlapping in bulk) go to the
  /// arrangement below.
  silhouette,
  /// The reference: every face split into convex pieces, each clipped and projected, one
  /// aggregate exact union of all pieces, then the intersection with the receiver.
  union_of_pieces,
  /// The silhouette builder with CGAL's Arrangement_2 in place of the sweep (its winding
  /// numbers assigned by walking across the arrangement's edges): a second reference.
  arrangement,
};

/// Options of compute_shadow_region.
struct clip_options {
  scene_limits limits{};
  /// Keep the projected casters before the receiver clip, for pictures.
  bool keep_projected = true;
  /// Detect shadows_overlap (one extra union per caster when there are several casters).
  bool detect_overlap = true;
  clip_method method = clip_method::automatic;
  /// Called now and then with the stage ("classifying faces", "arrangement", "done") and the
  /// fraction of faces processed, for progress bars; may be empty.
  std::function<void(std::string_view stage, double fraction)> progress;
};

/// Computes the exact shadow region of `s`. The receiver plane is derived from the receiver's
/// vertices. Throws error "scene.<what>" for malformed scenes, naming the element: fewer than
/// 3 distinct vertices, non-planar or self-intersecting receiver, hole outside the receiver,
/// non-planar or self-intersecting caster face, face index out of range, too many vertices.
/// Degenerate geometry is reported in `cases`, never thrown.
shadow_region compute_shadow_region(const scene& s, const clip_options& options = {});

/// Same with the receiver plane given as P (any non-zero multiple of the derived plane; the
/// receiver must lie in it, else error "scene.receiver_not_in_plane"). The region does not
/// depend on the scale or sign of P; the chart's dropped axis and area scale do not either.
shadow_region compute_shadow_region(const scene& s, const plane<rational>& P,
                                    const clip_options& options = {});

/// Where a chart point lies with respect to the regular part of a region.
enum class region_side { outside, boundary, inside };
/// Exact position of the chart point q relative to r.polygons (degenerate pieces ignored).
region_side locate(const shadow_region& r, const point2& q);

/// A small scene for `shadowproof demo`: an L-shaped receiver with a square hole, a point
/// light, a tilted square, a triangle crossing the receiver plane, a square reaching the
/// light's height and an edge-on triangle.
scene make_demo_scene();

/// The 3D area √area_squared as the nearest double (correctly rounded: MPFR brackets the
/// square root at growing precision until both ends round to the same double). A decimal
/// approximation for people; the exact value is area_squared.
double approximate_area(const shadow_region& r);

/// Human-readable report: cases, exact chart area, area² and its decimal approximation,
/// polygons (chart and 3D coordinates), degenerate pieces.
void print_region_report(std::ostream& out, const shadow_region& r);

/// The same pipeline done the way real-time code does it (seed 003): float shadow matrix,
/// every caster face projected whole (no 3D clipping), divided by w, then clipped against the
/// receiver with float Sutherland–Hodgman, in float. Compared with the exact region: the float
/// polygons are converted exactly to rationals and combined exactly, so the differences below
/// are exact statements about the float output.
struct float_comparison {
  std::size_t float_polygons = 0;        ///< non-empty clipped float polygons
  std::size_t non_finite_vertices = 0;   ///< NaN or ±Inf coordinates produced
  std::size_t invalid_polygons = 0;      ///< non-simple or degenerate float polygons (not combined)
  std::size_t vertices_outside_receiver = 0; ///< float shadow vertices strictly outside the receiver
  bool receiver_convex = true;           ///< Sutherland–Hodgman is only correct for a convex clip polygon
  rational float_area{0};                ///< chart area of the union of the valid float polygons
  rational exact_area{0};                ///< chart area of the exact region
  rational false_shadow_area{0};         ///< float \ exact: shadow where there is none
  rational missing_shadow_area{0};       ///< exact \ float: shadow the float pipeline lost
  rational outside_receiver_area{0};     ///< float \ receiver: shadow leaking off the receiver
  std::size_t missing_pieces = 0;        ///< connected pieces of exact \ float (lost slivers)
};

/// Runs the float pipeline on `s` and compares it with `exact` (computed for the same scene).
float_comparison compare_with_float(const scene& s, const shadow_region& exact);

/// Prints a float_comparison with exact rationals and their nearest doubles.
void print_float_comparison(std::ostream& out, const float_comparison& c);

}  // namespace shadowproof
