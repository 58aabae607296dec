// The silhouette region builder (builders.h): the casters' boundary chains (chain.h), the
// receiver's rings and the zero-area pieces go into one CGAL arrangement; winding numbers
// are assigned to its faces by walking across edges from the unbounded face; the region is
// the faces with a positive shadow winding inside the receiver.
#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>

#include <numeric>
#include <optional>

#include "builders.h"
#include "chain.h"
#include "kernel.h"
#include "planar_sweep.h"
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
// It also names the input segment it lies on (`line`, into a table of segments): every piece
// of an overlap lies on the supporting line of each, so either one will do.
struct curve_data {
  long shadow = 0;
  long receiver = 0;
  bool degenerate = false;
  std::size_t line = 0;
  friend bool operator==(const curve_data& a, const curve_data& b) {
    return a.shadow == b.shadow && a.receiver == b.receiver && a.degenerate == b.degenerate;
  }
};
struct merge_data {
  curve_data operator()(const curve_data& a, const curve_data& b) const {
    return {a.shadow + b.shadow, a.receiver + b.receiver, a.degenerate || b.degenerate, a.line};
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

// The supporting lines of the input segments, as A x + B y = C with integer coefficients
// (computed when first asked for): an arrangement vertex lies on the line of every curve
// through it, so two of them that are not parallel give its exact coordinates by Cramer's
// rule, x = (C₁B₂ − C₂B₁)/D, y = (A₁C₂ − A₂C₁)/D with D = A₁B₂ − A₂B₁ — a few integer
// products, where forcing the lazy kernel's value of a crossing re-evaluates its whole
// construction, under a lock, at several times the cost.
class segment_lines {
 public:
  /// Adds the segment a → b (a ≠ b) and returns its index.
  std::size_t add(const point2& a, const point2& b) {
    ends_.push_back({a, b});
    return ends_.size() - 1;
  }
  /// The intersection of the lines of segments i and j, or nullopt when they are parallel.
  std::optional<point2> meet(std::size_t i, std::size_t j) {
    if (lines_.size() < ends_.size()) lines_.resize(ends_.size());
    const line &l = get(i), &m = get(j);
    mpz_class d = l.a * m.b - m.a * l.b;
    if (sgn(d) == 0) return std::nullopt;
    rational x(l.c * m.b - m.c * l.b, d), y(l.a * m.c - m.a * l.c, d);
    x.canonicalize();
    y.canonicalize();
    return point2{std::move(x), std::move(y)};
  }

 private:
  struct line {
    mpz_class a, b, c;
  };
  const line& get(std::size_t i) {
    auto& l = lines_[i];
    if (!l) {
      const auto& [p, q] = ends_[i];
      // (q_y − p_y) x + (p_x − q_x) y = (q_y − p_y) p_x + (p_x − q_x) p_y, times the lcm of
      // the denominators.
      const rational a = q[1] - p[1], b = p[0] - q[0], c = a * p[0] + b * p[1];
      mpz_class scale;
      mpz_lcm(scale.get_mpz_t(), a.get_den_mpz_t(), b.get_den_mpz_t());
      mpz_lcm(scale.get_mpz_t(), scale.get_mpz_t(), c.get_den_mpz_t());
      l = line{a.get_num() * (scale / a.get_den()), b.get_num() * (scale / b.get_den()), c.get_num() * (scale / c.get_den())};
    }
    return *l;
  }
  std::vector<std::array<point2, 2>> ends_;
  std::vector<std::optional<line>> lines_;
};

// The x-monotone curve a → b (pa → pb in the kernel) with `shadow` and `receiver` counted
// along a → b, registered in `lines`.
xcurve make_curve(segment_lines& lines, const point2& a, const point2& b, const cpoint& pa, const cpoint& pb, long shadow,
                  long receiver, bool degenerate) {
  const bool forward = CGAL::compare_xy(pa, pb) == CGAL::SMALLER;
  const long sign = forward ? 1 : -1;
  return xcurve(segment_traits::X_monotone_curve_2(pa, pb),
                curve_data{sign * shadow, sign * receiver, degenerate, lines.add(a, b)});
}
xcurve make_curve(segment_lines& lines, const point2& a, const point2& b, long shadow, long receiver, bool degenerate) {
  return make_curve(lines, a, b, to_cpoint(a), to_cpoint(b), shadow, receiver, degenerate);
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
  // Any order of the walk gives the same numbers (the chains are closed): a stack.
  std::vector<face_handle> todo;
  todo.reserve(arr.number_of_faces());
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
    const face_handle f = todo.back();
    todo.pop_back();
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

// The arrangement's vertices as rationals, each converted once and only when asked for:
// the exact value of an intersection point is costly to force, and only the vertices on the
// region's boundary and on its zero-area pieces are ever asked for.
// A vertex is the meeting point of the lines of two of its curves that are not parallel; only
// a vertex whose curves all lie on one line (or none) asks the kernel.
class exact_points {
 public:
  exact_points(arrangement& arr, segment_lines& lines) : lines_(lines) {
    std::size_t i = 0;
    for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) v->data().index = i++;
    points_.resize(i);
  }
  template <class Vertex>
  const point2& operator()(const Vertex& v) {
    auto& p = points_[v->data().index];
    if (!p) p = compute(v);
    return *p;
  }

 private:
  template <class Vertex>
  point2 compute(const Vertex& v) {
    if (!v->is_isolated()) {
      auto c = v->incident_halfedges();
      const auto first = c;
      const std::size_t l = c->curve().data().line;
      while (++c != first) {
        const std::size_t m = c->curve().data().line;
        if (m == l) continue;
        if (auto p = lines_.meet(l, m)) return std::move(*p);
      }
    }
    return to_point2(v->point());
  }
  segment_lines& lines_;
  std::vector<std::optional<point2>> points_;
};

// The polygons with holes of a region and its area (the sum of its rings' signed areas).
struct region_rings {
  std::vector<ring_with_holes> polygons;
  rational area{0};
};

// The boundary of the region of faces with `in(face)`: its polygons with holes, read off the
// arrangement as if every edge with the region on both sides were removed. A boundary
// half-edge has the region on its left only; the next one along the merged face is found by
// turning around the target vertex past half-edges interior to the region.
template <class In>
region_rings region_boundary(arrangement& arr, exact_points& points, In in) {
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
      r.push_back(points(h->source()));
      halfedge_handle n = h->next();
      while (!boundary(n)) n = n->twin()->next();
      h = n;
      if (++steps > guard) throw internal_error("a shadow boundary does not close");
    } while (h != halfedge_handle(h0));
    rings.emplace_back(find(h0->face()->data().id), std::move(r));
  }
  // One counter-clockwise outer ring per merged face, its clockwise rings are its holes.
  std::vector<std::ptrdiff_t> outer_of(arr.number_of_faces(), -1);
  region_rings out;
  std::vector<rational> areas;
  areas.reserve(rings.size());
  for (const auto& entry : rings) areas.push_back(signed_area(entry.second));
  for (std::size_t i = 0; i < rings.size(); ++i)
    if (sgn(areas[i]) > 0) {
      auto& [component, r] = rings[i];
      if (outer_of[component] >= 0) throw internal_error("a merged shadow face has two outer boundaries");
      outer_of[component] = static_cast<std::ptrdiff_t>(out.polygons.size());
      out.polygons.push_back({std::move(r), {}});
    }
  for (std::size_t i = 0; i < rings.size(); ++i)
    if (sgn(areas[i]) < 0) {
      auto& [component, r] = rings[i];
      if (outer_of[component] < 0) throw internal_error("a shadow hole has no outer boundary");
      out.polygons[static_cast<std::size_t>(outer_of[component])].second.push_back(std::move(r));
    }
  out.area = balanced_sum(std::move(areas));
  return out;
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

void add_chain(std::vector<xcurve>& curves, segment_lines& lines, const caster_chain& chain) {
  std::vector<cpoint> points;
  points.reserve(chain.points.size());
  for (const auto& p : chain.points) points.push_back(to_cpoint(p));
  for (const auto& s : chain.segments)
    if (s.weight != 0)
      curves.push_back(
          make_curve(lines, chain.points[s.a], chain.points[s.b], points[s.a], points[s.b], s.weight, 0, false));
}

// --- the same from the sweep (planar_sweep.h) -----------------------------------------------

// The boundary of the region of faces with `in(windings)` in a planar map: its directed
// edges (region on the left) grouped by connected open piece, and the region's area
// ½ Σ (x_from y_to − x_to y_from) over them. Pieces are found with a union–find over the
// edges: two edges next to each other on the sweep line with the region between them bound
// the same piece.
struct swept_boundary {
  std::vector<std::vector<std::array<std::uint32_t, 2>>> pieces;
  rational area{0};
};

template <class In>
swept_boundary swept_region_boundary(const planar_map& m, In in, bool with_area) {
  std::vector<std::uint32_t> parent(m.edges.size());
  std::iota(parent.begin(), parent.end(), std::uint32_t(0));
  const auto find = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [lower, upper] : m.adjacent)
    if (in(m.edges[lower].above())) parent[find(lower)] = find(upper);
  swept_boundary out;
  std::vector<std::ptrdiff_t> piece_of(m.edges.size(), -1);
  std::vector<rational> terms;
  for (std::uint32_t e = 0; e < m.edges.size(); ++e) {
    const auto& E = m.edges[e];
    const bool below = in(E.below), above = in(E.above());
    if (below == above) continue;
    const std::uint32_t from_id = above ? E.lo : E.hi, to_id = above ? E.hi : E.lo;
    const point2 *from = m.vertices[from_id], *to = m.vertices[to_id];
    auto& k = piece_of[find(e)];
    if (k < 0) {
      k = static_cast<std::ptrdiff_t>(out.pieces.size());
      out.pieces.emplace_back();
    }
    out.pieces[static_cast<std::size_t>(k)].push_back({from_id, to_id});
    if (with_area) terms.push_back((*from)[0] * (*to)[1] - (*to)[0] * (*from)[1]);
  }
  if (with_area) out.area = balanced_sum(std::move(terms)) / 2;
  return out;
}

