// The silhouette region builder (builders.h): the casters' boundary chains (chain.h), the
// receiver's rings and the zero-area pieces go into one CGAL arrangement; winding numbers
// are assigned to its faces by walking across edges from the unbounded face; the region is
// the faces with a positive shadow winding inside the receiver.
#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include <deque>
#include <numeric>

#include "builders.h"
#include "chain.h"
#include "kernel.h"
#include "polygon2.h"
#include "polygon_set.h"
#include "region_setup.h"
#include "shadowproof/core/error.h"

namespace shadowproof::detail {

namespace {

// What a curve of the arrangement carries: how much it adds to the shadow winding and to the
// receiver's winding when crossed from its right to its left, both counted for the curve
// directed from its lexicographically smaller end to its larger one, and whether it carries a
// zero-area shadow piece. Overlapping curves add up.
struct curve_data {
  long shadow = 0;
  long receiver = 0;
  bool degenerate = false;
  friend bool operator==(const curve_data& a, const curve_data& b) {
    return a.shadow == b.shadow && a.receiver == b.receiver && a.degenerate == b.degenerate;
  }
};
struct merge_data {
  curve_data operator()(const curve_data& a, const curve_data& b) const {
    return {a.shadow + b.shadow, a.receiver + b.receiver, a.degenerate || b.degenerate};
  }
};
struct face_data {
  long shadow = 0, receiver = 0;
  bool reached = false;
  std::size_t id = 0;
};

using segment_traits = CGAL::Arr_segment_traits_2<kernel>;
using traits = CGAL::Arr_curve_data_traits_2<segment_traits, curve_data, merge_data>;
struct vertex_data {
  bool degenerate_point = false;  ///< a zero-area shadow piece that is a single point
  std::size_t index = 0;          ///< into the table of rational vertices
};
using dcel = CGAL::Arr_extended_dcel<traits, vertex_data, std::size_t /*mark*/, face_data>;
using arrangement = CGAL::Arrangement_2<traits, dcel>;
using xcurve = traits::X_monotone_curve_2;
using face_handle = arrangement::Face_handle;
using halfedge_handle = arrangement::Halfedge_handle;

// The x-monotone curve a → b with `shadow` and `receiver` counted along a → b.
xcurve make_curve(const cpoint& a, const cpoint& b, long shadow, long receiver, bool degenerate) {
  const bool forward = CGAL::compare_xy(a, b) == CGAL::SMALLER;
  const long sign = forward ? 1 : -1;
  return xcurve(segment_traits::X_monotone_curve_2(a, b), curve_data{sign * shadow, sign * receiver, degenerate});
}

// The data of h's curve counted along h.
curve_data along(const halfedge_handle& h) {
  const curve_data& d = h->curve().data();
  const long sign = h->direction() == CGAL::ARR_LEFT_TO_RIGHT ? 1 : -1;
  return {sign * d.shadow, sign * d.receiver, d.degenerate};
}

// Winding numbers of every face: 0 on the unbounded face; crossing h from its right (its
// twin's face) to its left (its own face) adds along(h).
void assign_windings(arrangement& arr) {
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) f->data() = face_data{};
  std::deque<face_handle> todo;
  const face_handle unbounded = arr.unbounded_face();
  unbounded->data().reached = true;
  todo.push_back(unbounded);
  const auto visit_ccb = [&](const face_handle& f, arrangement::Ccb_halfedge_circulator first) {
    auto h = first;
    do {
      const face_handle g = h->twin()->face();
      if (!g->data().reached) {
        const curve_data d = along(h);
        g->data().shadow = f->data().shadow - d.shadow;
        g->data().receiver = f->data().receiver - d.receiver;
        g->data().reached = true;
        todo.push_back(g);
      }
    } while (++h != first);
  };
  while (!todo.empty()) {
    const face_handle f = todo.front();
    todo.pop_front();
    if (f->has_outer_ccb()) visit_ccb(f, f->outer_ccb());
    for (auto in = f->inner_ccbs_begin(); in != f->inner_ccbs_end(); ++in) visit_ccb(f, *in);
  }
  std::size_t id = 0;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (!f->data().reached) throw internal_error("a face of the shadow arrangement was not reached");
    // Faces are counted by counter-clockwise pieces: a negative count is an orientation bug.
    if (f->data().shadow < 0) throw internal_error("negative shadow winding number");
    f->data().id = id++;
  }
}

