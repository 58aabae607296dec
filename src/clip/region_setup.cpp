// The receiver, the clip half-spaces, face validation and piece classification shared by
// both region builders (region_setup.h).
#include "region_setup.h"

#include <algorithm>

#include "polygon2.h"
#include "polygon_set.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/vec3.h"

namespace shadowproof::detail {

std::string face_name(const caster& c, std::size_t f) {
  return c.is_polygon ? c.name : c.name + "/faces/" + std::to_string(f);
}

void validate_sizes(const scene& s, const scene_limits& lim) {
  std::size_t nv = 0, nf = 0;
  for (const auto& c : s.casters) {
    nv += c.vertices.size();
    nf += c.faces.size();
    for (std::size_t f = 0; f < c.faces.size(); ++f) {
      if (c.faces[f].size() > lim.max_face_vertices)
        throw error(errc::scene_too_large, face_name(c, f) + " has " + std::to_string(c.faces[f].size()) +
                                               " vertices; at most " + std::to_string(lim.max_face_vertices) +
                                               " (raise it with --max-face-vertices) per face");
      for (std::size_t k = 0; k < c.faces[f].size(); ++k)
        if (c.faces[f][k] >= c.vertices.size())
          throw error(errc::scene_bad_index, face_name(c, f) + (c.is_polygon ? "" : "/" + std::to_string(k)) +
                                                 ": vertex index " + std::to_string(c.faces[f][k]) +
                                                 " is out of range (the caster has " +
                                                 std::to_string(c.vertices.size()) + " vertices)");
    }
  }
  if (nv > lim.max_vertices)
    throw error(errc::scene_too_large, "the casters have " + std::to_string(nv) + " vertices; at most " +
                                           std::to_string(lim.max_vertices) + " (raise it with --max-vertices)");
  if (nf > lim.max_faces)
    throw error(errc::scene_too_large, "the casters have " + std::to_string(nf) + " faces; at most " +
                                           std::to_string(lim.max_faces) + " (raise it with --max-faces)");
  const auto check_ring = [&](const polygon3& p, const std::string& name) {
    if (p.vertices.size() > lim.max_face_vertices)
      throw error(errc::scene_too_large, name + " has " + std::to_string(p.vertices.size()) + " vertices; at most " +
                                             std::to_string(lim.max_face_vertices) + " (raise it with --max-face-vertices)");
  };
  check_ring(s.receiver.outer, "/receiver/polygon");
  for (std::size_t h = 0; h < s.receiver.holes.size(); ++h)
    check_ring(s.receiver.holes[h], "/receiver/holes/" + std::to_string(h));
}

plane<rational> derived_plane(const scene& s) {
  std::vector<point3> v = s.receiver.outer.vertices;
  drop_repeats(v);
  if (v.size() < 3) throw error(errc::scene_empty_polygon, "/receiver/polygon needs at least 3 distinct vertices");
  const point3 n = plane_normal(v);
  if (is_zero(n))
    throw error(errc::scene_empty_polygon, "/receiver/polygon has zero area (its vertices are collinear)");
  return plane<rational>{make_vec4<rational>(n[0], n[1], n[2], -dot(n, v[0]))};
}

namespace {

[[noreturn]] void not_simple(const std::string& name, bool folds_back) {
  throw error(errc::scene_self_intersecting,
              name + (folds_back ? " is not a simple polygon (its edges fold back on each other)"
                                 : " is not a simple polygon (its edges cross or touch)"));
}

// Validates one receiver ring and returns it in the chart, counter-clockwise.
std::vector<point2> chart_ring(const polygon3& ring, const std::string& name, const plane<rational>& P, int k) {
  std::vector<point3> v = ring.vertices;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (sgn(plane_value(P.p, v[i])) != 0)
      throw error(errc::scene_receiver_not_planar, name + "/" + std::to_string(i) + " is not in the plane of the receiver");
  drop_repeats(v);
  if (v.size() < 3) throw error(errc::scene_empty_polygon, name + " needs at least 3 distinct vertices");
  std::vector<point2> c;
  for (const auto& p : v) c.push_back(drop_axis(p, k));
  bool collinear = true;
  for (std::size_t i = 2; i < c.size() && collinear; ++i) collinear = sgn(orient2(c[0], c[1], c[i])) == 0;
  if (collinear) throw error(errc::scene_empty_polygon, name + " has zero area (its vertices are collinear)");
  if (fold_back_vertex(c)) not_simple(name, true);
  drop_straight(c, v);
  if (!is_simple(c)) not_simple(name, false);
  if (sgn(signed_area(c)) < 0) std::reverse(c.begin(), c.end());
  return c;
}

}  // namespace

point2 clip_setup::project(const point3& V) const {
  if (grazing()) return chart.to_chart(V);
  // Shadow matrix image M V = (P·L) V − (P·V) L, then the chart of its affine part.
  const auto& L = sc->light_source.l;
  const rational t = plane_value(P.p, V);
  const int k = chart.dropped_axis;
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const rational w = s - t * L[3];
  return {(s * V[i] - t * L[i]) / w, (s * V[j] - t * L[j]) / w};
}

bool clip_setup::at_light(const point3& V) const {
  return !grazing() && point_light() && plane_value(height, V) == 1;
}

shadow_region clip_setup::empty_region() const {
  shadow_region r;
  r.chart = chart;
  r.light = sc->light_source.l;
  r.receiver_outer = receiver_outer;
  r.receiver_holes = receiver_holes;
  r.view_box = view_box;
  return r;
}

std::vector<point3> clip_to_halfspace(const std::vector<point3>& poly, const vec4<rational>& h) {
  std::vector<point3> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const point3& a = poly[i];
    const point3& b = poly[(i + 1) % poly.size()];
    const rational ha = plane_value(h, a), hb = plane_value(h, b);
    if (sgn(ha) >= 0) out.push_back(a);
    if (sgn(ha) * sgn(hb) < 0) out.push_back(lerp(a, b, rational(ha / (ha - hb))));
  }
  return out;
}