std::vector<sweep_segment> chain_segments(const caster_chain& chain, std::vector<const point2*>& points) {
  std::vector<sweep_segment> out;
  const std::size_t base = points.size();
  for (const auto& p : chain.points) points.push_back(&p);
  for (const auto& s : chain.segments)
    if (s.weight != 0) out.push_back({base + s.a, base + s.b, s.weight, 0, false});
  return out;
}

// The zero-area pieces kept on the receiver outside the region (segments and points, in chart
// coordinates) written to r in canonical form and lifted to 3D, and the cases they make: a
// shadow touching the receiver's boundary, a degenerate shadow, an empty one. Both region
// builders (the sweep's and the arrangement's) end with it.
void record_zero_area_pieces(const std::vector<std::array<point2, 2>>& kept, bool contact, case_set& cases,
                             shadow_region& r) {
  if (contact) cases.insert(shadow_case::shadow_touches_receiver_boundary);
  for (const auto& k : canonical_pieces(kept))
    r.degenerate.push_back({k[0], k[1], r.chart.lift(k[0]), r.chart.lift(k[1])});
  if (!r.degenerate.empty()) cases.insert(shadow_case::degenerate_shadow);
  if (r.polygons.empty() && r.degenerate.empty()) cases.insert(shadow_case::empty);
}

