// Boundary chains with filtered predicates and combinatorial cancellation (chain.h).
#include "chain.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "polygon2.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/vec3.h"

namespace shadowproof::detail {

namespace {

// Interval arithmetic without per-operation rounding-mode switches: valid only inside a
// CGAL::Protect_FPU_rounding<true> scope (rounding towards +∞), and never mixed with GMP.
using interval = CGAL::Interval_nt<false>;
using ivec3 = std::array<interval, 3>;

// An interval containing q, or nullopt when q is too large or too small for the filter
// (then everything touching it is decided exactly). mpq_get_d truncates; it is exact for a
// dyadic rational with a numerator of at most 53 bits, else one ulp either way contains q.
bool to_interval(const rational& q, interval& out) {
  const double d = q.get_d();
  if (d == 0 && sgn(q) == 0) {
    out = interval(0);
    return true;
  }
  const double m = std::fabs(d);
  if (!(m > 0x1p-400 && m < 0x1p400)) return false;
  const mpz_srcptr num = q.get_num_mpz_t(), den = q.get_den_mpz_t();
  if (mpz_sizeinbase(num, 2) <= 53 && mpz_popcount(den) == 1) {
    out = interval(d);
    return true;
  }
  out = interval(std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL));
  return true;
}

// The sign of an interval value, or 2 when the interval cannot tell.
int certain_sign(const interval& x) {
  const CGAL::Uncertain<CGAL::Sign> s = CGAL::sign(x);
  if (!CGAL::is_certain(s)) return 2;
  return static_cast<int>(CGAL::get_certain(s));
}

interval ivalue(const std::array<interval, 4>& h, const ivec3& X) { return h[0] * X[0] + h[1] * X[1] + h[2] * X[2] + h[3]; }

// Per vertex: what the faces need to know, decided once.
struct vertex_facts {
  bool filtered = false;  // coordinates held as intervals
  ivec3 x{};
  bool inside = false;    // every clip half-space ≥ 0 at the vertex (exact)
  bool at_light = false;  // the vertex is a point light's position (exact)
  int side = 0;           // sign of P·V (exact)
  int above = -1;         // sign of f(V) − 1 for a point light (exact; −1 otherwise)
  bool used = false;
};

// Signed half-edge u → v stored in the bucket of min(u, v): the other end and ±1.
struct half_edge {
  std::uint32_t other;
  std::int32_t sign;
};

}  // namespace

