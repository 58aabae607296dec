// Exact polygon utilities over rationals (see polygon2.h).
#include "polygon2.h"

#include <CGAL/Interval_nt.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/partition_2.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <list>
#include <numeric>
#include <tuple>

#include "kernel.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/vec3.h"

namespace shadowproof::detail {

rational orient2(const point2& a, const point2& b, const point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

rational balanced_sum(std::vector<rational> terms) {
  if (terms.empty()) return 0;
  while (terms.size() > 1) {
    const std::size_t n = terms.size();
    std::size_t m = 0;
    for (std::size_t i = 0; i + 1 < n; i += 2) terms[m++] = terms[i] + terms[i + 1];
    if (n % 2 == 1) terms[m++] = std::move(terms[n - 1]);
    terms.resize(m);
  }
  return std::move(terms[0]);
}

rational signed_area(const std::vector<point2>& p) {
  std::vector<rational> terms;
  terms.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    terms.push_back(a[0] * b[1] - a[1] * b[0]);
  }
  return balanced_sum(std::move(terms)) / 2;
}

int largest_axis(const point3& n) {
  const rational a = abs(n[0]), b = abs(n[1]), c = abs(n[2]);
  if (a >= b && a >= c) return 0;
  if (b >= c) return 1;
  return 2;
}

point2 drop_axis(const point3& p, int k) { return {p[(k + 1) % 3], p[(k + 2) % 3]}; }

point3 plane_normal(const std::vector<point3>& v) {
  for (std::size_t k = 2; k < v.size(); ++k) {
    const point3 c = cross(difference(v[1], v[0]), difference(v[k], v[0]));
    if (!is_zero(c)) return c;
  }
  return {rational(0), rational(0), rational(0)};
}

namespace {

// A rational's nearest doubles below and above it, in the range where GMP's truncating
// conversion is within one ulp (else false: decide exactly).
bool bracket(const rational& q, CGAL::Interval_nt<false>& out) {
  const double d = q.get_d();
  if (d == 0) {
    if (sgn(q) != 0) return false;
    out = CGAL::Interval_nt<false>(0);
    return true;
  }
  const double m = std::fabs(d);
  if (!(m > 0x1p-400 && m < 0x1p400)) return false;
  out = CGAL::Interval_nt<false>(std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL));
  return true;
}

// The sign of orient2(a, b, c): in interval arithmetic when that decides it, else exactly.
// Only (nearly) collinear triples pay for rationals.
int orient2_sign(const point2& a, const point2& b, const point2& c) {
  CGAL::Interval_nt<false> v[6];
  const rational* q[6] = {&a[0], &a[1], &b[0], &b[1], &c[0], &c[1]};
  bool filtered = true;
  for (int i = 0; i < 6 && filtered; ++i) filtered = bracket(*q[i], v[i]);
  if (filtered) {
    CGAL::Protect_FPU_rounding<true> up;
    const auto o = (v[2] - v[0]) * (v[5] - v[1]) - (v[3] - v[1]) * (v[4] - v[0]);
    const CGAL::Uncertain<CGAL::Sign> s = CGAL::sign(o);
    if (CGAL::is_certain(s)) return static_cast<int>(CGAL::get_certain(s));
  }
  return sgn(orient2(a, b, c));
}

// (b − a)·(d − b): > 0 when a → b → d goes on in the same direction.
rational forward(const point2& a, const point2& b, const point2& d) {
  return (b[0] - a[0]) * (d[0] - b[0]) + (b[1] - a[1]) * (d[1] - b[1]);
}

}  // namespace

std::optional<std::size_t> fold_back_vertex(const std::vector<point2>& c) {
  const std::size_t n = c.size();
  if (n < 3) return std::nullopt;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = c[(i + n - 1) % n];
    const auto& b = c[i];
    const auto& d = c[(i + 1) % n];
    if (sgn(orient2(a, b, d)) == 0 && sgn(forward(a, b, d)) <= 0) return i;
  }
  return std::nullopt;
}

