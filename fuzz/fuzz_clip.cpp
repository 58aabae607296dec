// Fuzz target: exact clipping invariants on small scenes decoded from the input. A rectangular
// receiver in a plane with a small-integer normal, a light chosen among degenerate families
// (above, on the plane, directional, parallel), and one to three caster triangles on a small
// integer grid, some vertices snapped onto the plane or to the light's height.
// Invariants: no exception but shadowproof::error; the shadow lies inside the receiver (every
// vertex, and area ≤ receiver area); the area does not change when P is scaled by -3.
#include <cstdint>
#include <cstdlib>

#include "shadowproof/clip/shadow_region.h"
#include "shadowproof/core/error.h"
#include "byte_source.h"

namespace {

using namespace shadowproof;

rational grid(byte_source& src, long r = 6) { return rational(static_cast<long>(src.below(2 * r + 1)) - r); }

point3 cross(const point3& a, const point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

bool is_zero(const point3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

// Exact cross product sign of (b − a) × (c − a) in the chart.
int orientation(const point2& a, const point2& b, const point2& c) {
  const rational d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  return d > 0 ? 1 : (d < 0 ? -1 : 0);
}

// The receiver is convex and counter-clockwise in the chart: inside or on it means no edge
// sees the point strictly on its right.
bool in_convex(const std::vector<point2>& poly, const point2& q) {
  for (std::size_t i = 0; i < poly.size(); ++i)
    if (orientation(poly[i], poly[(i + 1) % poly.size()], q) < 0) return false;
  return true;
}

rational polygon_area(const std::vector<point2>& p) {
  rational twice = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    twice += a[0] * b[1] - a[1] * b[0];
  }
  return abs(twice) / 2;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  byte_source src(data, size);
  point3 n{grid(src, 3), grid(src, 3), grid(src, 3)};
  if (is_zero(n)) n = {0, 0, 1};
  point3 u = cross(n, {grid(src, 2), grid(src, 2), grid(src, 2)});
  if (is_zero(u)) u = cross(n, {1, 0, 0});
  if (is_zero(u)) u = cross(n, {0, 1, 0});
  const point3 v = cross(n, u);
  const point3 origin{grid(src), grid(src), grid(src)};
  const rational s = 1 + static_cast<long>(src.below(3)), t = 1 + static_cast<long>(src.below(3));
  auto at = [&](const rational& a, const rational& b) {
    return point3{origin[0] + a * u[0] + b * v[0], origin[1] + a * u[1] + b * v[1], origin[2] + a * u[2] + b * v[2]};
  };
  scene sc;
  sc.receiver.outer.vertices = {at(-s, -t), at(s, -t), at(s, t), at(-s, t)};
  const rational d = -(n[0] * origin[0] + n[1] * origin[1] + n[2] * origin[2]);
  auto plane_value = [&](const point3& x) -> rational { return n[0] * x[0] + n[1] * x[1] + n[2] * x[2] + d; };

  // Light: above the receiver, on its plane, directional, or parallel to it.
  point3 lp{grid(src, 8), grid(src, 8), grid(src, 8)};
  switch (src.below(4)) {
    case 0: sc.light_source = make_light<rational>(lp[0], lp[1], lp[2], 1); break;
    case 1: {  // slide the light along n onto the plane when n·n divides; else keep it
      const rational k = plane_value(lp) / (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      sc.light_source = make_light<rational>(lp[0] - k * n[0], lp[1] - k * n[1], lp[2] - k * n[2], 1);
      break;
    }
    case 2: {
      point3 dir{grid(src, 4), grid(src, 4), grid(src, 4)};
      if (is_zero(dir)) dir = n;
      sc.light_source = make_light<rational>(dir[0], dir[1], dir[2], 0);
      break;
    }
    default: {
      const point3 dir = is_zero(u) ? point3{1, 0, 0} : u;
      sc.light_source = make_light<rational>(dir[0], dir[1], dir[2], 0);
      break;
    }
  }

  const std::size_t casters = 1 + src.below(3);
  for (std::size_t i = 0; i < casters; ++i) {
    caster c;
    c.name = "/casters/" + std::to_string(i);
    c.is_polygon = true;
    for (int k = 0; k < 3; ++k) {
      point3 p{grid(src), grid(src), grid(src)};
      if (src.below(4) == 0) {  // snap onto the receiver plane
        const rational m = plane_value(p) / (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        p = {p[0] - m * n[0], p[1] - m * n[1], p[2] - m * n[2]};
      }
      c.vertices.push_back(p);
    }
    c.faces = {{0, 1, 2}};
    sc.casters.push_back(std::move(c));
  }

  try {
    clip_options options;
    options.keep_projected = false;
    const shadow_region r = compute_shadow_region(sc, options);
    const rational receiver_area = polygon_area(r.receiver_outer);
    if (r.chart_area > receiver_area) std::abort();
    for (const auto& poly : r.polygons)
      for (const auto& q : poly.outer)
        if (!in_convex(r.receiver_outer, q)) std::abort();
    for (const auto& piece : r.degenerate)
      if (!in_convex(r.receiver_outer, piece.a) || !in_convex(r.receiver_outer, piece.b)) std::abort();
    if (src.below(4) == 0) {
      const plane<rational> scaled{rational(-3) * make_plane(n[0], n[1], n[2], d).p};
      if (compute_shadow_region(sc, scaled, options).area_squared != r.area_squared) std::abort();
    }
  } catch (const error&) {
  }
  return 0;
}