caster_chain build_chain(const clip_setup& setup, std::size_t ci, case_set& cases,
                         std::vector<std::array<point2, 2>>& degenerate, const std::function<void(std::size_t)>& progress) {
  const caster& c = setup.sc->casters[ci];
  const auto& L = setup.sc->light_source.l;
  caster_chain out;
  const std::size_t nv = c.vertices.size();
  std::vector<vertex_facts> vf(nv);
  for (const auto& face : c.faces)
    for (auto i : face) vf[i].used = true;

  // Planes and the light as intervals (one too large for the filter disables it).
  std::vector<std::array<interval, 4>> hs(setup.halfspaces.size());
  bool planes_filtered = true;
  for (std::size_t j = 0; j < hs.size(); ++j)
    for (std::size_t k = 0; k < 4; ++k) planes_filtered = to_interval(setup.halfspaces[j][k], hs[j][k]) && planes_filtered;
  std::array<interval, 4> light{};
  for (std::size_t k = 0; k < 4; ++k) planes_filtered = to_interval(L[k], light[k]) && planes_filtered;
  std::array<interval, 4> pplane{};
  for (std::size_t k = 0; k < 4; ++k) planes_filtered = to_interval(setup.P.p[k], pplane[k]) && planes_filtered;

  for (std::size_t i = 0; i < nv; ++i) {
    if (!vf[i].used) continue;
    auto& f = vf[i];
    const point3& V = c.vertices[i];
    f.filtered = planes_filtered && to_interval(V[0], f.x[0]) && to_interval(V[1], f.x[1]) && to_interval(V[2], f.x[2]);
    // Side of P and the clip half-spaces: filtered, exact when the interval straddles 0.
    const bool point_light = !setup.grazing() && setup.point_light();
    std::array<int, 7> signs;
    signs.fill(2);
    if (f.filtered) {
      CGAL::Protect_FPU_rounding<true> up;
      signs[0] = certain_sign(ivalue(pplane, f.x));
      for (std::size_t j = 0; j < hs.size(); ++j) signs[j + 1] = certain_sign(ivalue(hs[j], f.x));
      if (point_light) signs[6] = certain_sign(ivalue(hs[0], f.x) - interval(1));
    }
    if (signs[0] == 2) signs[0] = sgn(plane_value(setup.P.p, V));
    for (std::size_t j = 0; j < hs.size(); ++j)
      if (signs[j + 1] == 2) signs[j + 1] = sgn(plane_value(setup.halfspaces[j], V));
    if (point_light && signs[6] == 2) signs[6] = sgn(plane_value(setup.height, V) - 1);
    f.side = signs[0];
    f.inside = std::all_of(signs.begin() + 1, signs.begin() + 1 + static_cast<std::ptrdiff_t>(hs.size()),
                           [](int s) { return s >= 0; });
    // Inside the cone, f(V) = 1 only at its apex: the light.
    if (point_light) {
      f.above = signs[6];
      f.at_light = f.inside && signs[6] == 0;
    }
  }

  // Cases from the vertices' sides (as the reference, over every vertex a face uses).
  caster_sides sides;
  for (std::size_t i = 0; i < nv; ++i) {
    if (!vf[i].used) continue;
    const int t = vf[i].side;
    if (t == 0) sides.on = true;
    else if (t * setup.light_side > 0) sides.front = true;
    else sides.back = true;
  }
  for (std::size_t i = 0; i < nv; ++i) sides.high = sides.high || (vf[i].used && vf[i].above >= 0);

  // The sign that turns "the light is on the positive side of the face's plane" into
  // "the face projects counter-clockwise": fixed for the whole clip region (the projection's
  // denominator keeps one sign there), found from the first face that needs it.
  int facing_to_ccw = 0;
  std::vector<std::uint32_t> he_from, he_to;  // directed half-edges of the fast faces
  he_from.reserve(3 * c.faces.size());
  he_to.reserve(3 * c.faces.size());
  std::vector<std::vector<point2>> polygons;

  const auto slow_face = [&](std::size_t f) {
    ++out.exact_faces;
    const face_geometry g = validate_face(setup, c, f, cases);
    bool inside = true;
    for (auto i : c.faces[f]) inside = inside && vf[i].inside;
    if (inside && !g.collinear && !g.edge_on && !setup.grazing()) {
      // Inside the clip region the projection maps the face's plane one to one: the whole
      // face's boundary, oriented counter-clockwise, with its straight vertices dropped.
      std::vector<point2> outline;
      outline.reserve(g.v.size());
      for (const auto& p : g.v) outline.push_back(setup.project(p));
      if (sgn(signed_area(outline)) < 0) std::reverse(outline.begin(), outline.end());
      polygons.push_back(std::move(outline));
      return;
    }
    cast_face(setup, g, cases, polygons, degenerate);
  };

  for (std::size_t f = 0; f < c.faces.size(); ++f) {
    if (progress && (f & 0xffff) == 0xffff) progress(f);
    const auto& face = c.faces[f];
    if (face.size() != 3 || setup.grazing()) {
      slow_face(f);
      continue;
    }
    const std::size_t ia = face[0], ib = face[1], ic = face[2];
    const vertex_facts &a = vf[ia], &b = vf[ib], &cc = vf[ic];
    if (ia == ib || ib == ic || ia == ic || !(a.inside && b.inside && cc.inside) || a.at_light || b.at_light ||
        cc.at_light || !(a.filtered && b.filtered && cc.filtered)) {
      slow_face(f);
      continue;
    }
    // Filtered: distinct vertices, a non-zero normal, and the light's side of the face.
    int facing = 2;
    bool distinct = false, nonzero_normal = false;
    {
      CGAL::Protect_FPU_rounding<true> up;
      const auto differ = [](const ivec3& p, const ivec3& q) {
        for (int k = 0; k < 3; ++k)
          if (p[k].inf() > q[k].sup() || q[k].inf() > p[k].sup()) return true;
        return false;
      };
      distinct = differ(a.x, b.x) && differ(b.x, cc.x) && differ(a.x, cc.x);
      const ivec3 n = cross(difference(b.x, a.x), difference(cc.x, a.x));
      nonzero_normal = certain_sign(n[0]) % 2 != 0 || certain_sign(n[1]) % 2 != 0 || certain_sign(n[2]) % 2 != 0;
      if (distinct && nonzero_normal)
        facing = certain_sign(n[0] * light[0] + n[1] * light[1] + n[2] * light[2] - dot(n, a.x) * light[3]);
    }
    const point3 &A = c.vertices[ia], &B = c.vertices[ib], &C = c.vertices[ic];
    if (!distinct || !nonzero_normal || facing == 2) {
      // Exact: a repeated or collinear triangle goes through validation; else its facing.
      if (A == B || B == C || A == C || is_zero(cross(difference(B, A), difference(C, A)))) {
        slow_face(f);
        continue;
      }
      const point3 n = cross(difference(B, A), difference(C, A));
      facing = sgn(dot(n, point3{L[0], L[1], L[2]}) - dot(n, A) * L[3]);
      ++out.exact_faces;
    }
    if (facing == 0) {  // edge-on: its shadow has no area
      slow_face(f);
      continue;
    }
    if (a.side == 0 && b.side == 0 && cc.side == 0)
      cases.insert(shadow_case::caster_in_receiver_plane);
    if (facing_to_ccw == 0) {
      const int turn = sgn(orient2(setup.project(A), setup.project(B), setup.project(C)));
      if (turn == 0) throw internal_error("a face that is not edge-on projects to zero area");
      facing_to_ccw = turn * facing;
    }
    const bool ccw = facing * facing_to_ccw > 0;
    const std::uint32_t u = static_cast<std::uint32_t>(ia), v = static_cast<std::uint32_t>(ccw ? ib : ic),
                        w = static_cast<std::uint32_t>(ccw ? ic : ib);
    he_from.insert(he_from.end(), {u, v, w});
    he_to.insert(he_to.end(), {v, w, u});
  }
  sides.note(setup, cases);

  // Cancellation: half-edges bucketed by their smaller vertex (a counting sort, O(n)); each
  // undirected edge keeps the signed count of its two directions.
  out.half_edges = he_from.size();
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (std::size_t e = 0; e < he_from.size(); ++e) ++start[std::min(he_from[e], he_to[e]) + 1];
  for (std::size_t i = 0; i < nv; ++i) start[i + 1] += start[i];
  std::vector<half_edge> bucket(he_from.size());
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t e = 0; e < he_from.size(); ++e) {
      const std::uint32_t u = he_from[e], v = he_to[e];
      bucket[fill[std::min(u, v)]++] = u < v ? half_edge{v, 1} : half_edge{u, -1};
    }
  }
  he_from = {};
  he_to = {};
  std::vector<std::int64_t> projected_at(nv, -1);
  const auto project_vertex = [&](std::uint32_t i) {
    if (projected_at[i] < 0) {
      projected_at[i] = static_cast<std::int64_t>(out.points.size());
      out.points.push_back(setup.project(c.vertices[i]));
    }
    return static_cast<std::size_t>(projected_at[i]);
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> surviving;  // (u < v, weight index)
  std::vector<long> weights;
  for (std::uint32_t u = 0; u < nv; ++u) {
    const auto first = bucket.begin() + start[u], last = bucket.begin() + start[u + 1];
    std::sort(first, last, [](const half_edge& x, const half_edge& y) { return x.other < y.other; });
    for (auto it = first; it != last;) {
      long w = 0;
      auto jt = it;
      for (; jt != last && jt->other == it->other; ++jt) w += jt->sign;
      if (w != 0) {
        surviving.emplace_back(u, it->other);
        weights.push_back(w);
      }
      it = jt;
    }
  }
  out.segments.reserve(surviving.size() + 4 * polygons.size());
  for (std::size_t e = 0; e < surviving.size(); ++e) {
    const std::size_t pa = project_vertex(surviving[e].first);
    const std::size_t pb = project_vertex(surviving[e].second);
    out.segments.push_back({pa, pb, weights[e]});
  }
  // Faces projected whole or in pieces: their edges as they are (the arrangement cancels
  // shared ones geometrically).
  for (auto& outline : polygons) {
    out.half_edges += outline.size();
    const std::size_t first = out.points.size();
    for (auto& p : outline) out.points.push_back(std::move(p));
    for (std::size_t i = 0; i < outline.size(); ++i)
      out.segments.push_back({first + i, first + (i + 1) % outline.size(), 1});
  }
  return out;
}

}  // namespace shadowproof::detail