std::vector<std::size_t> straight_vertices(const std::vector<point2>& c) {
  std::vector<std::size_t> out;
  const std::size_t n = c.size();
  if (n < 3) return out;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& a = c[(i + n - 1) % n];
    const auto& b = c[i];
    const auto& d = c[(i + 1) % n];
    if (orient2_sign(a, b, d) == 0 && sgn(forward(a, b, d)) > 0) out.push_back(i);
  }
  // Every vertex straight is impossible for a closed polygon with area; keep the input then
  // (the caller's zero-area test rejects it).
  if (out.size() + 2 > n) out.clear();
  return out;
}

bool on_segment(const point2& a, const point2& b, const point2& p) {
  return sgn(orient2(a, b, p)) == 0 && std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}

namespace {

bool segments_meet(const point2& a, const point2& b, const point2& c, const point2& d) {
  const int o1 = sgn(orient2(a, b, c)), o2 = sgn(orient2(a, b, d));
  const int o3 = sgn(orient2(c, d, a)), o4 = sgn(orient2(c, d, b));
  if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

}  // namespace

bool is_simple(const std::vector<point2>& p) {
  if (p.size() < 3) return false;
  if (fold_back_vertex(p)) return false;
  if (p.size() > 24) {
    CGAL::Polygon_2<kernel> poly;
    for (const auto& q : p) poly.push_back(to_cpoint(q));
    return poly.is_simple();
  }
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      if (segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return false;
    }
  return true;
}

bool is_convex(const std::vector<point2>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    if (sgn(orient2(p[i], p[(i + 1) % n], p[(i + 2) % n])) <= 0) return false;
  // Turning left everywhere can still wind around twice; a simple polygon cannot.
  return true;
}

std::vector<std::vector<std::size_t>> convex_pieces(const std::vector<point2>& p) {
  std::vector<std::vector<std::size_t>> out;
  if (is_convex(p)) {
    out.emplace_back(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) out.back()[i] = i;
    return out;
  }
  // Partition the vertex indices, reading the points through a property map.
  std::vector<cpoint> points;
  points.reserve(p.size());
  for (const auto& q : p) points.push_back(to_cpoint(q));
  using map = CGAL::Pointer_property_map<cpoint>::type;
  using traits = CGAL::Partition_traits_2<kernel, map>;
  const traits t(CGAL::make_property_map(points));
  std::vector<std::size_t> indices(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) indices[i] = i;
  std::list<traits::Polygon_2> pieces;
  CGAL::greene_approx_convex_partition_2(indices.begin(), indices.end(), std::back_inserter(pieces), t);
  for (const auto& piece : pieces) {
    out.emplace_back(piece.vertices_begin(), piece.vertices_end());
    // The partition keeps the input's orientation; make sure, the pieces are clipped as CCW.
    std::vector<point2> corners;
    for (auto i : out.back()) corners.push_back(p[i]);
    if (sgn(signed_area(corners)) < 0) std::reverse(out.back().begin(), out.back().end());
    if (sgn(signed_area(corners)) == 0) throw internal_error("convex partition produced a piece without area");
  }
  return out;
}

std::optional<std::array<point2, 2>> segment_intersection(const point2& a, const point2& b, const point2& c,
                                                          const point2& d) {
  const rational o1 = orient2(a, b, c), o2 = orient2(a, b, d);
  if (sgn(o1) == 0 && sgn(o2) == 0) {
    // Collinear: the overlap of the two parameter ranges along the line.
    auto lo_hi = [](point2 x, point2 y) { return x < y ? std::array<point2, 2>{x, y} : std::array<point2, 2>{y, x}; };
    const auto s = lo_hi(a, b), t = lo_hi(c, d);
    const point2 lo = std::max(s[0], t[0]), hi = std::min(s[1], t[1]);
    if (hi < lo) return std::nullopt;
    return std::array<point2, 2>{lo, hi};
  }
  const rational o3 = orient2(c, d, a), o4 = orient2(c, d, b);
  if (sgn(o1) * sgn(o2) > 0 || sgn(o3) * sgn(o4) > 0) return std::nullopt;
  // Proper crossing or an endpoint on the other segment: a + u (b − a), u = o3 / (o3 − o4).
  const rational u = o3 / (o3 - o4);
  const point2 x{a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])};
  return std::array<point2, 2>{x, x};
}