std::vector<point3> clip_setup::clip(std::vector<point3> poly) const {
  for (const auto& h : halfspaces) {
    poly = clip_to_halfspace(poly, h);
    if (poly.empty()) break;
  }
  return poly;
}

clip_setup make_clip_setup(const scene& sc, const plane<rational>& P, case_set& cases) {
  clip_setup c;
  c.sc = &sc;
  c.P = P;
  const point3 n{P.a(), P.b(), P.c()};
  const int k = largest_axis(n);
  c.chart.receiver_plane = P;
  c.chart.dropped_axis = k;
  c.chart.area_scale_squared = dot(n, n) / (n[k] * n[k]);

  c.receiver_outer = chart_ring(sc.receiver.outer, "/receiver/polygon", P, k);
  if (!sc.receiver.holes.empty()) {  // (without holes the receiver has area: no set operation)
    polygon_set receiver(c.receiver_outer);
    for (std::size_t h = 0; h < sc.receiver.holes.size(); ++h) {
      const std::string name = "/receiver/holes/" + std::to_string(h);
      auto hole = chart_ring(sc.receiver.holes[h], name, P, k);
      polygon_set outside(hole);
      outside.subtract(polygon_set(c.receiver_outer));
      if (!outside.empty()) throw error(errc::scene_hole_outside_receiver, name + " is not inside /receiver/polygon");
      receiver.subtract(polygon_set(hole));
      std::reverse(hole.begin(), hole.end());
      c.receiver_holes.push_back(std::move(hole));
    }
    if (receiver.empty()) throw error(errc::scene_empty_polygon, "the holes cover the whole receiver");
  }

  // View box: the receiver's bounding box enlarged by a quarter of its larger side, so the
  // box's own edges never touch the receiver (they would fake boundary contacts).
  rational umin = c.receiver_outer[0][0], umax = umin, vmin = c.receiver_outer[0][1], vmax = vmin;
  for (const auto& p : c.receiver_outer) {
    umin = std::min(umin, p[0]);
    umax = std::max(umax, p[0]);
    vmin = std::min(vmin, p[1]);
    vmax = std::max(vmax, p[1]);
  }
  const rational m = std::max(umax - umin, vmax - vmin) / 4;
  c.view_box = {umin - m, vmin - m, umax + m, vmax + m};

  const auto& L = sc.light_source.l;
  c.s = dot(P.p, L);
  if (c.grazing()) {
    cases.insert(sc.light_source.is_directional() ? shadow_case::light_parallel : shadow_case::light_on_plane);
    // Only the part of a caster lying in P shades (its own footprint).
    c.halfspaces = {P.p, rational(-1) * P.p};
    return c;
  }
  c.light_side = sc.light_source.is_directional() ? sgn(c.s) : sgn(c.s) * sgn(L[3]);
  // f(V) = w (P·V) / s for a point light (0 on P, 1 at the light's height) and (P·V) / s for
  // a directional light (grows towards the light).
  const rational scale = sc.light_source.is_directional() ? rational(1) / c.s : L[3] / c.s;
  c.height = scale * P.p;
  c.halfspaces.push_back(c.height);  // f ≥ 0: the light's side of P, P itself included
  // Cone of the light over the view box: for each box edge (A, B) the plane through A, B and
  // L, i.e. Π·V = det[A; B; L; V], oriented to be positive at the box centre.
  const auto& b = c.view_box;
  const std::array<point2, 4> box{{{b[0], b[1]}, {b[2], b[1]}, {b[2], b[3]}, {b[0], b[3]}}};
  const point3 centre = c.chart.lift({(b[0] + b[2]) / 2, (b[1] + b[3]) / 2});
  for (std::size_t e = 0; e < 4; ++e) {
    const point3 A = c.chart.lift(box[e]);
    const point3 B = c.chart.lift(box[(e + 1) % 4]);
    vec4<rational> pi;
    for (std::size_t col = 0; col < 4; ++col) {
      mat4<rational> m4;
      for (std::size_t j = 0; j < 3; ++j) {
        m4(0, j) = A[j];
        m4(1, j) = B[j];
      }
      m4(0, 3) = 1;
      m4(1, 3) = 1;
      for (std::size_t j = 0; j < 4; ++j) m4(2, j) = L[j];
      m4(3, col) = 1;
      pi[col] = determinant(m4);
    }
    if (sgn(plane_value(pi, centre)) < 0) pi = rational(-1) * pi;
    c.halfspaces.push_back(pi);
  }
  return c;
}

