#pragma once
// Exact polygon utilities over rationals, shared by both region builders: orientation, area,
// repeated and straight vertices, simplicity, convex pieces, segment intersection, and the
// canonical forms that make two computations of one region compare equal.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "shadowproof/clip/shadow_region.h"

namespace shadowproof::detail {

/// (b − a) × (c − a): > 0 when a, b, c turn counter-clockwise, 0 when collinear.
rational orient2(const point2& a, const point2& b, const point2& c);

/// The sum of the terms, added pairwise in a balanced tree: rationals with unrelated
/// denominators grow with every addition, so a running sum of n terms costs O(n²) while this
/// costs O(M(N) log n) for a result of size N.
rational balanced_sum(std::vector<rational> terms);

/// Signed area of the closed polygon p (shoelace, summed by balanced_sum): > 0 counter-clockwise.
rational signed_area(const std::vector<point2>& p);

/// Index k of the largest |n_k| (the first one on ties): the chart of a plane with normal n
/// drops that coordinate.
int largest_axis(const point3& n);

/// (x_{k+1}, x_{k+2}) of p, indices mod 3.
point2 drop_axis(const point3& p, int k);

/// Normal (v1 − v0) × (vk − v0) with vk the first vertex not collinear with v0 and v1; zero
/// when every vertex is collinear.
point3 plane_normal(const std::vector<point3>& v);

/// Removes consecutive repeats, cyclically; true when one was removed.
template <class P>
bool drop_repeats(std::vector<P>& v) {
  std::vector<P> out;
  out.reserve(v.size());
  for (const auto& p : v)
    if (out.empty() || out.back() != p) out.push_back(p);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  const bool changed = out.size() != v.size();
  v = std::move(out);
  return changed;
}

/// Index of a vertex where the closed polygon c (no consecutive repeats) folds back on
/// itself: its neighbours a, d are collinear with it and it is not strictly between them, so
/// the edges into and out of it overlap. Such a polygon is not simple. nullopt when none.
std::optional<std::size_t> fold_back_vertex(const std::vector<point2>& c);

/// Indices of the straight vertices of c: strictly between their two neighbours on one line
/// (a 180° turn). Removing them does not change the region, and removing one never changes
/// whether another is straight, so the result is unique. O(n).
std::vector<std::size_t> straight_vertices(const std::vector<point2>& c);

/// Erases the entries of v at the sorted indices `at`.
template <class P>
void erase_indices(std::vector<P>& v, const std::vector<std::size_t>& at) {
  if (at.empty()) return;
  std::vector<P> out;
  out.reserve(v.size() - at.size());
  std::size_t j = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (j < at.size() && at[j] == i) {
      ++j;
      continue;
    }
    out.push_back(std::move(v[i]));
  }
  v = std::move(out);
}

/// Removes the straight vertices of c, and the same entries of the parallel array v.
template <class P>
bool drop_straight(std::vector<point2>& c, std::vector<P>& v) {
  const auto at = straight_vertices(c);
  erase_indices(c, at);
  erase_indices(v, at);
  return !at.empty();
}

/// Exact simplicity of a closed polygon without consecutive repeats: no two edges meet except
/// adjacent ones at their shared vertex. O(n²) pair tests for small n, CGAL's sweep (O(n log n))
/// above 24 vertices.
bool is_simple(const std::vector<point2>& p);

/// True when p (counter-clockwise, no straight vertices) turns left at every vertex.
bool is_convex(const std::vector<point2>& p);

/// Decomposition of a simple counter-clockwise polygon without straight vertices into convex
/// counter-clockwise pieces, as index lists into p: p itself when convex (O(n)), else Greene's
/// y-monotone partition into convex pieces (CGAL's greene_approx_convex_partition_2,
/// O(n log n)). The pieces cover p and have disjoint interiors.
std::vector<std::vector<std::size_t>> convex_pieces(const std::vector<point2>& p);

/// True when p lies on the closed segment [a, b].
bool on_segment(const point2& a, const point2& b, const point2& p);

/// The intersection of the closed segments [a, b] and [c, d] (a ≠ b, c ≠ d): none, a point
/// (returned as {p, p}) or a segment.
std::optional<std::array<point2, 2>> segment_intersection(const point2& a, const point2& b, const point2& c,
                                                          const point2& d);

/// A ring rotated to start at the rotation that is lexicographically smallest as a sequence
/// (so that two traversals of one boundary compare equal).
std::vector<point2> canonical_ring(std::vector<point2> cycle);

/// An outer ring (counter-clockwise) with its holes (clockwise).
using ring_with_holes = std::pair<std::vector<point2>, std::vector<std::vector<point2>>>;

/// A regular region's polygons with holes in canonical form, whatever boundary walks
/// described it: one polygon per connected piece of the region's interior (the boundary
/// re-linked where it touches itself so that each cycle keeps to one piece), straight
/// vertices removed, counter-clockwise cycles as polygons and clockwise ones as holes of the
/// smallest polygon around them, every ring starting at its smallest rotation, holes and
/// polygons sorted. 3D coordinates are lifted through the chart.
std::vector<region_polygon> canonical_polygons(std::vector<ring_with_holes> polygons, const receiver_chart& chart);

/// The same from the boundary of each group of pieces as directed edges (from, to) between
/// vertices[from] and vertices[to] (distinct points), with the region on their left, in any
/// order: each group a union of connected open pieces of the region (a piece's boundary in
/// one group only).
std::vector<region_polygon> canonical_polygons(const std::vector<std::vector<std::array<std::uint32_t, 2>>>& pieces,
                                               const std::vector<const point2*>& vertices, const receiver_chart& chart);

/// Zero-area pieces in canonical form: collinear segments that overlap or touch are merged
/// into maximal ones, points lying on a segment are dropped, and the rest is sorted (segments
/// (a < b) first, then points). Depends only on the union of the input as a point set.
std::vector<std::array<point2, 2>> canonical_pieces(const std::vector<std::array<point2, 2>>& pieces);

}  // namespace shadowproof::detail