std::vector<point2> canonical_ring(std::vector<point2> cycle) {
  const std::size_t n = cycle.size();
  std::size_t best = 0;
  for (std::size_t s = 1; s < n; ++s) {
    // Compare the rotations starting at s and at best, element by element.
    for (std::size_t i = 0; i < n; ++i) {
      const auto& x = cycle[(s + i) % n];
      const auto& y = cycle[(best + i) % n];
      if (x < y) {
        best = s;
        break;
      }
      if (y < x) break;
    }
  }
  std::rotate(cycle.begin(), cycle.begin() + static_cast<std::ptrdiff_t>(best), cycle.end());
  return cycle;
}

namespace {
// True when the counter-clockwise angle from a to x is smaller than from a to y (angles in
// [0, 2π), exact: by half-plane, then by the cross product).
bool ccw_before(const point2& a, const point2& x, const point2& y) {
  const auto half = [&](const point2& d) {
    const rational c = a[0] * d[1] - a[1] * d[0];
    const rational t = a[0] * d[0] + a[1] * d[1];
    return (sgn(c) > 0 || (sgn(c) == 0 && sgn(t) > 0)) ? 0 : 1;
  };
  const int hx = half(x), hy = half(y);
  if (hx != hy) return hx < hy;
  return sgn(x[0] * y[1] - x[1] * y[0]) > 0;
}

// The boundary of a regular region given by closed walks (region on their left), re-linked
// into the boundary cycles of its connected open pieces: at a vertex where the boundary
// touches itself, an incoming edge continues with the outgoing edge first met turning
// clockwise from it, which keeps to the piece on its left. The cycles do not depend on how
// the input walks were chosen or where they start.
std::vector<std::vector<point2>> link_cycles(const std::vector<const point2*>& point_of,
                                             const std::vector<std::array<std::size_t, 2>>& numbered);

// The same from the boundary's directed edges (from, to), in any order.
std::vector<std::vector<point2>> component_cycles(const std::vector<std::array<const point2*, 2>>& boundary) {
  // Every vertex numbered once, in lexicographic order (one sort of the corners; the walk
  // then runs on numbers and compares points only where the boundary touches itself).
  std::vector<const point2*> corners;
  corners.reserve(2 * boundary.size());
  for (const auto& e : boundary) {
    corners.push_back(e[0]);
    corners.push_back(e[1]);
  }
  // Compared by their truncated doubles first: GMP's conversion is monotone, so different
  // doubles order the rationals and only equal ones are compared exactly.
  std::vector<std::array<double, 2>> approx(corners.size());
  for (std::size_t k = 0; k < corners.size(); ++k) approx[k] = {(*corners[k])[0].get_d(), (*corners[k])[1].get_d()};
  const auto less = [&](std::size_t x, std::size_t y) {
    for (std::size_t i = 0; i < 2; ++i) {
      const double dx = approx[x][i], dy = approx[y][i];
      if (std::isfinite(dx) && std::isfinite(dy) && dx != dy) return dx < dy;
      const int c = cmp((*corners[x])[i], (*corners[y])[i]);
      if (c != 0) return c < 0;
    }
    return false;
  };
  std::vector<std::size_t> order(corners.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), less);
  std::vector<std::size_t> id(corners.size());
  std::vector<const point2*> point_of;
  for (auto k : order) {
    if (point_of.empty() || *point_of.back() != *corners[k]) point_of.push_back(corners[k]);
    id[k] = point_of.size() - 1;
  }
  std::vector<std::array<std::size_t, 2>> numbered(boundary.size());
  for (std::size_t e = 0; e < boundary.size(); ++e) numbered[e] = {id[2 * e], id[2 * e + 1]};
  return link_cycles(point_of, numbered);
}

