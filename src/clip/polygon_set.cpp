// The one translation unit that instantiates CGAL's Boolean set operations (polygon_set.h).
#include "polygon_set.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <iterator>

#include "kernel.h"

namespace shadowproof::detail {

namespace {

using cpolygon = CGAL::Polygon_2<kernel>;
using cpolygon_wh = CGAL::Polygon_with_holes_2<kernel>;
using cset = CGAL::Polygon_set_2<kernel>;

cpolygon to_cpolygon(const ring& v) {
  cpolygon p;
  for (const auto& q : v) p.push_back(to_cpoint(q));
  return p;
}

ring to_ring(const cpolygon& p) {
  ring r;
  r.reserve(p.size());
  for (auto it = p.vertices_begin(); it != p.vertices_end(); ++it) r.push_back(to_point2(*it));
  return r;
}

}  // namespace

struct polygon_set::impl {
  cset set;
};

polygon_set::polygon_set() : impl_(std::make_unique<impl>()) {}
polygon_set::~polygon_set() = default;
polygon_set::polygon_set(const polygon_set& o) : impl_(std::make_unique<impl>(*o.impl_)) {}
polygon_set& polygon_set::operator=(const polygon_set& o) {
  if (this != &o) *impl_ = *o.impl_;
  return *this;
}
polygon_set::polygon_set(polygon_set&&) noexcept = default;
polygon_set& polygon_set::operator=(polygon_set&&) noexcept = default;

polygon_set::polygon_set(const ring& outer) : impl_(std::make_unique<impl>()) {
  impl_->set = cset(to_cpolygon(outer));
}

polygon_set::polygon_set(const std::vector<ring_with_holes>& polygons) : impl_(std::make_unique<impl>()) {
  for (const auto& p : polygons) {
    cpolygon_wh pw(to_cpolygon(p.first));
    for (const auto& h : p.second) pw.add_hole(to_cpolygon(h));
    impl_->set.join(pw);
  }
}

void polygon_set::join(const std::vector<ring>& rings) {
  if (rings.empty()) return;
  std::vector<cpolygon> pieces;
  pieces.reserve(rings.size());
  for (const auto& r : rings) pieces.push_back(to_cpolygon(r));
  impl_->set.join(pieces.begin(), pieces.end());
}

void polygon_set::intersect(const polygon_set& other) { impl_->set.intersection(other.impl_->set); }
void polygon_set::subtract(const polygon_set& other) { impl_->set.difference(other.impl_->set); }
bool polygon_set::empty() const { return impl_->set.is_empty(); }
std::size_t polygon_set::size() const { return impl_->set.number_of_polygons_with_holes(); }

std::vector<ring_with_holes> polygon_set::polygons() const {
  std::vector<cpolygon_wh> pw;
  impl_->set.polygons_with_holes(std::back_inserter(pw));
  std::vector<ring_with_holes> out;
  for (const auto& p : pw) {
    ring_with_holes r{to_ring(p.outer_boundary()), {}};
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) r.second.push_back(to_ring(*h));
    out.push_back(std::move(r));
  }
  return out;
}

rational polygon_set::area() const {
  std::vector<cpolygon_wh> pw;
  impl_->set.polygons_with_holes(std::back_inserter(pw));
  rational a = 0;
  for (const auto& p : pw) {
    a += to_q(p.outer_boundary().area());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += to_q(h->area());
  }
  return a;
}

std::vector<std::array<point2, 2>> polygon_set::edges() const {
  std::vector<cpolygon_wh> pw;
  impl_->set.polygons_with_holes(std::back_inserter(pw));
  std::vector<std::array<point2, 2>> e;
  const auto add = [&e](const cpolygon& p) {
    for (auto it = p.edges_begin(); it != p.edges_end(); ++it)
      e.push_back({to_point2(it->source()), to_point2(it->target())});
  };
  for (const auto& p : pw) {
    add(p.outer_boundary());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) add(*h);
  }
  return e;
}

region_side polygon_set::side(const point2& q) const {
  if (impl_->set.is_empty()) return region_side::outside;
  switch (impl_->set.oriented_side(to_cpoint(q))) {
    case CGAL::ON_NEGATIVE_SIDE: return region_side::outside;
    case CGAL::ON_ORIENTED_BOUNDARY: return region_side::boundary;
    default: return region_side::inside;
  }
}

}  // namespace shadowproof::detail
