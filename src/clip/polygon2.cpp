// Exact polygon utilities over rationals (see polygon2.h).
#include "polygon2.h"

#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/partition_2.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <iterator>
#include <list>
#include <map>
#include <tuple>

#include "kernel.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/vec3.h"

namespace shadowproof::detail {

rational orient2(const point2& a, const point2& b, const point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

rational signed_area(const std::vector<point2>& p) {
  rational s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return s / 2;
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
    if (sgn(orient2(a, b, d)) == 0 && sgn(forward(a, b, d)) > 0) out.push_back(i);
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
    std::vector<point2> ring;
    for (auto i : out.back()) ring.push_back(p[i]);
    if (sgn(signed_area(ring)) < 0) std::reverse(out.back().begin(), out.back().end());
    if (sgn(signed_area(ring)) == 0) throw internal_error("convex partition produced a piece without area");
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

std::vector<point2> canonical_ring(std::vector<point2> ring) {
  const std::size_t n = ring.size();
  std::size_t best = 0;
  for (std::size_t s = 1; s < n; ++s) {
    // Compare the rotations starting at s and at best, element by element.
    for (std::size_t i = 0; i < n; ++i) {
      const auto& x = ring[(s + i) % n];
      const auto& y = ring[(best + i) % n];
      if (x < y) {
        best = s;
        break;
      }
      if (y < x) break;
    }
  }
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(best), ring.end());
  return ring;
}

std::vector<region_polygon> canonical_polygons(
    std::vector<std::pair<std::vector<point2>, std::vector<std::vector<point2>>>> polygons,
    const receiver_chart& chart) {
  auto clean = [](std::vector<point2> ring) {
    erase_indices(ring, straight_vertices(ring));
    return canonical_ring(std::move(ring));
  };
  for (auto& p : polygons) {
    p.first = clean(std::move(p.first));
    for (auto& h : p.second) h = clean(std::move(h));
    std::sort(p.second.begin(), p.second.end());
  }
  std::sort(polygons.begin(), polygons.end());
  std::vector<region_polygon> out;
  out.reserve(polygons.size());
  for (auto& p : polygons) {
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
