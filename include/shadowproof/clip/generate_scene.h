#pragma once
/// Reproducible random clip scenes biased to exact degeneracies, for property tests and
/// fuzzing: closed, open, non-manifold and inconsistently oriented meshes and triangle soups
/// on a small integer grid over a receiver in a plane with a small-integer normal, lit by
/// point and directional lights chosen among degenerate families. Every coordinate is an
/// integer, so coincident vertices, shared edges, edge-on faces, vertices on the receiver's
/// plane or at the light's height happen often and exactly.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "shadowproof/clip/scene.h"
#include "shadowproof/core/vec3.h"

namespace shadowproof {

namespace detail {

template <class Source>
long pick(Source& src, long lo, long hi) {
  return lo + static_cast<long>(src.below(static_cast<std::uint64_t>(hi - lo + 1)));
}

// A frame (origin O, in-plane axes u, v, normal n) with small integer vectors; n = u × v is
// the receiver's normal, so the point (a, b, h) = O + a u + b v + h n lies at height h.
struct scene_frame {
  point3 O, u, v, n;
  point3 at(long a, long b, long h) const {
    return sum(sum(O, scaled(rational(a), u)), sum(scaled(rational(b), v), scaled(rational(h), n)));
  }
};

template <class Source>
scene_frame random_frame(Source& src) {
  scene_frame f;
  f.O = {rational(pick(src, -3, 3)), rational(pick(src, -3, 3)), rational(pick(src, -3, 3))};
  if (src.below(3) != 0) {  // the ground z = 0 (up to a shift), the common case
    f.u = {rational(1), rational(0), rational(0)};
    f.v = {rational(0), rational(1), rational(0)};
  } else {
    const point3 a{rational(pick(src, -2, 2)), rational(pick(src, -2, 2)), rational(pick(src, 1, 2))};
    point3 b = cross(a, point3{rational(pick(src, -2, 2)), rational(pick(src, -2, 2)), rational(pick(src, -2, 2))});
    if (is_zero(b)) b = cross(a, point3{rational(1), rational(0), rational(0)});
    if (is_zero(b)) b = cross(a, point3{rational(0), rational(1), rational(0)});
    f.u = a;
    f.v = b;
  }
  f.n = cross(f.u, f.v);
  return f;
}

// Faces of shapes in local (a, b, h) grid coordinates, outward oriented (counter-clockwise
// seen from outside).
using local_point = std::array<long, 3>;
struct local_mesh {
  std::vector<local_point> v;
  std::vector<std::vector<std::size_t>> f;
};

inline local_mesh box_mesh(long a0, long b0, long h0, long a1, long b1, long h1, bool quads) {
  local_mesh m;
  for (int k = 0; k < 8; ++k) m.v.push_back({k & 1 ? a1 : a0, k & 2 ? b1 : b0, k & 4 ? h1 : h0});
  const std::vector<std::vector<std::size_t>> q = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& face : q) {
    if (quads) m.f.push_back(face);
    else {
      m.f.push_back({face[0], face[1], face[2]});
      m.f.push_back({face[0], face[2], face[3]});
    }
  }
  return m;
}

inline local_mesh tetra_mesh(const std::array<local_point, 4>& p) {
  local_mesh m;
  m.v.assign(p.begin(), p.end());
  m.f = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  return m;
}

inline local_mesh octa_mesh(long a, long b, long h, long r, long rh) {
  local_mesh m;
  m.v = {{a + r, b, h}, {a - r, b, h}, {a, b + r, h}, {a, b - r, h}, {a, b, h + rh}, {a, b, h - rh}};
  m.f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// An open height field over a k × k grid: every interior edge shared by two triangles.
template <class Source>
local_mesh terrain_mesh(Source& src, long a, long b, long k, long h_lo, long h_hi) {
  local_mesh m;
  for (long i = 0; i <= k; ++i)
    for (long j = 0; j <= k; ++j) m.v.push_back({a + i, b + j, pick(src, h_lo, h_hi)});
  const auto id = [&](long i, long j) { return static_cast<std::size_t>(i * (k + 1) + j); };
  for (long i = 0; i < k; ++i)
    for (long j = 0; j < k; ++j) {
      m.f.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.f.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

}  // namespace detail

/// A random scene drawn from `src` (anything with `std::uint64_t below(std::uint64_t n)`,
/// uniform in [0, n)). `max_casters` bounds the casters, `max_faces` roughly the faces of each.
/// Families: triangle soups (up to 8 triangles, repeated, collinear and edge-on ones included),
/// boxes (quads or triangles), tetrahedra, octahedra and open height fields, each sometimes
/// with faces flipped, removed or duplicated; vertices snapped onto the receiver's plane or
/// the point light's height; lights above, on, below or parallel to the receiver, and at a
/// caster's vertex. Malformed scenes (non-planar or self-intersecting quads) can occur: they
/// must be rejected with shadowproof::error.
template <class Source>
scene generate_clip_scene(Source& src, std::size_t max_casters = 3, std::size_t max_faces = 16) {
  using detail::pick;
  const detail::scene_frame fr = detail::random_frame(src);
  scene s;
  const long half_a = pick(src, 2, 6), half_b = pick(src, 2, 6);
  switch (src.below(4)) {
    case 0: {  // an L shape
      s.receiver.outer.vertices = {fr.at(-half_a, -half_b, 0), fr.at(half_a, -half_b, 0), fr.at(half_a, 0, 0),
                                   fr.at(0, 0, 0),            fr.at(0, half_b, 0),       fr.at(-half_a, half_b, 0)};
      break;
    }
    case 1: {  // a rectangle with a hole
      s.receiver.outer.vertices = {fr.at(-half_a, -half_b, 0), fr.at(half_a, -half_b, 0), fr.at(half_a, half_b, 0),
                                   fr.at(-half_a, half_b, 0)};
      s.receiver.holes.push_back(polygon3{{fr.at(-1, -1, 0), fr.at(1, -1, 0), fr.at(1, 1, 0), fr.at(-1, 1, 0)}});
      break;
    }
    default:
      s.receiver.outer.vertices = {fr.at(-half_a, -half_b, 0), fr.at(half_a, -half_b, 0), fr.at(half_a, half_b, 0),
                                   fr.at(-half_a, half_b, 0)};
  }
  // The light (a caster vertex may replace it below).
  const long light_height = pick(src, 3, 9);
  const std::uint64_t light_family = src.below(7);
  const auto point_light = [&](const point3& p) { return make_light<rational>(p[0], p[1], p[2], 1); };
  const auto direction = [&](long a, long b, long h) {
    const point3 d = sum(sum(scaled(rational(a), fr.u), scaled(rational(b), fr.v)), scaled(rational(h), fr.n));
    return is_zero(d) ? make_light<rational>(fr.n[0], fr.n[1], fr.n[2], 0) : make_light<rational>(d[0], d[1], d[2], 0);
  };
  switch (light_family) {
    case 0: s.light_source = point_light(fr.at(pick(src, -4, 4), pick(src, -4, 4), light_height)); break;
    case 1: s.light_source = point_light(fr.at(pick(src, -8, 8), pick(src, -8, 8), 0)); break;  // on the plane
    case 2: s.light_source = direction(pick(src, -3, 3), pick(src, -3, 3), pick(src, 1, 4)); break;
    case 3: s.light_source = direction(pick(src, -3, 3), pick(src, -3, 3), 0); break;  // parallel
    case 4: s.light_source = direction(pick(src, -3, 3), pick(src, -3, 3), -pick(src, 1, 4)); break;  // from below
    case 5: s.light_source = point_light(fr.at(pick(src, -4, 4), pick(src, -4, 4), -pick(src, 1, 5))); break;
    default: s.light_source = point_light(fr.at(pick(src, -4, 4), pick(src, -4, 4), light_height)); break;
  }
  const bool light_at_vertex = light_family == 6;
  // Heights snap onto the plane (0) and, for a point light above it, the light's height.
  const auto height = [&](long lo, long hi) {
    const std::uint64_t r = src.below(8);
    if (r == 0) return 0L;
    if (r == 1 && light_family == 0) return light_height;
    return pick(src, lo, hi);
  };
  const std::size_t casters = 1 + static_cast<std::size_t>(src.below(max_casters));
  for (std::size_t ci = 0; ci < casters; ++ci) {
    detail::local_mesh m;
    const std::uint64_t shape = src.below(6);
    const long a = pick(src, -4, 3), b = pick(src, -4, 3);
    if (shape == 0) {  // a soup of triangles on a tiny grid: coincident, collinear, edge-on
      const std::size_t n = 1 + static_cast<std::size_t>(src.below(std::min<std::size_t>(8, max_faces)));
      for (std::size_t t = 0; t < n; ++t) {
        for (int k = 0; k < 3; ++k) m.v.push_back({pick(src, -3, 3), pick(src, -3, 3), height(-1, 5)});
        m.f.push_back({3 * t, 3 * t + 1, 3 * t + 2});
      }
    } else if (shape == 1) {
      const long h0 = height(-2, 4);
      m = detail::box_mesh(a, b, h0, a + pick(src, 1, 3), b + pick(src, 1, 3), h0 + pick(src, 1, 3), src.below(2) == 0);
    } else if (shape == 2) {
      std::array<detail::local_point, 4> p;
      for (auto& q : p) q = {pick(src, -3, 3), pick(src, -3, 3), height(-1, 6)};
      m = detail::tetra_mesh(p);
    } else if (shape == 3) {
      m = detail::octa_mesh(a, b, height(0, 5), pick(src, 1, 2), pick(src, 1, 2));
    } else if (shape == 4) {
      const long k = std::min<long>(pick(src, 1, 3), max_faces >= 18 ? 3 : max_faces >= 8 ? 2 : 1);
      m = detail::terrain_mesh(src, a, b, k, -1, 4);
    } else {  // one planar polygon with 4 to 6 vertices at one height (maybe not simple)
      const long h = height(-1, 6);
      const std::size_t n = 4 + static_cast<std::size_t>(src.below(3));
      m.f.emplace_back();
      for (std::size_t k = 0; k < n; ++k) {
        m.v.push_back({pick(src, -4, 4), pick(src, -4, 4), h});
        m.f.back().push_back(k);
      }
    }
    // Damage: flip, drop or duplicate a face now and then.
    if (m.f.size() > 1 && src.below(4) == 0) {
      const std::size_t k = static_cast<std::size_t>(src.below(m.f.size()));
      switch (src.below(3)) {
        case 0: std::reverse(m.f[k].begin(), m.f[k].end()); break;
        case 1: m.f.erase(m.f.begin() + static_cast<std::ptrdiff_t>(k)); break;
        default: m.f.push_back(m.f[k]); break;
      }
    }
    caster c;
    c.name = "/casters/" + std::to_string(ci) + (shape == 5 ? "/polygon" : "/mesh");
    c.is_polygon = shape == 5;
    for (const auto& p : m.v) c.vertices.push_back(fr.at(p[0], p[1], p[2]));
    c.faces = m.f;
    s.casters.push_back(std::move(c));
  }
  if (light_at_vertex) {
    const caster& c = s.casters[static_cast<std::size_t>(src.below(s.casters.size()))];
    const point3& p = c.vertices[static_cast<std::size_t>(src.below(c.vertices.size()))];
    s.light_source = point_light(p);
  }
  return s;
}

}  // namespace shadowproof
