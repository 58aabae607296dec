// The exact shadow region: 3D clipping and projection over rationals, then CGAL's exact
// Boolean set operations in the receiver's chart. The only file that includes CGAL's
// Boolean_set_operations_2.
#include "shadowproof/clip/shadow_region.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Cartesian.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <type_traits>

#include "shadowproof/core/error.h"
#include "shadowproof/core/homogeneous.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof {

namespace {

// The exact kernel. Epeck (lazy exact with interval filters) was measured against
// Cartesian<mpq_class> on the 10k-triangle sphere benchmark and is faster (see
// the README's clipping section); SHADOWPROOF_CLIP_CARTESIAN_GMPQ switches to the other one.
#ifdef SHADOWPROOF_CLIP_CARTESIAN_GMPQ
using kernel = CGAL::Cartesian<mpq_class>;
#else
using kernel = CGAL::Exact_predicates_exact_constructions_kernel;
#endif
using ft = kernel::FT;
using cpoint = kernel::Point_2;
using csegment = kernel::Segment_2;
using cpolygon = CGAL::Polygon_2<kernel>;
using cpolygon_wh = CGAL::Polygon_with_holes_2<kernel>;
using cset = CGAL::Polygon_set_2<kernel>;

// Conversions between rational and the kernel's field type, whichever exact type it wraps.
template <class F>
F to_field(const rational& q) {
  if constexpr (std::is_same_v<F, rational>) {
    return q;
  } else {
    using et = typename F::ET;
    if constexpr (std::is_same_v<et, rational>) return F(q);
    else return F(et(q.get_mpq_t()));
  }
}

template <class F>
rational from_field(const F& x) {
  if constexpr (std::is_same_v<F, rational>) {
    return x;
  } else {
    using et = std::decay_t<decltype(CGAL::exact(x))>;
    if constexpr (std::is_same_v<et, rational>) return CGAL::exact(x);
    else return rational(CGAL::exact(x).mpq());
  }
}

ft to_ft(const rational& q) { return to_field<ft>(q); }
rational to_q(const ft& x) { return from_field<ft>(x); }

cpoint to_cpoint(const point2& p) { return cpoint(to_ft(p[0]), to_ft(p[1])); }
point2 to_point2(const cpoint& p) { return {to_q(p.x()), to_q(p.y())}; }

// --- small exact 2D/3D algebra ------------------------------------------------------------

point3 sub3(const point3& a, const point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
point3 cross3(const point3& a, const point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
rational dot33(const point3& a, const point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero3(const point3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

// Orientation of (a, b, c): > 0 counter-clockwise.
rational orient2(const point2& a, const point2& b, const point2& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

rational signed_area2(const std::vector<point2>& p) {
  rational s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return s / 2;
}

// Normal of the plane through v0, v1 and the first vertex vk not collinear with them:
// (v1 − v0) × (vk − v0); zero when every vertex is collinear. Planarity is then checked
// vertex by vertex, so an error can name the first vertex off that plane.
point3 plane_normal(const std::vector<point3>& v) {
  for (std::size_t k = 2; k < v.size(); ++k) {
    const point3 c = cross3(sub3(v[1], v[0]), sub3(v[k], v[0]));
    if (!is_zero3(c)) return c;
  }
  return {rational(0), rational(0), rational(0)};
}

int largest_axis(const rational& a, const rational& b, const rational& c) {
  const rational aa = abs(a), ab = abs(b), ac = abs(c);
  if (aa >= ab && aa >= ac) return 0;
  if (ab >= ac) return 1;
  return 2;
}

point2 drop_axis(const point3& p, int k) { return {p[(k + 1) % 3], p[(k + 2) % 3]}; }

// Removes consecutive repeats (cyclically); reports whether any was removed.
template <class P>
bool drop_repeats(std::vector<P>& v) {
  std::vector<P> out;
  for (const auto& p : v)
    if (out.empty() || out.back() != p) out.push_back(p);
  while (out.size() > 1 && out.front() == out.back()) out.pop_back();
  const bool changed = out.size() != v.size();
  v = std::move(out);
  return changed;
}

// Removes vertices lying on the line through their neighbours (in chart coordinates `c`,
// keeping `v` parallel to it); reports whether any was removed.
template <class P>
bool drop_collinear(std::vector<point2>& c, std::vector<P>& v) {
  bool changed = false;
  bool again = true;
  while (again && c.size() >= 3) {
    again = false;
    for (std::size_t i = 0; i < c.size() && c.size() >= 3; ++i) {
      const std::size_t n = c.size();
      const auto& a = c[(i + n - 1) % n];
      const auto& b = c[i];
      const auto& d = c[(i + 1) % n];
      if (sgn(orient2(a, b, d)) == 0) {
        c.erase(c.begin() + static_cast<std::ptrdiff_t>(i));
        v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
        changed = again = true;
        break;
      }
    }
  }
  return changed;
}

// Strict segment intersection test for the simplicity check of small polygons.
bool on_segment(const point2& a, const point2& b, const point2& p) {
  return sgn(orient2(a, b, p)) == 0 && std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) &&
         std::min(a[1], b[1]) <= p[1] && p[1] <= std::max(a[1], b[1]);
}
bool segments_meet(const point2& a, const point2& b, const point2& c, const point2& d) {
  const int o1 = sgn(orient2(a, b, c)), o2 = sgn(orient2(a, b, d));
  const int o3 = sgn(orient2(c, d, a)), o4 = sgn(orient2(c, d, b));
  if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

// Exact simplicity of a closed polygon without repeated consecutive vertices.
bool is_simple(const std::vector<point2>& p) {
  if (p.size() < 3) return false;
  if (p.size() > 24) {
    cpolygon poly;
    for (const auto& q : p) poly.push_back(to_cpoint(q));
    return poly.is_simple();
  }
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const auto &a = p[i], &b = p[(i + 1) % n], &c = p[j], &d = p[(j + 1) % n];
      if (adjacent) {
        // Adjacent edges may only share their common vertex: fold-backs overlap.
        const point2& shared = (j == i + 1) ? b : a;
        const point2& other_i = (j == i + 1) ? a : b;
        const point2& other_j = (j == i + 1) ? d : c;
        if (sgn(orient2(other_i, shared, other_j)) == 0) {
          // Collinear neighbours: simple only when they go on in the same direction.
          const rational dot = (shared[0] - other_i[0]) * (other_j[0] - shared[0]) +
                               (shared[1] - other_i[1]) * (other_j[1] - shared[1]);
          if (sgn(dot) <= 0) return false;
        }
        continue;
      }
      if (segments_meet(a, b, c, d)) return false;
    }
  return true;
}

// Ear clipping of a simple counter-clockwise polygon without collinear consecutive vertices.
// Returns index triples into `p`.
std::vector<std::array<std::size_t, 3>> triangulate(const std::vector<point2>& p) {
  std::vector<std::array<std::size_t, 3>> out;
  std::vector<std::size_t> idx(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) idx[i] = i;
  std::size_t start = 0;
  while (idx.size() > 3) {
    const std::size_t n = idx.size();
    bool found = false;
    for (std::size_t step = 0; step < n && !found; ++step) {
      const std::size_t i = (start + step) % n;
      const std::size_t ia = idx[(i + n - 1) % n], ib = idx[i], ic = idx[(i + 1) % n];
      if (sgn(orient2(p[ia], p[ib], p[ic])) <= 0) continue;
      bool empty = true;
      for (std::size_t j = 0; j < n && empty; ++j) {
        const std::size_t q = idx[j];
        if (q == ia || q == ib || q == ic) continue;
        if (sgn(orient2(p[ia], p[ib], p[q])) >= 0 && sgn(orient2(p[ib], p[ic], p[q])) >= 0 &&
            sgn(orient2(p[ic], p[ia], p[q])) >= 0)
          empty = false;
      }
      if (!empty) continue;
      out.push_back({ia, ib, ic});
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(i));
      start = i == 0 ? 0 : i - 1;
      found = true;
    }
    if (!found) {
      // Only a 180° vertex left between collinear neighbours can block every ear; dropping
      // it keeps the region.
      bool dropped = false;
      for (std::size_t i = 0; i < n && !dropped; ++i)
        if (sgn(orient2(p[idx[(i + n - 1) % n]], p[idx[i]], p[idx[(i + 1) % n]])) == 0) {
          idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(i));
          dropped = true;
        }
      if (!dropped) throw internal_error("ear clipping found no ear");
    }
  }
  if (idx.size() == 3 && sgn(orient2(p[idx[0]], p[idx[1]], p[idx[2]])) > 0)
    out.push_back({idx[0], idx[1], idx[2]});
  return out;
}

cset make_set(const std::vector<cpolygon>& pieces) {
  cset s;
  if (!pieces.empty()) s.join(pieces.begin(), pieces.end());
  return s;
}

rational set_area(const cset& s) {
  std::vector<cpolygon_wh> pw;
  s.polygons_with_holes(std::back_inserter(pw));
  rational a = 0;
  for (const auto& p : pw) {
    a += to_q(p.outer_boundary().area());
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) a += to_q(h->area());
  }
  return a;
}

std::vector<csegment> set_edges(const cset& s) {
  std::vector<cpolygon_wh> pw;
  s.polygons_with_holes(std::back_inserter(pw));
  std::vector<csegment> e;
  for (const auto& p : pw) {
    for (auto it = p.outer_boundary().edges_begin(); it != p.outer_boundary().edges_end(); ++it)
      e.push_back(*it);
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h)
      for (auto it = h->edges_begin(); it != h->edges_end(); ++it) e.push_back(*it);
  }
  return e;
}

// Parts of the segment [a, b] (a point when a = b) whose points satisfy `keep`, where `keep`
// may only change at the intersections with `cuts`. Splits at those intersections and
// classifies every split point and every open piece between two of them by its midpoint.
template <class Keep>
void keep_parts(const cpoint& a, const cpoint& b, const std::vector<csegment>& cuts, Keep keep,
                std::vector<std::array<cpoint, 2>>& out) {
  if (a == b) {
    if (keep(a)) out.push_back({a, a});
    return;
  }
  const csegment s(a, b);
  // Parameters along the segment, as the coordinate of largest extent.
  const bool use_x = CGAL::abs(b.x() - a.x()) >= CGAL::abs(b.y() - a.y());
  auto param = [&](const cpoint& p) { return use_x ? (p.x() - a.x()) / (b.x() - a.x())
                                                   : (p.y() - a.y()) / (b.y() - a.y()); };
  std::vector<std::pair<ft, cpoint>> splits{{ft(0), a}, {ft(1), b}};
  for (const auto& c : cuts) {
    if (!CGAL::do_intersect(s, c)) continue;
    const auto x = CGAL::intersection(s, c);
    if (!x) continue;
    if (const cpoint* p = boost::get<cpoint>(&*x)) {
      splits.emplace_back(param(*p), *p);
    } else if (const csegment* q = boost::get<csegment>(&*x)) {
      splits.emplace_back(param(q->source()), q->source());
      splits.emplace_back(param(q->target()), q->target());
    }
  }
  std::sort(splits.begin(), splits.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  splits.erase(std::unique(splits.begin(), splits.end(),
                           [](const auto& x, const auto& y) { return x.first == y.first; }),
               splits.end());
  // Elements in order: split point 0, midpoint 0, split point 1, ..., last split point.
  // A run of kept elements is reported by its closure (from the split point at or before
  // its first element to the one at or after its last).
  const std::size_t n = splits.size();
  std::vector<bool> k(2 * n - 1);
  for (std::size_t i = 0; i < n; ++i) {
    k[2 * i] = keep(splits[i].second);
    if (i + 1 < n) k[2 * i + 1] = keep(CGAL::midpoint(splits[i].second, splits[i + 1].second));
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

cpolygon to_cpolygon(const std::vector<point2>& v) {
  cpolygon p;
  for (const auto& q : v) p.push_back(to_cpoint(q));
  return p;
}

// --- the pipeline -------------------------------------------------------------------------

class region_builder {
 public:
  region_builder(const scene& s, const plane<rational>& P, const clip_options& o)
      : scene_(s), P_(P), options_(o) {}

  shadow_region run();

 private:
  void validate_sizes();
  void build_receiver();
  void prepare_clip();
  void process_caster(std::size_t ci);
  void process_triangle(const std::array<point3, 3>& tri, bool edge_on, std::size_t ci);
  std::vector<point3> clip_to_halfspace(const std::vector<point3>& poly, const vec4<rational>& h) const;
  void add_projected(std::vector<point2> pts, std::size_t ci);
  point2 project(const point3& V) const;
  rational clip_value(const vec4<rational>& h, const point3& V) const {
    return h[0] * V[0] + h[1] * V[1] + h[2] * V[2] + h[3];
  }
  void note(shadow_case c) { cases_.insert(c); }
  std::string face_name(const caster& c, std::size_t f) const {
    return c.is_polygon ? c.name : c.name + "/faces/" + std::to_string(f);
  }

  const scene& scene_;
  plane<rational> P_;
  clip_options options_;
  shadow_region r_;
  std::set<shadow_case> cases_;
  cset receiver_;
  std::vector<csegment> receiver_edges_;
  rational s_;                             // P·L
  std::vector<vec4<rational>> halfspaces_; // h·(V,1) ≥ 0 keeps the part that can cast
  vec4<rational> height_;                  // f(V): 0 on P, 1 at a point light's height
  std::vector<std::vector<cpolygon>> pieces_;  // per caster
  std::vector<std::array<point2, 2>> degenerate_;  // projected zero-area pieces
};

point2 region_builder::project(const point3& V) const {
  // Shadow matrix image M V = (P·L) V − (P·V) L, then the chart of its affine part.
  const auto& L = scene_.light_source.l;
  const rational t = P_.a() * V[0] + P_.b() * V[1] + P_.c() * V[2] + P_.d();
  const int k = r_.chart.dropped_axis;
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const rational w = s_ - t * L[3];
  return {(s_ * V[i] - t * L[i]) / w, (s_ * V[j] - t * L[j]) / w};
}

void region_builder::validate_sizes() {
  std::size_t nv = 0, nf = 0;
  const auto& lim = options_.limits;
  for (const auto& c : scene_.casters) {
    nv += c.vertices.size();
    nf += c.faces.size();
    for (std::size_t f = 0; f < c.faces.size(); ++f) {
      if (c.faces[f].size() > lim.max_face_vertices)
        throw error(errc::scene_too_large, face_name(c, f) + " has " + std::to_string(c.faces[f].size()) +
                                           " vertices; at most " + std::to_string(lim.max_face_vertices) + " (raise it with --max-face-vertices)" +
                                           " per face");
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
      throw error(errc::scene_too_large, name + " has " + std::to_string(p.vertices.size()) +
                                         " vertices; at most " + std::to_string(lim.max_face_vertices) + " (raise it with --max-face-vertices)");
  };
  check_ring(scene_.receiver.outer, "/receiver/polygon");
  for (std::size_t h = 0; h < scene_.receiver.holes.size(); ++h)
    check_ring(scene_.receiver.holes[h], "/receiver/holes/" + std::to_string(h));
}

// Validates one receiver ring and returns it in the chart, counter-clockwise.
std::vector<point2> chart_ring(const polygon3& ring, const std::string& name, const plane<rational>& P,
                               int k) {
  std::vector<point3> v = ring.vertices;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (sgn(P.a() * v[i][0] + P.b() * v[i][1] + P.c() * v[i][2] + P.d()) != 0)
      throw error(errc::scene_receiver_not_planar,
                  name + "/" + std::to_string(i) + " is not in the plane of the receiver");
  drop_repeats(v);
  if (v.size() < 3)
    throw error(errc::scene_empty_polygon, name + " needs at least 3 distinct vertices");
  std::vector<point2> c;
  for (const auto& p : v) c.push_back(drop_axis(p, k));
  drop_collinear(c, v);
  if (c.size() < 3)
    throw error(errc::scene_empty_polygon, name + " has zero area (its vertices are collinear)");
  if (!is_simple(c))
    throw error(errc::scene_self_intersecting, name + " is not a simple polygon (its edges cross or touch)");
  if (sgn(signed_area2(c)) < 0) std::reverse(c.begin(), c.end());
  return c;
}

void region_builder::build_receiver() {
  const point3 n{P_.a(), P_.b(), P_.c()};
  const int k = largest_axis(n[0], n[1], n[2]);
  r_.chart.receiver_plane = P_;
  r_.chart.dropped_axis = k;
  r_.chart.area_scale_squared = dot33(n, n) / (n[k] * n[k]);

  r_.receiver_outer = chart_ring(scene_.receiver.outer, "/receiver/polygon", P_, k);
  receiver_ = cset(to_cpolygon(r_.receiver_outer));
  for (std::size_t h = 0; h < scene_.receiver.holes.size(); ++h) {
    const std::string name = "/receiver/holes/" + std::to_string(h);
    auto ring = chart_ring(scene_.receiver.holes[h], name, P_, k);
    const cpolygon hp = to_cpolygon(ring);
    cset inside(hp);
    inside.difference(cpolygon(to_cpolygon(r_.receiver_outer)));
    if (!inside.is_empty())
      throw error(errc::scene_hole_outside_receiver, name + " is not inside /receiver/polygon");
    receiver_.difference(hp);
    std::reverse(ring.begin(), ring.end());
    r_.receiver_holes.push_back(ring);
  }
  if (receiver_.is_empty())
    throw error(errc::scene_empty_polygon, "the holes cover the whole receiver");
  receiver_edges_ = set_edges(receiver_);

  // View box: the receiver's bounding box enlarged by a quarter of its larger side, so the
  // box's own edges never touch the receiver (they would fake boundary contacts).
  rational umin = r_.receiver_outer[0][0], umax = umin, vmin = r_.receiver_outer[0][1], vmax = vmin;
  for (const auto& p : r_.receiver_outer) {
    umin = std::min(umin, p[0]); umax = std::max(umax, p[0]);
    vmin = std::min(vmin, p[1]); vmax = std::max(vmax, p[1]);
  }
  const rational m = std::max(umax - umin, vmax - vmin) / 4;
  r_.view_box = {umin - m, vmin - m, umax + m, vmax + m};
}

void region_builder::prepare_clip() {
  const auto& L = scene_.light_source.l;
  s_ = dot(P_.p, L);
  if (sgn(s_) == 0) {
    note(scene_.light_source.is_directional() ? shadow_case::light_parallel : shadow_case::light_on_plane);
    return;
  }
  // f(V) = w (P·V) / s for a point light (0 on P, 1 at the light's height) and (P·V) / s for
  // a directional light (grows towards the light).
  const rational scale = scene_.light_source.is_directional() ? rational(1) / s_ : L[3] / s_;
  height_ = scale * P_.p;
  halfspaces_.push_back(height_);  // f ≥ 0: the light's side of P, P itself included
  // Cone of the light over the view box: for each box edge (A, B) the plane through A, B and
  // L, i.e. Π·V = det[A; B; L; V], oriented to be positive at the box centre.
  const auto& b = r_.view_box;
  const std::array<point2, 4> box{{{b[0], b[1]}, {b[2], b[1]}, {b[2], b[3]}, {b[0], b[3]}}};
  const point3 centre = r_.chart.lift({(b[0] + b[2]) / 2, (b[1] + b[3]) / 2});
  for (std::size_t e = 0; e < 4; ++e) {
    const point3 A = r_.chart.lift(box[e]);
    const point3 B = r_.chart.lift(box[(e + 1) % 4]);
    vec4<rational> pi;
    for (std::size_t c = 0; c < 4; ++c) {
      mat4<rational> m;
      for (std::size_t j = 0; j < 3; ++j) {
        m(0, j) = A[j];
        m(1, j) = B[j];
      }
      m(0, 3) = 1;
      m(1, 3) = 1;
      for (std::size_t j = 0; j < 4; ++j) m(2, j) = L[j];
      m(3, c) = 1;
      pi[c] = determinant(m);
    }
    if (sgn(clip_value(pi, centre)) < 0) pi = rational(-1) * pi;
    halfspaces_.push_back(pi);
  }
}

void region_builder::add_projected(std::vector<point2> pts, std::size_t ci) {
  drop_repeats(pts);
  if (pts.size() >= 3 && sgn(signed_area2(pts)) != 0) {
    std::vector<point2> unused = pts;
    drop_collinear(pts, unused);
    // The projection of a convex piece is convex (the denominator keeps its sign inside the
    // clipped region), so it is a valid simple polygon once oriented.
    if (sgn(signed_area2(pts)) < 0) std::reverse(pts.begin(), pts.end());
    pieces_[ci].push_back(to_cpolygon(pts));
    return;
  }
  if (pts.empty()) return;
  // Zero area: the points are collinear; keep the two extreme ones.
  auto lo = pts[0], hi = pts[0];
  for (const auto& p : pts) {
    if (p < lo) lo = p;
    if (hi < p) hi = p;
  }
  degenerate_.push_back({lo, hi});
}

// Sutherland–Hodgman against one half-space h(X) ≥ 0, exactly: the part of the convex polygon
// `poly` (in 3D) that h keeps, with the crossing points of its edges computed over rationals.
std::vector<point3> region_builder::clip_to_halfspace(const std::vector<point3>& poly, const vec4<rational>& h) const {
  std::vector<point3> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const point3& a = poly[i];
    const point3& b = poly[(i + 1) % poly.size()];
    const rational ha = clip_value(h, a), hb = clip_value(h, b);
    if (sgn(ha) >= 0) out.push_back(a);
    if (sgn(ha) * sgn(hb) < 0) {
      const rational u = ha / (ha - hb);
      out.push_back({a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2])});
    }
  }
  return out;
}

void region_builder::process_triangle(const std::array<point3, 3>& tri, bool edge_on, std::size_t ci) {
  std::vector<point3> poly(tri.begin(), tri.end());
  if (sgn(s_) == 0) {
    // Grazing light: only the part of the caster lying in P shades (its own footprint).
    const vec4<rational> up = P_.p;
    const vec4<rational> down = rational(-1) * P_.p;
    for (const auto& h : {up, down}) {
      poly = clip_to_halfspace(poly, h);
      if (poly.empty()) return;
    }
    std::vector<point2> pts;
    for (const auto& p : poly) pts.push_back(drop_axis(p, r_.chart.dropped_axis));
    add_projected(pts, ci);
    return;
  }
  for (const auto& h : halfspaces_) {
    poly = clip_to_halfspace(poly, h);
    if (poly.empty()) return;
  }
  if (edge_on) note(shadow_case::caster_edge_on);
  // A point light on the piece (only possible at the cone's apex, f = 1) projects nowhere;
  // the rays through it are covered by the piece's other boundary points, which project to
  // the same line (the piece's plane then contains the light), so the light is left out.
  std::vector<point2> pts;
  bool contains_light = false;
  for (const auto& p : poly) {
    if (scene_.light_source.is_point() && clip_value(height_, p) == 1) {
      contains_light = true;
      continue;
    }
    pts.push_back(project(p));
  }
  if (contains_light) note(shadow_case::caster_contains_light);
  add_projected(pts, ci);
}

void region_builder::process_caster(std::size_t ci) {
  const caster& c = scene_.casters[ci];
  const auto& L = scene_.light_source.l;
  // Which side of P each vertex used by a face lies on (for the named cases).
  const int light_side = scene_.light_source.is_directional() ? sgn(s_) : sgn(s_) * sgn(L[3]);
  bool any_front = false, any_back = false, any_on = false, any_high = false;
  for (std::size_t f = 0; f < c.faces.size(); ++f) {
    const std::string name = face_name(c, f);
    std::vector<point3> v;
    for (auto i : c.faces[f]) v.push_back(c.vertices[i]);
    if (v.empty()) throw error(errc::scene_empty_polygon, name + " has no vertices");
    for (const auto& p : v) {
      const rational t = P_.a() * p[0] + P_.b() * p[1] + P_.c() * p[2] + P_.d();
      const int side = sgn(t) * (light_side == 0 ? 1 : light_side);
      if (sgn(t) == 0) any_on = true;
      else if (side > 0) any_front = true;
      else any_back = true;
      if (sgn(s_) != 0 && scene_.light_source.is_point() && clip_value(height_, p) >= 1) any_high = true;
    }
    const std::vector<point3> given = v;
    if (drop_repeats(v)) note(shadow_case::coincident_vertices);
    const point3 n = plane_normal(v);
    if (v.size() < 3 || is_zero3(n)) {
      // Collinear (or a single point): check it really is, then cast it as a segment.
      for (std::size_t i = 2; i < v.size(); ++i)
        if (!is_zero3(cross3(sub3(v[1], v[0]), sub3(v[i], v[0]))))
          throw internal_error(name + ": inconsistent collinearity test");
      if (v.size() >= 3) note(shadow_case::collinear_vertices);
      // The degenerate triangle (lo, hi, hi) clips and projects like any other.
      point3 lo = v[0], hi = v[0];
      for (const auto& p : v) {
        if (p < lo) lo = p;
        if (hi < p) hi = p;
      }
      process_triangle({lo, hi, hi}, false, ci);
      continue;
    }
    const rational dn = -dot33(n, v[0]);
    for (std::size_t i = 0; i < given.size(); ++i)
      if (sgn(dot33(n, given[i]) + dn) != 0)
        throw error(errc::scene_caster_not_planar,
                    name + ": vertex " + std::to_string(c.faces[f][i]) +
                        " is not in the plane of the face's other vertices");
    bool in_plane = true;
    for (const auto& p : v)
      if (sgn(P_.a() * p[0] + P_.b() * p[1] + P_.c() * p[2] + P_.d()) != 0) in_plane = false;
    if (in_plane) note(shadow_case::caster_in_receiver_plane);
    const int k = largest_axis(n[0], n[1], n[2]);
    std::vector<point2> chart;
    for (const auto& p : v) chart.push_back(drop_axis(p, k));
    if (drop_collinear(chart, v)) note(shadow_case::collinear_vertices);
    if (!is_simple(chart))
      throw error(errc::scene_self_intersecting, name + " is not a simple polygon (its edges cross or touch)");
    if (sgn(signed_area2(chart)) < 0) {
      std::reverse(chart.begin(), chart.end());
      std::reverse(v.begin(), v.end());
    }
    // The face's plane contains the light: its shadow has no area.
    const bool edge_on = sgn(n[0] * L[0] + n[1] * L[1] + n[2] * L[2] + dn * L[3]) == 0;
    if (v.size() == 3) {
      process_triangle({v[0], v[1], v[2]}, edge_on, ci);
    } else {
      for (const auto& t : triangulate(chart)) process_triangle({v[t[0]], v[t[1]], v[t[2]]}, edge_on, ci);
    }
  }
  if (sgn(s_) != 0) {
    if (any_front && any_back) note(shadow_case::caster_crosses_receiver);
    if (!any_front && !any_on && any_back) note(shadow_case::caster_behind_receiver);
    if (any_on && any_front && !any_back) note(shadow_case::caster_touches_receiver);
    if (any_high) note(shadow_case::caster_reaches_light_height);
  }
}

shadow_region region_builder::run() {
  validate_sizes();
  r_.light = scene_.light_source.l;
  build_receiver();
  prepare_clip();
  pieces_.resize(scene_.casters.size());
  for (std::size_t ci = 0; ci < scene_.casters.size(); ++ci) process_caster(ci);

  // One aggregate union of every projected piece, then the receiver clip.
  std::vector<cpolygon> all;
  for (const auto& p : pieces_) all.insert(all.end(), p.begin(), p.end());
  cset shadow_all = make_set(all);
  const rational all_area = set_area(shadow_all);
  if (options_.detect_overlap && scene_.casters.size() > 1) {
    rational sum = 0;
    for (const auto& p : pieces_) sum += set_area(make_set(p));
    if (sum != all_area) note(shadow_case::shadows_overlap);
  }
  cset result = shadow_all;
  result.intersection(receiver_);
  const rational area = set_area(result);
  if (area != all_area) note(shadow_case::shadow_outside_receiver);
  r_.chart_area = area;
  r_.area_squared = area * area * r_.chart.area_scale_squared;

  std::vector<cpolygon_wh> pw;
  result.polygons_with_holes(std::back_inserter(pw));
  for (const auto& p : pw) {
    region_polygon rp;
    for (auto it = p.outer_boundary().vertices_begin(); it != p.outer_boundary().vertices_end(); ++it)
      rp.outer.push_back(to_point2(*it));
    for (auto h = p.holes_begin(); h != p.holes_end(); ++h) {
      rp.holes.emplace_back();
      for (auto it = h->vertices_begin(); it != h->vertices_end(); ++it) rp.holes.back().push_back(to_point2(*it));
    }
    // Arrangement vertices of degree two where pieces met in a straight line are not corners.
    std::vector<point2> unused = rp.outer;
    drop_collinear(rp.outer, unused);
    for (auto& h : rp.holes) {
      unused = h;
      drop_collinear(h, unused);
    }
    for (const auto& q : rp.outer) rp.outer_3d.push_back(r_.chart.lift(q));
    for (const auto& h : rp.holes) {
      rp.holes_3d.emplace_back();
      for (const auto& q : h) rp.holes_3d.back().push_back(r_.chart.lift(q));
    }
    r_.polygons.push_back(std::move(rp));
  }

  // Zero-area pieces: what lies in the closed receiver but not in the closed regular region.
  const std::vector<csegment> result_edges = set_edges(result);
  std::vector<csegment> cuts = receiver_edges_;
  cuts.insert(cuts.end(), result_edges.begin(), result_edges.end());
  const auto keep = [&](const cpoint& q) {
    return receiver_.oriented_side(q) != CGAL::ON_NEGATIVE_SIDE &&
           (result.is_empty() || result.oriented_side(q) == CGAL::ON_NEGATIVE_SIDE);
  };
  std::vector<std::array<cpoint, 2>> kept;
  for (const auto& d : degenerate_) keep_parts(to_cpoint(d[0]), to_cpoint(d[1]), cuts, keep, kept);
  const std::size_t from_casters = kept.size();
  // Contacts: the regular shadow's boundary meeting the receiver's boundary outside the
  // regular result (a shadow touching the receiver at a point or along a segment).
  const std::vector<csegment> shadow_edges = set_edges(shadow_all);
  for (const auto& e : shadow_edges)
    for (const auto& re : receiver_edges_) {
      if (!CGAL::do_intersect(e, re)) continue;
      const auto x = CGAL::intersection(e, re);
      if (!x) continue;
      if (const cpoint* p = boost::get<cpoint>(&*x)) keep_parts(*p, *p, result_edges, keep, kept);
      else if (const csegment* q = boost::get<csegment>(&*x))
        keep_parts(q->source(), q->target(), result_edges, keep, kept);
    }
  if (kept.size() > from_casters) note(shadow_case::shadow_touches_receiver_boundary);

  // Collinear segments that overlap or touch are merged; points on a kept segment say
  // nothing new.
  std::vector<std::array<point2, 2>> segs, pts;
  for (const auto& k : kept) {
    point2 a = to_point2(k[0]), b = to_point2(k[1]);
    if (b < a) std::swap(a, b);
    (a == b ? pts : segs).push_back({a, b});
  }
  std::sort(segs.begin(), segs.end());
  bool merged = true;
  while (merged) {
    merged = false;
    for (std::size_t i = 0; i < segs.size() && !merged; ++i)
      for (std::size_t j = i + 1; j < segs.size() && !merged; ++j) {
        const auto &s1 = segs[i], &s2 = segs[j];
        if (sgn(orient2(s1[0], s1[1], s2[0])) != 0 || sgn(orient2(s1[0], s1[1], s2[1])) != 0) continue;
        // Same line, both sorted lexicographically: they meet when neither ends before the other starts.
        if (s1[1] < s2[0] || s2[1] < s1[0]) continue;
        segs[i] = {std::min(s1[0], s2[0]), std::max(s1[1], s2[1])};
        segs.erase(segs.begin() + static_cast<std::ptrdiff_t>(j));
        merged = true;
      }
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  for (const auto& s : segs) r_.degenerate.push_back({s[0], s[1], r_.chart.lift(s[0]), r_.chart.lift(s[1])});
  for (const auto& p : pts) {
    bool covered = false;
    for (const auto& s : segs) covered = covered || on_segment(s[0], s[1], p[0]);
    if (!covered) r_.degenerate.push_back({p[0], p[0], r_.chart.lift(p[0]), r_.chart.lift(p[0])});
  }
  if (!r_.degenerate.empty()) note(shadow_case::degenerate_shadow);
  if (r_.polygons.empty() && r_.degenerate.empty()) note(shadow_case::empty);

  if (options_.keep_projected) {
    std::vector<cpolygon_wh> all_pw;
    shadow_all.polygons_with_holes(std::back_inserter(all_pw));
    for (const auto& p : all_pw) {
      r_.projected_loops.emplace_back();
      for (auto it = p.outer_boundary().vertices_begin(); it != p.outer_boundary().vertices_end(); ++it)
        r_.projected_loops.back().push_back(to_point2(*it));
      for (auto h = p.holes_begin(); h != p.holes_end(); ++h) {
        r_.projected_loops.emplace_back();
        for (auto it = h->vertices_begin(); it != h->vertices_end(); ++it) r_.projected_loops.back().push_back(to_point2(*it));
      }
    }
    r_.projected_degenerate = degenerate_;
  }
  r_.cases.assign(cases_.begin(), cases_.end());
  return r_;
}

plane<rational> derived_plane(const scene& s) {
  std::vector<point3> v = s.receiver.outer.vertices;
  drop_repeats(v);
  if (v.size() < 3) throw error(errc::scene_empty_polygon, "/receiver/polygon needs at least 3 distinct vertices");
  const point3 n = plane_normal(v);
  if (is_zero3(n))
    throw error(errc::scene_empty_polygon, "/receiver/polygon has zero area (its vertices are collinear)");
  return plane<rational>{make_vec4<rational>(n[0], n[1], n[2], -dot33(n, v[0]))};
}

cset region_set(const shadow_region& r) {
  cset s;
  for (const auto& p : r.polygons) {
    cpolygon_wh pw(to_cpolygon(p.outer));
    for (const auto& h : p.holes) pw.add_hole(to_cpolygon(h));
    s.join(pw);
  }
  return s;
}

}  // namespace

// ===========================================================================================
// receiver_chart

point2 receiver_chart::to_chart(const point3& X) const { return drop_axis(X, dropped_axis); }

point3 receiver_chart::lift(const point2& q) const {
  const int k = dropped_axis, i = (k + 1) % 3, j = (k + 2) % 3;
  point3 X;
  X[i] = q[0];
  X[j] = q[1];
  const auto& p = receiver_plane.p;
  X[k] = -(p[3] + p[i] * q[0] + p[j] * q[1]) / p[k];
  return X;
}

std::string_view receiver_chart::axis_name(int i) const {
  static constexpr std::string_view names[3] = {"x", "y", "z"};
  return names[(dropped_axis + 1 + i) % 3];
}

std::string_view to_string(shadow_case c) {
  switch (c) {
    case shadow_case::empty: return "empty";
    case shadow_case::light_parallel: return "light_parallel";
    case shadow_case::light_on_plane: return "light_on_plane";
    case shadow_case::caster_in_receiver_plane: return "caster_in_receiver_plane";
    case shadow_case::caster_touches_receiver: return "caster_touches_receiver";
    case shadow_case::caster_crosses_receiver: return "caster_crosses_receiver";
    case shadow_case::caster_behind_receiver: return "caster_behind_receiver";
    case shadow_case::caster_reaches_light_height: return "caster_reaches_light_height";
    case shadow_case::caster_contains_light: return "caster_contains_light";
    case shadow_case::caster_edge_on: return "caster_edge_on";
    case shadow_case::coincident_vertices: return "coincident_vertices";
    case shadow_case::collinear_vertices: return "collinear_vertices";
    case shadow_case::shadows_overlap: return "shadows_overlap";
    case shadow_case::shadow_outside_receiver: return "shadow_outside_receiver";
    case shadow_case::shadow_touches_receiver_boundary: return "shadow_touches_receiver_boundary";
    case shadow_case::degenerate_shadow: return "degenerate_shadow";
  }
  return "unknown";
}

bool shadow_region::has(shadow_case c) const { return std::find(cases.begin(), cases.end(), c) != cases.end(); }

shadow_region compute_shadow_region(const scene& s, const clip_options& options) {
  if (is_zero(s.light_source.l))
    throw zero_light_error();
  region_builder b(s, derived_plane(s), options);
  return b.run();
}

shadow_region compute_shadow_region(const scene& s, const plane<rational>& P, const clip_options& options) {
  if (sgn(P.a()) == 0 && sgn(P.b()) == 0 && sgn(P.c()) == 0)
    throw zero_normal_error();
  if (is_zero(s.light_source.l))
    throw zero_light_error();
  // The given plane must be a multiple of the receiver's own plane.
  for (std::size_t i = 0; i < s.receiver.outer.vertices.size(); ++i) {
    const auto& v = s.receiver.outer.vertices[i];
    if (sgn(P.a() * v[0] + P.b() * v[1] + P.c() * v[2] + P.d()) != 0)
      throw error(errc::scene_receiver_not_in_plane, "/receiver/polygon/" + std::to_string(i) + " is not in the given plane");
  }
  region_builder b(s, P, options);
  return b.run();
}

region_side locate(const shadow_region& r, const point2& q) {
  if (r.polygons.empty()) return region_side::outside;
  const cset s = region_set(r);
  switch (s.oriented_side(to_cpoint(q))) {
    case CGAL::ON_NEGATIVE_SIDE: return region_side::outside;
    case CGAL::ON_ORIENTED_BOUNDARY: return region_side::boundary;
    default: return region_side::inside;
  }
}

// ===========================================================================================
// The float pipeline (seed 003's way) and its exact comparison

namespace {

using fpoint = std::array<float, 2>;

// Sutherland–Hodgman: clips `subject` against each edge of the counter-clockwise `clip`
// polygon. Correct only for a convex clip polygon; float throughout, like real-time code.
std::vector<fpoint> sutherland_hodgman(std::vector<fpoint> subject, const std::vector<fpoint>& clip) {
  for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
    const fpoint a = clip[e], b = clip[(e + 1) % clip.size()];
    const auto inside = [&](const fpoint& p) {
      return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) >= 0.0f;
    };
    std::vector<fpoint> out;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const fpoint p = subject[i], q = subject[(i + 1) % subject.size()];
      const bool ip = inside(p), iq = inside(q);
      if (ip) out.push_back(p);
      if (ip != iq) {
        // Intersection of pq with the clip line, in float.
        const float dx = q[0] - p[0], dy = q[1] - p[1];
        const float ex = b[0] - a[0], ey = b[1] - a[1];
        const float den = dx * ey - dy * ex;
        const float t = ((a[0] - p[0]) * ey - (a[1] - p[1]) * ex) / den;
        out.push_back({p[0] + t * dx, p[1] + t * dy});
      }
    }
    subject = std::move(out);
  }
  return subject;
}

}  // namespace