face_geometry validate_face(const clip_setup& setup, const caster& c, std::size_t f, case_set& cases) {
  face_geometry g;
  const std::string name = face_name(c, f);
  std::vector<point3> v;
  v.reserve(c.faces[f].size());
  for (auto i : c.faces[f]) v.push_back(c.vertices[i]);
  if (v.empty()) throw error(errc::scene_empty_polygon, name + " has no vertices");
  const std::vector<point3> given = v;
  if (drop_repeats(v)) cases.insert(shadow_case::coincident_vertices);
  const point3 n = plane_normal(v);
  if (v.size() < 3 || is_zero(n)) {
    // Collinear (or a single point): it casts as the segment between its extreme vertices.
    if (v.size() >= 3) cases.insert(shadow_case::collinear_vertices);
    point3 lo = v[0], hi = v[0];
    for (const auto& p : v) {
      lo = std::min(lo, p);
      hi = std::max(hi, p);
    }
    g.v = {lo, hi};
    g.collinear = true;
    return g;
  }
  const rational dn = -dot(n, v[0]);
  for (std::size_t i = 0; i < given.size(); ++i)
    if (sgn(dot(n, given[i]) + dn) != 0)
      throw error(errc::scene_caster_not_planar,
                  name + ": vertex " + std::to_string(c.faces[f][i]) + " is not in the plane of the face's other vertices");
  bool in_plane = true;
  for (const auto& p : v) in_plane = in_plane && sgn(plane_value(setup.P.p, p)) == 0;
  if (in_plane) cases.insert(shadow_case::caster_in_receiver_plane);
  const int k = largest_axis(n);
  std::vector<point2> chart;
  chart.reserve(v.size());
  for (const auto& p : v) chart.push_back(drop_axis(p, k));
  if (fold_back_vertex(chart))
    throw error(errc::scene_self_intersecting,
                name + " is not a simple polygon (its edges fold back on each other)");
  if (drop_straight(chart, v)) cases.insert(shadow_case::collinear_vertices);
  if (!is_simple(chart))
    throw error(errc::scene_self_intersecting, name + " is not a simple polygon (its edges cross or touch)");
  if (sgn(signed_area(chart)) < 0) {
    std::reverse(chart.begin(), chart.end());
    std::reverse(v.begin(), v.end());
  }
  // The face's plane (n, dn) contains the light: its shadow has no area.
  if (!setup.grazing()) {
    const auto& L = setup.sc->light_source.l;
    g.edge_on = sgn(dot(n, point3{L[0], L[1], L[2]}) + dn * L[3]) == 0;
  }
  g.v = std::move(v);
  g.chart = std::move(chart);
  return g;
}

