#pragma once
// Exact Boolean operations on regular polygon sets in the receiver's chart: a thin wrapper
// around CGAL's Polygon_set_2 over the exact kernel, so that polygon_set.cpp is the one
// translation unit that instantiates CGAL's Boolean operations (they take long to compile).
// Rings are counter-clockwise outer boundaries and clockwise holes, in rationals.
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "polygon2.h"
#include "shadowproof/clip/shadow_region.h"

namespace shadowproof::detail {

using ring = std::vector<point2>;

class polygon_set {
 public:
  polygon_set();
  ~polygon_set();
  polygon_set(const polygon_set&);
  polygon_set& operator=(const polygon_set&);
  polygon_set(polygon_set&&) noexcept;
  polygon_set& operator=(polygon_set&&) noexcept;

  /// The closed simple polygon `outer` (counter-clockwise).
  explicit polygon_set(const ring& outer);
  /// The union of the given polygons with holes.
  explicit polygon_set(const std::vector<ring_with_holes>& polygons);

  /// this ∪= the counter-clockwise simple polygons `rings`, in one aggregated operation.
  void join(const std::vector<ring>& rings);
  /// this ∩= other.
  void intersect(const polygon_set& other);
  /// this \= other.
  void subtract(const polygon_set& other);

  bool empty() const;
  /// Exact area.
  rational area() const;
  /// Number of polygons with holes (connected pieces of the interior).
  std::size_t size() const;
  /// The polygons with holes in CGAL's order (outer counter-clockwise, holes clockwise).
  std::vector<ring_with_holes> polygons() const;
  /// Every boundary edge.
  std::vector<std::array<point2, 2>> edges() const;
  /// Position of q: outside, on the boundary, or inside.
  region_side side(const point2& q) const;

 private:
  struct impl;
  std::unique_ptr<impl> impl_;
};

}  // namespace shadowproof::detail