// The region of silhouette_region from the sweep instead of an arrangement: the same fields
// by the same rules, read off the planar map (the faces around a vertex are the faces on
// both sides of its edges). False when the sweep declines the input (then nothing is set).
bool swept_region(const clip_setup& setup, const std::vector<caster_chain>& chains,
                  const std::vector<std::array<point2, 2>>& degenerate, const clip_options& options, case_set& cases,
                  shadow_region& r) {
  std::vector<const point2*> points;
  std::vector<sweep_segment> segments;
  for (const auto& chain : chains) {
    auto own = chain_segments(chain, points);
    segments.insert(segments.end(), own.begin(), own.end());
  }
  const auto add_ring = [&](const std::vector<point2>& boundary) {
    const std::size_t base = points.size();
    for (const auto& p : boundary) points.push_back(&p);
    for (std::size_t i = 0; i < boundary.size(); ++i)
      segments.push_back({base + i, base + (i + 1) % boundary.size(), 0, 1, false});
  };
  add_ring(setup.receiver_outer);
  for (const auto& h : setup.receiver_holes) add_ring(h);  // clockwise: −1 inside
  std::vector<std::size_t> point_pieces;
  for (const auto& d : degenerate) {
    const std::size_t base = points.size();
    points.push_back(&d[0]);
    if (d[0] == d[1]) {
      point_pieces.push_back(base);
    } else {
      points.push_back(&d[1]);
      segments.push_back({base, base + 1, 0, 0, true});
    }
  }
  // Overlaps first: each caster's shadow area alone (a declined sweep declines everything).
  const bool overlap = options.detect_overlap && chains.size() > 1;
  std::vector<rational> own_areas;
  if (overlap)
    for (const auto& chain : chains) {
      std::vector<const point2*> own_points;
      const auto own = chain_segments(chain, own_points);
      const auto map = planar_sweep(own_points, own, {});
      if (!map) return false;
      own_areas.push_back(swept_region_boundary(*map, [](const windings& w) { return w[0] > 0; }, true).area);
    }
  const auto swept = planar_sweep(points, segments, point_pieces);
  if (!swept) return false;
  const planar_map& m = *swept;

  const auto in_shadow = [](const windings& w) { return w[0] > 0; };
  const auto in_receiver = [](const windings& w) { return w[1] > 0; };
  const auto in_result = [&](const windings& w) { return in_shadow(w) && in_receiver(w); };
  if (overlap || options.keep_projected) {
    swept_boundary shadow = swept_region_boundary(m, in_shadow, overlap);
    if (overlap && balanced_sum(std::move(own_areas)) != shadow.area) cases.insert(shadow_case::shadows_overlap);
    if (options.keep_projected) {
      for (const auto& p : canonical_polygons(shadow.pieces, m.vertices, r.chart)) {
        r.projected_loops.push_back(p.outer);
        for (const auto& h : p.holes) r.projected_loops.push_back(h);
      }
      r.projected_degenerate = canonical_pieces(degenerate);
    }
  }
  // Every bounded face lies on a side of some edge; an isolated point lies in a face too.
  bool outside = false;
  for (const auto& e : m.edges)
    for (const windings& w : {e.below, e.above()}) outside = outside || (in_shadow(w) && !in_receiver(w));
  if (outside) cases.insert(shadow_case::shadow_outside_receiver);
  const swept_boundary result = swept_region_boundary(m, in_result, false);
  r.polygons = canonical_polygons(result.pieces, m.vertices, r.chart);
  // The area from the canonical rings: consecutive shoelace terms share a vertex, so partial
  // sums along a ring keep smaller denominators than over the edges in any order.
  std::vector<rational> ring_areas;
  for (const auto& p : r.polygons) {
    ring_areas.push_back(signed_area(p.outer));
    for (const auto& h : p.holes) ring_areas.push_back(signed_area(h));
  }
  r.chart_area = balanced_sum(std::move(ring_areas));
  r.area_squared = r.chart_area * r.chart_area * r.chart.area_scale_squared;

  // Zero-area pieces in the closed receiver and outside the closed result, and contacts of
  // the shadow's boundary with the receiver's boundary outside the closed result.
  struct vertex_contacts {
    bool edges = false, from_caster = false, shadow_edge = false, receiver_edge = false, receiver = false, result = false;
  };
  std::vector<vertex_contacts> at(m.vertices.size());
  std::vector<std::array<point2, 2>> kept;
  bool contact = false;
  for (const auto& e : m.edges) {
    const windings f = e.above(), g = e.below;
    const bool shadow_edge = in_shadow(f) != in_shadow(g), receiver_edge = in_receiver(f) != in_receiver(g);
    const bool receiver = in_receiver(f) || in_receiver(g), in_region = in_result(f) || in_result(g);
    for (const auto v : {e.lo, e.hi}) {
      auto& a = at[v];
      a.edges = true;
      a.from_caster = a.from_caster || e.degenerate;
      a.shadow_edge = a.shadow_edge || shadow_edge;
      a.receiver_edge = a.receiver_edge || receiver_edge;
      a.receiver = a.receiver || receiver;
      a.result = a.result || in_region;
    }
    if (!(e.degenerate || (shadow_edge && receiver_edge)) || !(receiver && !in_region)) continue;
    kept.push_back({*m.vertices[e.lo], *m.vertices[e.hi]});
    if (shadow_edge && receiver_edge) contact = true;
  }
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    auto a = at[v];
    if (!a.edges) {
      if (!m.point_piece[v]) continue;  // not a vertex of the map
      a.receiver = in_receiver(m.isolated[v]);
      a.result = in_result(m.isolated[v]);
    }
    a.from_caster = a.from_caster || m.point_piece[v];
    const bool touching = a.shadow_edge && a.receiver_edge;
    if (!(a.from_caster || touching) || !(a.receiver && !a.result)) continue;
    kept.push_back({*m.vertices[v], *m.vertices[v]});
    if (touching) contact = true;
  }
  record_zero_area_pieces(kept, contact, cases, r);
  return true;
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
  if (options.method != clip_method::arrangement) {
    case_set swept_cases = cases;
    if (swept_region(setup, chains, degenerate, options, swept_cases, r)) {
      r.cases.assign(swept_cases.begin(), swept_cases.end());
      report("done", total_faces);
      return r;
    }
  }

  std::vector<xcurve> curves;
  segment_lines lines;
  for (const auto& chain : chains) add_chain(curves, lines, chain);
  const auto add_ring = [&](const std::vector<point2>& boundary) {
    for (std::size_t i = 0; i < boundary.size(); ++i)
      curves.push_back(make_curve(lines, boundary[i], boundary[(i + 1) % boundary.size()], 0, 1, false));
  };
  add_ring(setup.receiver_outer);
  for (const auto& h : setup.receiver_holes) add_ring(h);  // clockwise: −1 inside
  std::vector<point2> degenerate_points;
  for (const auto& d : degenerate) {
    if (d[0] == d[1]) degenerate_points.push_back(d[0]);
    else curves.push_back(make_curve(lines, d[0], d[1], 0, 0, true));
  }
  arrangement arr;
  CGAL::insert(arr, curves.begin(), curves.end());
  for (const auto& p : degenerate_points) CGAL::insert_point(arr, to_cpoint(p))->data().degenerate_point = true;
  assign_windings(arr);
  exact_points points(arr, lines);

  const auto in_shadow = [](const auto& f) { return f->data().shadow > 0; };
  const auto in_receiver = [](const auto& f) { return f->data().receiver > 0; };
  const auto in_result = [&](const auto& f) { return in_shadow(f) && in_receiver(f); };
  // Areas are summed over boundary rings only: no exact value of a vertex inside the region.
  const bool overlap = options.detect_overlap && s.casters.size() > 1;
  std::optional<region_rings> shadow_rings;
  if (overlap || options.keep_projected) shadow_rings = region_boundary(arr, points, in_shadow);
  if (overlap) {
    std::vector<rational> areas;
    for (const auto& chain : chains) {
      std::vector<xcurve> own;
      segment_lines own_lines;
      add_chain(own, own_lines, chain);
      arrangement one;
      CGAL::insert(one, own.begin(), own.end());
      assign_windings(one);
      exact_points own_points(one, own_lines);
      areas.push_back(region_boundary(one, own_points, in_shadow).area);
    }
    if (balanced_sum(std::move(areas)) != shadow_rings->area) cases.insert(shadow_case::shadows_overlap);
  }
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
    if (in_shadow(f) && !in_receiver(f)) cases.insert(shadow_case::shadow_outside_receiver);
  region_rings result_rings = region_boundary(arr, points, in_result);
  r.chart_area = result_rings.area;
  r.area_squared = r.chart_area * r.chart_area * r.chart.area_scale_squared;
  r.polygons = canonical_polygons(std::move(result_rings.polygons), r.chart);

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
    kept.push_back({points(h->source()), points(h->target())});
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
    const point2& p = points(v);
    kept.push_back({p, p});
    if (touching) contact = true;
  }
  record_zero_area_pieces(kept, contact, cases, r);

  if (options.keep_projected) {
    for (const auto& p : canonical_polygons(std::move(shadow_rings->polygons), r.chart)) {
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