// The arrangement's vertices as rationals, each converted once (lazy exact numbers are
// slow to evaluate one operation at a time), indexed by the vertices' data.
std::vector<point2> vertex_points(arrangement& arr) {
  std::vector<point2> points;
  points.reserve(arr.number_of_vertices());
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    v->data().index = points.size();
    points.push_back(to_point2(v->point()));
  }
  return points;
}

// Twice the signed area enclosed by one boundary cycle (shoelace, exact).
template <class Circulator>
void twice_ccb_area(const std::vector<point2>& p, Circulator first, std::vector<rational>& terms) {
  auto h = first;
  do {
    const point2& a = p[h->source()->data().index];
    const point2& b = p[h->target()->data().index];
    terms.push_back(a[0] * b[1] - a[1] * b[0]);
  } while (++h != first);
}

// Twice the area of every bounded face with `in(face)`, indexed by face id (0 elsewhere).
template <class In>
std::vector<rational> twice_face_areas(const arrangement& arr, const std::vector<point2>& p, In in) {
  std::vector<rational> out(arr.number_of_faces());
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (f->is_unbounded() || !in(f)) continue;
    std::vector<rational> terms;
    twice_ccb_area(p, f->outer_ccb(), terms);
    for (auto h = f->inner_ccbs_begin(); h != f->inner_ccbs_end(); ++h) twice_ccb_area(p, *h, terms);
    out[f->data().id] = balanced_sum(std::move(terms));
  }
  return out;
}

// The sum of the areas of the faces with `in(face)`.
template <class In>
rational area_of(const arrangement& arr, const std::vector<rational>& twice_areas, In in) {
  std::vector<rational> terms;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
    if (!f->is_unbounded() && in(f)) terms.push_back(twice_areas[f->data().id]);
  return balanced_sum(std::move(terms)) / 2;
}

// The boundary of the region of faces with `in(face)`: its polygons with holes, read off the
// arrangement as if every edge with the region on both sides were removed. A boundary
// half-edge has the region on its left only; the next one along the merged face is found by
// turning around the target vertex past half-edges interior to the region.
template <class In>
std::vector<ring_with_holes> region_boundary(arrangement& arr, const std::vector<point2>& points, In in) {
  const auto boundary = [&](const halfedge_handle& h) { return in(h->face()) && !in(h->twin()->face()); };
  // Faces of one merged face share a component.
  std::vector<std::size_t> parent(arr.number_of_faces());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e)
    if (in(e->face()) && in(e->twin()->face())) parent[find(e->face()->data().id)] = find(e->twin()->face()->data().id);
  for (auto h = arr.halfedges_begin(); h != arr.halfedges_end(); ++h) h->data() = 0;
  std::vector<std::pair<std::size_t, ring>> rings;
  const std::size_t guard = arr.number_of_halfedges() + 1;
  for (auto h0 = arr.halfedges_begin(); h0 != arr.halfedges_end(); ++h0) {
    if (h0->data() != 0 || !boundary(h0)) continue;
    ring r;
    halfedge_handle h = h0;
    std::size_t steps = 0;
    do {
      h->data() = 1;
      r.push_back(points[h->source()->data().index]);
      halfedge_handle n = h->next();
      while (!boundary(n)) n = n->twin()->next();
      h = n;
      if (++steps > guard) throw internal_error("a shadow boundary does not close");
    } while (h != halfedge_handle(h0));
    rings.emplace_back(find(h0->face()->data().id), std::move(r));
  }
  // One counter-clockwise outer ring per merged face, its clockwise rings are its holes.
  std::vector<std::ptrdiff_t> outer_of(arr.number_of_faces(), -1);
  std::vector<ring_with_holes> polygons;
  for (auto& [component, r] : rings)
    if (sgn(signed_area(r)) > 0) {
      if (outer_of[component] >= 0) throw internal_error("a merged shadow face has two outer boundaries");
      outer_of[component] = static_cast<std::ptrdiff_t>(polygons.size());
      polygons.push_back({std::move(r), {}});
    }
  for (auto& [component, r] : rings)
    if (!r.empty() && sgn(signed_area(r)) < 0) {
      if (outer_of[component] < 0) throw internal_error("a shadow hole has no outer boundary");
      polygons[static_cast<std::size_t>(outer_of[component])].second.push_back(std::move(r));
    }
  return polygons;
}