// The cycles of the boundary edges `numbered` between distinct points point_of[i].
std::vector<std::vector<point2>> link_cycles(const std::vector<const point2*>& point_of,
                                             const std::vector<std::array<std::size_t, 2>>& numbered) {
  std::vector<std::vector<std::size_t>> out_edges(point_of.size());  // vertex -> targets of its outgoing edges
  std::size_t edges = 0;
  for (const auto& e : numbered) {
    out_edges[e[0]].push_back(e[1]);
    ++edges;
  }
  // Successor of the edge u -> v.
  const auto next = [&](std::size_t u, std::size_t v) -> std::size_t {
    const auto& targets = out_edges[v];
    if (targets.size() == 1) return 0;
    const point2 &pu = *point_of[u], &pv = *point_of[v];
    const point2 back{pu[0] - pv[0], pu[1] - pv[1]};
    std::size_t best = 0;
    for (std::size_t k = 1; k < targets.size(); ++k) {
      const point2 &tk = *point_of[targets[k]], &tb = *point_of[targets[best]];
      const point2 dk{tk[0] - pv[0], tk[1] - pv[1]};
      const point2 db{tb[0] - pv[0], tb[1] - pv[1]};
      if (ccw_before(back, db, dk)) best = k;  // the largest counter-clockwise angle
    }
    return best;
  };
  std::vector<std::vector<bool>> used(out_edges.size());
  for (std::size_t v = 0; v < out_edges.size(); ++v) used[v].assign(out_edges[v].size(), false);
  std::vector<std::vector<point2>> cycles;
  std::size_t walked = 0;
  for (std::size_t v0 = 0; v0 < out_edges.size(); ++v0)
    for (std::size_t k0 = 0; k0 < out_edges[v0].size(); ++k0) {
      if (used[v0][k0]) continue;
      std::vector<point2> cycle;
      std::size_t u = v0, k = k0;
      while (!used[u][k]) {
        used[u][k] = true;
        if (++walked > edges) throw internal_error("region boundary cycles do not close");
        cycle.push_back(*point_of[u]);
        const std::size_t v = out_edges[u][k];
        k = next(u, v);
        u = v;
      }
      if (u != v0 || k != k0) throw internal_error("a region boundary cycle does not return to its start");
      cycles.push_back(std::move(cycle));
    }
  return cycles;
}

std::vector<std::vector<point2>> component_cycles(const std::vector<std::vector<point2>>& walks) {
  std::vector<std::array<const point2*, 2>> boundary;
  for (const auto& w : walks)
    for (std::size_t i = 0; i < w.size(); ++i) boundary.push_back({&w[i], &w[(i + 1) % w.size()]});
  return component_cycles(boundary);
}

// The same from edges (from, to) between vertices[from] and vertices[to], distinct points.
std::vector<std::vector<point2>> component_cycles(const std::vector<std::array<std::uint32_t, 2>>& boundary,
                                                  const std::vector<const point2*>& vertices) {
  std::vector<std::uint32_t> used;
  used.reserve(2 * boundary.size());
  for (const auto& e : boundary) used.insert(used.end(), {e[0], e[1]});
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<const point2*> point_of(used.size());
  for (std::size_t i = 0; i < used.size(); ++i) point_of[i] = vertices[used[i]];
  const auto local = [&](std::uint32_t v) {
    return static_cast<std::size_t>(std::lower_bound(used.begin(), used.end(), v) - used.begin());
  };
  std::vector<std::array<std::size_t, 2>> numbered(boundary.size());
  for (std::size_t e = 0; e < boundary.size(); ++e) numbered[e] = {local(boundary[e][0]), local(boundary[e][1])};
  return link_cycles(point_of, numbered);
}

