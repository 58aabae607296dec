// The float pipeline the way real-time code runs it (seed 003) and its exact comparison with
// the exact region (shadow_region.h, compare_with_float).
#include <algorithm>
#include <cmath>

#include "polygon2.h"
#include "polygon_set.h"
#include "shadowproof/clip/shadow_region.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof {

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
      if (sgn(detail::orient2(ex[i], ex[(i + 1) % ex.size()], ex[(i + 2) % ex.size()])) < 0) c.receiver_convex = false;
    if (!exact.receiver_holes.empty()) c.receiver_convex = false;
  }

  detail::polygon_set receiver(exact.receiver_outer);
  for (const auto& h : exact.receiver_holes) {
    auto ring = h;
    std::reverse(ring.begin(), ring.end());
    receiver.subtract(detail::polygon_set(ring));
  }
  std::vector<detail::ring> valid;
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
        if (receiver.side(p) == region_side::outside) ++c.vertices_outside_receiver;
      detail::drop_repeats(q);
      // A float polygon that is not simple (bow-ties, fold-backs) is counted, not combined.
      if (q.size() < 3 || sgn(detail::signed_area(q)) == 0 || !detail::is_simple(q)) {
        ++c.invalid_polygons;
        continue;
      }
      if (sgn(detail::signed_area(q)) < 0) std::reverse(q.begin(), q.end());
      valid.push_back(std::move(q));
    }
  detail::polygon_set f;
  f.join(valid);
  std::vector<detail::ring_with_holes> exact_polygons;
  for (const auto& p : exact.polygons) exact_polygons.push_back({p.outer, p.holes});
  const detail::polygon_set e(exact_polygons);
  c.float_area = f.area();
  c.exact_area = exact.chart_area;
  detail::polygon_set false_part = f;
  false_part.subtract(e);
  c.false_shadow_area = false_part.area();
  detail::polygon_set missing = e;
  missing.subtract(f);
  c.missing_shadow_area = missing.area();
  c.missing_pieces = missing.size();
  detail::polygon_set outside = f;
  outside.subtract(receiver);
  c.outside_receiver_area = outside.area();
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
