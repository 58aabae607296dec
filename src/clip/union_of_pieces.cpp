// The reference region builder: the union of every clipped, projected convex piece of every
// caster face, by exact Boolean operations (builders.h). Simple and slow; the silhouette
// builder must give the identical region.
#include <algorithm>

#include "builders.h"
#include "polygon2.h"
#include "polygon_set.h"
#include "region_setup.h"

namespace shadowproof::detail {

namespace {

// Parts of the segment [a, b] (a point when a = b) whose points satisfy `keep`, where `keep`
// may only change at the intersections with `cuts`. Splits at those intersections and
// classifies every split point and every open piece between two of them by its midpoint; a
// run of kept elements is reported by its closure.
template <class Keep>
void keep_parts(const point2& a, const point2& b, const std::vector<std::array<point2, 2>>& cuts, Keep keep,
                std::vector<std::array<point2, 2>>& out) {
  if (a == b) {
    if (keep(a)) out.push_back({a, a});
    return;
  }
  // Parameter along the segment: the coordinate of largest extent.
  const bool use_u = abs(b[0] - a[0]) >= abs(b[1] - a[1]);
  auto param = [&](const point2& p) {
    return use_u ? rational((p[0] - a[0]) / (b[0] - a[0])) : rational((p[1] - a[1]) / (b[1] - a[1]));
  };
  std::vector<std::pair<rational, point2>> splits{{rational(0), a}, {rational(1), b}};
  for (const auto& c : cuts) {
    const auto x = segment_intersection(a, b, c[0], c[1]);
    if (!x) continue;
    splits.emplace_back(param((*x)[0]), (*x)[0]);
    if ((*x)[0] != (*x)[1]) splits.emplace_back(param((*x)[1]), (*x)[1]);
  }
  std::sort(splits.begin(), splits.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  splits.erase(std::unique(splits.begin(), splits.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
               splits.end());
  // Elements in order: split point 0, open piece 0, split point 1, ..., last split point.
  const std::size_t n = splits.size();
  std::vector<bool> k(2 * n - 1);
  for (std::size_t i = 0; i < n; ++i) {
    k[2 * i] = keep(splits[i].second);
    if (i + 1 < n) {
      const point2& p = splits[i].second;
      const point2& q = splits[i + 1].second;
      k[2 * i + 1] = keep(point2{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2});
    }
  }
  for (std::size_t i = 0; i < k.size();) {
    if (!k[i]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < k.size() && k[j + 1]) ++j;
    out.push_back({splits[i / 2].second, splits[(j + 1) / 2].second});
    i = j + 1;
  }
}

}  // namespace

shadow_region union_of_pieces_region(const scene& s, const plane<rational>& P, const clip_options& options) {
  validate_sizes(s, options.limits);
  case_set cases;
  const clip_setup setup = make_clip_setup(s, P, cases);
  shadow_region r = setup.empty_region();

  std::vector<std::vector<ring>> pieces(s.casters.size());
  std::vector<std::array<point2, 2>> degenerate;
  for (std::size_t ci = 0; ci < s.casters.size(); ++ci) {
    const caster& c = s.casters[ci];
    caster_sides sides;
    for (std::size_t f = 0; f < c.faces.size(); ++f) {
      for (auto i : c.faces[f]) sides.add(setup, c.vertices[i]);
      const face_geometry g = validate_face(setup, c, f, cases);
      cast_face(setup, g, cases, pieces[ci], degenerate);
    }
    sides.note(setup, cases);
  }

  // One aggregate union of every projected piece, then the receiver clip.
  std::vector<ring> all;
  for (const auto& p : pieces) all.insert(all.end(), p.begin(), p.end());
  polygon_set shadow_all;
  shadow_all.join(all);
  const rational all_area = shadow_all.area();
  if (options.detect_overlap && s.casters.size() > 1) {
    rational sum = 0;
    for (const auto& p : pieces) {
      polygon_set one;
      one.join(p);
      sum += one.area();
    }
    if (sum != all_area) cases.insert(shadow_case::shadows_overlap);
  }
  polygon_set receiver(setup.receiver_outer);
  for (const auto& h : setup.receiver_holes) {
    ring ccw = h;
    std::reverse(ccw.begin(), ccw.end());
    receiver.subtract(polygon_set(ccw));
  }
  polygon_set result = shadow_all;
  result.intersect(receiver);
  const rational area = result.area();
  if (area != all_area) cases.insert(shadow_case::shadow_outside_receiver);
  r.chart_area = area;
  r.area_squared = area * area * r.chart.area_scale_squared;
  r.polygons = canonical_polygons(result.polygons(), r.chart);

  // Zero-area pieces: what lies in the closed receiver but not in the closed regular region.
  const auto receiver_edges = receiver.edges();
  const auto result_edges = result.edges();
  std::vector<std::array<point2, 2>> cuts = receiver_edges;
  cuts.insert(cuts.end(), result_edges.begin(), result_edges.end());
  const auto keep = [&](const point2& q) {
    return receiver.side(q) != region_side::outside && result.side(q) == region_side::outside;
  };
  std::vector<std::array<point2, 2>> kept;
  for (const auto& d : degenerate) keep_parts(d[0], d[1], cuts, keep, kept);
  const std::size_t from_casters = kept.size();
  // Contacts: the regular shadow's boundary meeting the receiver's boundary outside the
  // regular result (a shadow touching the receiver at a point or along a segment).
  for (const auto& e : shadow_all.edges())
    for (const auto& re : receiver_edges)
      if (const auto x = segment_intersection(e[0], e[1], re[0], re[1]))
        keep_parts((*x)[0], (*x)[1], result_edges, keep, kept);
  if (kept.size() > from_casters) cases.insert(shadow_case::shadow_touches_receiver_boundary);

  for (const auto& k : canonical_pieces(kept))
    r.degenerate.push_back({k[0], k[1], r.chart.lift(k[0]), r.chart.lift(k[1])});
  if (!r.degenerate.empty()) cases.insert(shadow_case::degenerate_shadow);
  if (r.polygons.empty() && r.degenerate.empty()) cases.insert(shadow_case::empty);

  if (options.keep_projected) {
    for (const auto& p : canonical_polygons(shadow_all.polygons(), r.chart)) {
      r.projected_loops.push_back(p.outer);
      for (const auto& h : p.holes) r.projected_loops.push_back(h);
    }
    r.projected_degenerate = canonical_pieces(degenerate);
  }
  r.cases.assign(cases.begin(), cases.end());
  return r;
}

}  // namespace shadowproof::detail