float_comparison compare_with_float(const scene& s, const shadow_region& exact) {
  float_comparison c;
  const int k = exact.chart.dropped_axis;
  const plane<float> Pf = convert<float>(exact.chart.receiver_plane);
  const light<float> Lf = convert<float>(s.light_source);
  const mat4<float> M = shadow_matrix(Pf, Lf);

  std::vector<fpoint> clip;
  for (const auto& p : exact.receiver_outer) clip.push_back({to_nearest_float(p[0]), to_nearest_float(p[1])});
  {
    const std::vector<point2>& ex = exact.receiver_outer;
    // Convexity of the receiver outline (the exact one).
    for (std::size_t i = 0; i < ex.size(); ++i)
      if (sgn(orient2(ex[i], ex[(i + 1) % ex.size()], ex[(i + 2) % ex.size()])) < 0) c.receiver_convex = false;
    if (!exact.receiver_holes.empty()) c.receiver_convex = false;
  }

  cset receiver(to_cpolygon(exact.receiver_outer));
  for (const auto& h : exact.receiver_holes) {
    auto ring = h;
    std::reverse(ring.begin(), ring.end());
    receiver.difference(to_cpolygon(ring));
  }
  std::vector<cpolygon> valid;
  for (const auto& cst : s.casters)
    for (const auto& face : cst.faces) {
      std::vector<fpoint> proj;
      for (auto vi : face) {
        const auto& v = cst.vertices[vi];
        vec4<float> V = make_vec4<float>(to_nearest_float(v[0]), to_nearest_float(v[1]), to_nearest_float(v[2]), 1.0f);
        vec4<float> img;
        for (std::size_t r = 0; r < 4; ++r) {
          float acc = 0.0f;
          for (std::size_t cc = 0; cc < 4; ++cc) acc += M(r, cc) * V[cc];
          img[r] = acc;
        }
        const float x = img[static_cast<std::size_t>((k + 1) % 3)] / img[3];
        const float y = img[static_cast<std::size_t>((k + 2) % 3)] / img[3];
        proj.push_back({x, y});
      }
      // Non-finite vertices (w = 0 or overflow) poison the clip: count them and skip the polygon.
      auto all_finite = [&c](const auto& pts) {
        std::size_t bad = 0;
        for (const auto& p : pts) bad += (!std::isfinite(p[0]) || !std::isfinite(p[1])) ? 1 : 0;
        c.non_finite_vertices += bad;
        if (bad > 0) ++c.invalid_polygons;
        return bad == 0;
      };
      if (!all_finite(proj)) continue;
      auto out = sutherland_hodgman(proj, clip);
      if (out.empty()) continue;
      ++c.float_polygons;
      if (!all_finite(out)) continue;
      std::vector<point2> q;
      for (const auto& p : out) q.push_back({exact_value(p[0]), exact_value(p[1])});
      for (const auto& p : q)
        if (receiver.oriented_side(to_cpoint(p)) == CGAL::ON_NEGATIVE_SIDE) ++c.vertices_outside_receiver;
      drop_repeats(q);
      if (q.size() < 3 || sgn(signed_area2(q)) == 0 || !is_simple(q)) {
        ++c.invalid_polygons;
        continue;
      }
      if (sgn(signed_area2(q)) < 0) std::reverse(q.begin(), q.end());
      valid.push_back(to_cpolygon(q));
    }
  const cset f = make_set(valid);
  const cset e = region_set(exact);
  c.float_area = set_area(f);
  c.exact_area = exact.chart_area;
  cset false_part = f;
  false_part.difference(e);
  c.false_shadow_area = set_area(false_part);
  cset missing = e;
  missing.difference(f);
  c.missing_shadow_area = set_area(missing);
  c.missing_pieces = missing.number_of_polygons_with_holes();
  cset outside = f;
  outside.difference(receiver);
  c.outside_receiver_area = set_area(outside);
  return c;
}

void print_float_comparison(std::ostream& out, const float_comparison& c) {
  const auto line = [&](const char* what, const rational& q) {
    out << "  " << what << ": " << to_string(q) << " (~" << to_nearest_double(q) << ")\n";
  };
  out << "float pipeline (float shadow matrix, whole faces projected, Sutherland-Hodgman clip):\n";
  out << "  float polygons: " << c.float_polygons << ", invalid (non-simple, degenerate or non-finite): "
      << c.invalid_polygons << ", NaN/Inf vertices: " << c.non_finite_vertices << '\n';
  out << "  float vertices strictly outside the receiver: " << c.vertices_outside_receiver << '\n';
  if (!c.receiver_convex)
    out << "  receiver is not convex or has holes: Sutherland-Hodgman clips against its outline as if convex\n";
  line("exact chart area", c.exact_area);
  line("float chart area (union)", c.float_area);
  line("false shadow area (float minus exact)", c.false_shadow_area);
  line("missing shadow area (exact minus float)", c.missing_shadow_area);
  out << "  missing pieces: " << c.missing_pieces << '\n';
  line("float shadow outside the receiver", c.outside_receiver_area);
}

}  // namespace shadowproof