// The orientation of a boundary cycle of one connected open piece (the piece on its left, the
// cycle never crossing itself): the turn at its lexicographically smallest vertex when that
// vertex is visited once and is not straight — both edges there leave into the half-plane
// x ≥ v.x, so the turn is the cycle's orientation, as for a simple polygon — else the sign
// of the area. One orient2 instead of a sum over every vertex.
int cycle_orientation(const std::vector<point2>& c) {
  const std::size_t n = c.size();
  std::size_t m = 0, visits = 1;
  for (std::size_t i = 1; i < n; ++i) {
    if (c[i] < c[m]) {
      m = i;
      visits = 1;
    } else if (c[i] == c[m]) {
      ++visits;
    }
  }
  if (visits == 1 && n >= 3) {
    const int turn = sgn(orient2(c[(m + n - 1) % n], c[m], c[(m + 1) % n]));
    if (turn != 0) return turn;
  }
  return sgn(signed_area(c));
}

// Exact point-in-polygon by the crossing number; q must not lie on the ring's boundary.
bool inside_ring(const std::vector<point2>& ring, const point2& q) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const auto &a = ring[i], &b = ring[j];
    if (on_segment(a, b, q)) throw internal_error("a hole's test point lies on another boundary");
    if ((a[1] > q[1]) != (b[1] > q[1])) {
      const rational x = a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
      if (q[0] < x) in = !in;
    }
  }
  return in;
}

// The boundary cycles of one group of the region's connected open pieces appended to
// `grouped`: counter-clockwise ones bound polygons, clockwise ones holes, each inside the
// smallest polygon around it. Two pieces touching at a point are two polygons.
void add_group(std::vector<std::vector<point2>> cycles, std::vector<ring_with_holes>& grouped) {
  std::vector<std::vector<point2>> outers, holes;
  for (auto& cycle : cycles) {
    erase_indices(cycle, straight_vertices(cycle));
    const int orientation = cycle_orientation(cycle);
    if (orientation > 0) outers.push_back(canonical_ring(std::move(cycle)));
    else if (orientation < 0) holes.push_back(canonical_ring(std::move(cycle)));
    else throw internal_error("a region boundary encloses no area");
  }
  if (outers.empty()) throw internal_error("a region polygon has no outer boundary");
  const std::size_t first = grouped.size();
  // Areas only to tell nested pieces apart, so only when a hole has several candidates.
  std::vector<rational> outer_area;
  for (auto& o : outers) {
    if (outers.size() > 1 && !holes.empty()) outer_area.push_back(signed_area(o));
    grouped.push_back({std::move(o), {}});
  }
  for (auto& h : holes) {
    std::size_t best = 0;
    if (outer_area.size() > 1) {
      // The smallest of the polygon's pieces around the hole (a point on a hole edge is on
      // no other boundary: pieces meet only at vertices).
      const point2 q{(h[0][0] + h[1][0]) / 2, (h[0][1] + h[1][1]) / 2};
      std::ptrdiff_t found = -1;
      for (std::size_t i = 0; i < outer_area.size(); ++i)
        if ((found < 0 || outer_area[i] < outer_area[static_cast<std::size_t>(found)]) &&
            inside_ring(grouped[first + i].first, q))
          found = static_cast<std::ptrdiff_t>(i);
      if (found < 0) throw internal_error("a hole of a region lies in no polygon");
      best = static_cast<std::size_t>(found);
    }
    grouped[first + best].second.push_back(std::move(h));
  }
}

