#pragma once
// An exact sweep over weighted chart segments (planar_sweep.cpp): every crossing and every
// touching computed once, the segments split there into edges that meet only at their ends,
// overlapping pieces merged with their weights added, and the winding numbers on both sides
// of every edge carried across the sweep line. What the silhouette builder needs of an
// arrangement, without building one.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "shadowproof/clip/shadow_region.h"

namespace shadowproof::detail {

/// A directed segment points[a] → points[b] of an input to planar_sweep. Crossing it from its
/// right to its left adds `shadow` to the shadow winding and `receiver` to the receiver's;
/// `degenerate` marks a zero-area shadow piece (both weights 0).
struct sweep_segment {
  std::size_t a = 0, b = 0;
  long shadow = 0, receiver = 0;
  bool degenerate = false;
};

/// Windings of a face: the shadow's and the receiver's.
using windings = std::array<long, 2>;

/// The planar subdivision of a set of weighted segments.
struct planar_map {
  /// Every distinct endpoint and crossing, in lexicographic (x, then y) order.
  std::vector<const point2*> vertices;
  /// An edge from vertices[lo] to vertices[hi] (lo < hi, so it runs left to right, or
  /// upwards when vertical); edges meet only at their ends. Its weights are counted along
  /// lo → hi; `below` is the winding of the face on its right (below it), the face on its
  /// left has below + weights.
  struct edge {
    std::uint32_t lo = 0, hi = 0;
    windings weight{}, below{};
    bool degenerate = false;
    windings above() const { return {below[0] + weight[0], below[1] + weight[1]}; }
  };
  std::vector<edge> edges;
  /// Pairs (lower, upper) of edges that were next to each other on the sweep line: the face
  /// between them has the windings lower.above(). Two edges bound a common face iff they are
  /// joined by a path of such pairs through that face's windings.
  std::vector<std::array<std::uint32_t, 2>> adjacent;
  /// Per vertex: an isolated input point (a zero-area shadow piece) is there.
  std::vector<char> point_piece;
  /// Per vertex without edges that is a point piece: the windings of the face containing it.
  std::vector<windings> isolated;
  std::size_t crossings = 0;  ///< proper crossings computed
  std::vector<point2> owned;  ///< the crossing points (vertices point into it or into the input)
};

/// The planar map of `segments` (endpoints *points[a], *points[b]; zero-length ones ignored)
/// and of the isolated points *points[i] for i in `point_pieces`. Predicates on interval filters,
/// exact rationals when a filter cannot decide; crossings by Cramer's rule on the integer
/// coefficients of the two lines. O((n + k) log n) for n segments with k crossings when the
/// segments are short next to the spread of the input; nullopt (nothing computed) when
/// candidate pairs of segments exceed a budget linear in n (long overlapping segments) or a
/// coordinate lies outside the filter's range (magnitude beyond 2^±400): the caller then
/// uses an arrangement.
std::optional<planar_map> planar_sweep(const std::vector<const point2*>& points, const std::vector<sweep_segment>& segments,
                                       const std::vector<std::size_t>& point_pieces);

}  // namespace shadowproof::detail