void caster_sides::add(const clip_setup& setup, const point3& V) {
  const int t = sgn(plane_value(setup.P.p, V));
  if (t == 0) on = true;
  else if (t * setup.light_side > 0) front = true;
  else back = true;
  if (!setup.grazing() && setup.point_light() && plane_value(setup.height, V) >= 1) high = true;
}

void caster_sides::note(const clip_setup& setup, case_set& cases) const {
  if (setup.grazing()) return;
  if (front && back) cases.insert(shadow_case::caster_crosses_receiver);
  if (!front && !on && back) cases.insert(shadow_case::caster_behind_receiver);
  if (on && front && !back) cases.insert(shadow_case::caster_touches_receiver);
  if (high) cases.insert(shadow_case::caster_reaches_light_height);
}

projected_piece cast_convex_piece(const clip_setup& setup, std::vector<point3> poly, bool edge_on, case_set& cases) {
  projected_piece out;
  poly = setup.clip(std::move(poly));
  if (poly.empty()) return out;
  out.empty = false;
  if (edge_on) cases.insert(shadow_case::caster_edge_on);
  // A point light on the piece (only possible at the cone's apex, f = 1) projects nowhere;
  // the rays through it are covered by the piece's other boundary points, which project to
  // the same line (the piece's plane then contains the light), so the light is left out.
  std::vector<point2> pts;
  pts.reserve(poly.size());
  bool contains_light = false;
  for (const auto& p : poly) {
    if (setup.at_light(p)) {
      contains_light = true;
      continue;
    }
    pts.push_back(setup.project(p));
  }
  if (contains_light) cases.insert(shadow_case::caster_contains_light);
  drop_repeats(pts);
  if (pts.size() >= 3 && sgn(signed_area(pts)) != 0) {
    // The projection of a convex piece is convex (the denominator keeps its sign inside the
    // clipped region), so it is a valid simple polygon once oriented.
    erase_indices(pts, straight_vertices(pts));
    if (sgn(signed_area(pts)) < 0) std::reverse(pts.begin(), pts.end());
    out.polygon = std::move(pts);
    return out;
  }
  if (pts.empty()) {
    out.empty = true;
    return out;
  }
  // Zero area: the points are collinear; keep the two extreme ones.
  auto lo = pts[0], hi = pts[0];
  for (const auto& p : pts) {
    lo = std::min(lo, p);
    hi = std::max(hi, p);
  }
  out.segment = {lo, hi};
  return out;
}

void cast_face(const clip_setup& setup, const face_geometry& g, case_set& cases,
               std::vector<std::vector<point2>>& polygons, std::vector<std::array<point2, 2>>& degenerate) {
  const auto take = [&](projected_piece p) {
    if (p.empty) return;
    if (!p.polygon.empty()) polygons.push_back(std::move(p.polygon));
    else degenerate.push_back(p.segment);
  };
  if (g.collinear) {
    // The degenerate triangle (lo, hi, hi) clips and projects like any other.
    take(cast_convex_piece(setup, {g.v[0], g.v[1], g.v[1]}, false, cases));
    return;
  }
  if (g.v.size() == 3) {
    take(cast_convex_piece(setup, g.v, g.edge_on, cases));
    return;
  }
  for (const auto& piece : convex_pieces(g.chart)) {
    std::vector<point3> poly;
    poly.reserve(piece.size());
    for (auto i : piece) poly.push_back(g.v[i]);
    take(cast_convex_piece(setup, std::move(poly), g.edge_on, cases));
  }
}

}  // namespace shadowproof::detail