// The groups in canonical order, lifted through the chart.
std::vector<region_polygon> sorted_polygons(std::vector<ring_with_holes> grouped, const receiver_chart& chart) {
  for (auto& p : grouped) std::sort(p.second.begin(), p.second.end());
  std::sort(grouped.begin(), grouped.end());
  std::vector<region_polygon> out;
  out.reserve(grouped.size());
  for (auto& p : grouped) {
    region_polygon rp;
    rp.outer = std::move(p.first);
    rp.holes = std::move(p.second);
    for (const auto& q : rp.outer) rp.outer_3d.push_back(chart.lift(q));
    for (const auto& h : rp.holes) {
      rp.holes_3d.emplace_back();
      for (const auto& q : h) rp.holes_3d.back().push_back(chart.lift(q));
    }
    out.push_back(std::move(rp));
  }
  return out;
}

}  // namespace

std::vector<region_polygon> canonical_polygons(std::vector<ring_with_holes> polygons, const receiver_chart& chart) {
  // Each input polygon with holes is a union of the region's connected open pieces (a
  // piece's boundary never leaves the polygon it was given in), so it is re-linked and its
  // holes assigned on its own.
  std::vector<ring_with_holes> grouped;
  for (auto& p : polygons) {
    std::vector<std::vector<point2>> walks;
    walks.push_back(std::move(p.first));
    for (auto& h : p.second) walks.push_back(std::move(h));
    add_group(component_cycles(walks), grouped);
  }
  return sorted_polygons(std::move(grouped), chart);
}

std::vector<region_polygon> canonical_polygons(const std::vector<std::vector<std::array<std::uint32_t, 2>>>& pieces,
                                               const std::vector<const point2*>& vertices, const receiver_chart& chart) {
  std::vector<ring_with_holes> grouped;
  for (const auto& boundary : pieces) add_group(component_cycles(boundary, vertices), grouped);
  return sorted_polygons(std::move(grouped), chart);
}

std::vector<std::array<point2, 2>> canonical_pieces(const std::vector<std::array<point2, 2>>& pieces) {
  // Segments keyed by their supporting line: direction (1, m) with offset c = v − m u, or the
  // vertical direction (0, 1) with offset c = u; then merged along the line in order.
  struct keyed {
    bool vertical;
    rational slope, offset;
    point2 a, b;
  };
  std::vector<keyed> segs;
  std::vector<point2> pts;
  for (const auto& piece : pieces) {
    point2 a = piece[0], b = piece[1];
    if (a == b) {
      pts.push_back(a);
      continue;
    }
    if (b < a) std::swap(a, b);
    if (a[0] == b[0]) segs.push_back({true, rational(0), a[0], a, b});
    else {
      const rational m = (b[1] - a[1]) / (b[0] - a[0]);
      segs.push_back({false, m, a[1] - m * a[0], a, b});
    }
  }
  std::sort(segs.begin(), segs.end(), [](const keyed& x, const keyed& y) {
    return std::tie(x.vertical, x.slope, x.offset, x.a, x.b) < std::tie(y.vertical, y.slope, y.offset, y.a, y.b);
  });
  std::vector<std::array<point2, 2>> merged;
  for (std::size_t i = 0; i < segs.size();) {
    point2 a = segs[i].a, b = segs[i].b;
    std::size_t j = i + 1;
    for (; j < segs.size() && segs[j].vertical == segs[i].vertical && segs[j].slope == segs[i].slope &&
           segs[j].offset == segs[i].offset && !(b < segs[j].a);
         ++j)
      b = std::max(b, segs[j].b);
    merged.push_back({a, b});
    // The next run on the same line starts after a gap; on another line it starts afresh.
    i = j;
  }
  std::sort(merged.begin(), merged.end());
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  std::vector<std::array<point2, 2>> out = merged;
  for (const auto& p : pts) {
    bool covered = false;
    for (const auto& s : merged) covered = covered || on_segment(s[0], s[1], p);
    if (!covered) out.push_back({p, p});
  }
  return out;
}

}  // namespace shadowproof::detail