// The faces around vertex v (its face when isolated).
template <class F>
void for_each_face_around(const arrangement::Vertex_handle& v, F f) {
  if (v->is_isolated()) {
    f(v->face());
    return;
  }
  auto c = v->incident_halfedges();
  const auto first = c;
  do {
    f(c->face());
    f(c->twin()->face());
  } while (++c != first);
}

void add_chain(std::vector<xcurve>& curves, const caster_chain& chain) {
  std::vector<cpoint> points;
  points.reserve(chain.points.size());
  for (const auto& p : chain.points) points.push_back(to_cpoint(p));
  for (const auto& s : chain.segments)
    if (s.weight != 0) curves.push_back(make_curve(points[s.a], points[s.b], s.weight, 0, false));
}

}  // namespace

shadow_region silhouette_region(const scene& s, const plane<rational>& P, const clip_options& options) {
  validate_sizes(s, options.limits);
  case_set cases;
  const clip_setup setup = make_clip_setup(s, P, cases);
  shadow_region r = setup.empty_region();

  std::size_t total_faces = 0, done_faces = 0;
  for (const auto& c : s.casters) total_faces += c.faces.size();
  const auto report = [&](const char* stage, std::size_t done) {
    if (options.progress) options.progress(stage, total_faces == 0 ? 1.0 : double(done) / double(total_faces));
  };
  std::vector<caster_chain> chains;
  std::vector<std::array<point2, 2>> degenerate;
  for (std::size_t ci = 0; ci < s.casters.size(); ++ci) {
    chains.push_back(build_chain(setup, ci, cases, degenerate,
                                 [&](std::size_t f) { report("classifying faces", done_faces + f); }));
    done_faces += s.casters[ci].faces.size();
    r.silhouette_edges += chains.back().segments.size();
    r.face_half_edges += chains.back().half_edges;
  }
  report("arrangement", total_faces);

  std::vector<xcurve> curves;
  for (const auto& chain : chains) add_chain(curves, chain);
  const auto add_ring = [&](const std::vector<point2>& boundary) {
    for (std::size_t i = 0; i < boundary.size(); ++i)
      curves.push_back(
          make_curve(to_cpoint(boundary[i]), to_cpoint(boundary[(i + 1) % boundary.size()]), 0, 1, false));
  };
  add_ring(setup.receiver_outer);
  for (const auto& h : setup.receiver_holes) add_ring(h);  // clockwise: −1 inside
  std::vector<point2> degenerate_points;
  for (const auto& d : degenerate) {
    if (d[0] == d[1]) degenerate_points.push_back(d[0]);
    else curves.push_back(make_curve(to_cpoint(d[0]), to_cpoint(d[1]), 0, 0, true));
  }
  arrangement arr;
  CGAL::insert(arr, curves.begin(), curves.end());
  for (const auto& p : degenerate_points) CGAL::insert_point(arr, to_cpoint(p))->data().degenerate_point = true;
  assign_windings(arr);
  const std::vector<point2> points = vertex_points(arr);

  const auto in_shadow = [](const auto& f) { return f->data().shadow > 0; };
  const auto in_receiver = [](const auto& f) { return f->data().receiver > 0; };
  const auto in_result = [&](const auto& f) { return in_shadow(f) && in_receiver(f); };
  const std::vector<rational> twice_areas = twice_face_areas(arr, points, in_shadow);  // result ⊆ shadow

  const rational all_area = area_of(arr, twice_areas, in_shadow);
  if (options.detect_overlap && s.casters.size() > 1) {
    rational sum = 0;
    for (const auto& chain : chains) {
      std::vector<xcurve> own;
      add_chain(own, chain);
      arrangement one;
      CGAL::insert(one, own.begin(), own.end());
      assign_windings(one);
      sum += area_of(one, twice_face_areas(one, vertex_points(one), in_shadow), in_shadow);
    }
    if (sum != all_area) cases.insert(shadow_case::shadows_overlap);
  }
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
    if (in_shadow(f) && !in_receiver(f)) cases.insert(shadow_case::shadow_outside_receiver);
  r.chart_area = area_of(arr, twice_areas, in_result);
  r.area_squared = r.chart_area * r.chart_area * r.chart.area_scale_squared;
  r.polygons = canonical_polygons(region_boundary(arr, points, in_result), r.chart);

  // Zero-area pieces in the closed receiver and outside the closed result, and contacts of
  // the shadow's boundary with the receiver's boundary outside the closed result.
  const auto keep_edge = [&](const halfedge_handle& e) {
    const face_handle f = e->face(), g = e->twin()->face();
    return (in_receiver(f) || in_receiver(g)) && !in_result(f) && !in_result(g);
  };
  const auto keep_vertex = [&](const arrangement::Vertex_handle& v) {
    bool receiver = false, result = false;
    for_each_face_around(v, [&](const face_handle& f) {
      receiver = receiver || in_receiver(f);
      result = result || in_result(f);
    });
    return receiver && !result;
  };
  std::vector<std::array<point2, 2>> kept;
  bool contact = false;
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    const halfedge_handle h = e;
    const face_handle f = h->face(), g = h->twin()->face();
    const bool shadow_edge = in_shadow(f) != in_shadow(g), receiver_edge = in_receiver(f) != in_receiver(g);
    const bool from_caster = h->curve().data().degenerate;
    if (!(from_caster || (shadow_edge && receiver_edge)) || !keep_edge(h)) continue;
    kept.push_back({points[h->source()->data().index], points[h->target()->data().index]});
    if (shadow_edge && receiver_edge) contact = true;
  }
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    bool from_caster = v->data().degenerate_point, shadow_edge = false, receiver_edge = false;
    if (!v->is_isolated()) {
      auto c = v->incident_halfedges();
      const auto first = c;
      do {
        const face_handle f = c->face(), g = c->twin()->face();
        from_caster = from_caster || c->curve().data().degenerate;
        shadow_edge = shadow_edge || in_shadow(f) != in_shadow(g);
        receiver_edge = receiver_edge || in_receiver(f) != in_receiver(g);
      } while (++c != first);
    }
    const bool touching = shadow_edge && receiver_edge;
    if (!(from_caster || touching) || !keep_vertex(v)) continue;
    const point2& p = points[v->data().index];
    kept.push_back({p, p});
    if (touching) contact = true;
  }
  if (contact) cases.insert(shadow_case::shadow_touches_receiver_boundary);
  for (const auto& k : canonical_pieces(kept))
    r.degenerate.push_back({k[0], k[1], r.chart.lift(k[0]), r.chart.lift(k[1])});
  if (!r.degenerate.empty()) cases.insert(shadow_case::degenerate_shadow);
  if (r.polygons.empty() && r.degenerate.empty()) cases.insert(shadow_case::empty);

  if (options.keep_projected) {
    for (const auto& p : canonical_polygons(region_boundary(arr, points, in_shadow), r.chart)) {
      r.projected_loops.push_back(p.outer);
      for (const auto& h : p.holes) r.projected_loops.push_back(h);
    }
    r.projected_degenerate = canonical_pieces(degenerate);
  }
  r.cases.assign(cases.begin(), cases.end());
  report("done", total_faces);
  return r;
}

}  // namespace shadowproof::detail
