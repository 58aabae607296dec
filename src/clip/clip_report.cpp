// Text report of a shadow region, its approximate area, and the demo scene.
#include <mpfr.h>

#include <charconv>
#include <ostream>

#include "shadowproof/clip/shadow_region.h"

namespace shadowproof {

namespace {

std::string tuple_text(const point2& p) { return "(" + to_string(p[0]) + ", " + to_string(p[1]) + ")"; }
std::string tuple_text(const point3& p) {
  return "(" + to_string(p[0]) + ", " + to_string(p[1]) + ", " + to_string(p[2]) + ")";
}

void print_ring(std::ostream& out, const char* what, const std::vector<point2>& c, const std::vector<point3>& p) {
  out << "    " << what << " (" << c.size() << " vertices; chart (u, v) -> 3D (x, y, z)):\n";
  for (std::size_t i = 0; i < c.size(); ++i) out << "      " << tuple_text(c[i]) << " -> " << tuple_text(p[i]) << '\n';
}

point3 p3(int x, int y, int z) { return {rational(x), rational(y), rational(z)}; }

}  // namespace

double approximate_area(const shadow_region& r) {
  // √q rounded down and up at precision p, each then rounded to 53 bits: equal means both
  // bracket ends give the same double, which is then the correctly rounded √q.
  for (mpfr_prec_t p = 96;; p *= 2) {
    mpfr_t lo, hi;
    mpfr_inits2(p, lo, hi, static_cast<mpfr_ptr>(nullptr));
    mpfr_set_q(lo, r.area_squared.get_mpq_t(), MPFR_RNDD);
    mpfr_set_q(hi, r.area_squared.get_mpq_t(), MPFR_RNDU);
    mpfr_sqrt(lo, lo, MPFR_RNDD);
    mpfr_sqrt(hi, hi, MPFR_RNDU);
    const double a = mpfr_get_d(lo, MPFR_RNDN), b = mpfr_get_d(hi, MPFR_RNDN);
    mpfr_clears(lo, hi, static_cast<mpfr_ptr>(nullptr));
    if (a == b || p > 1 << 16) return a;
  }
}

void print_region_report(std::ostream& out, const shadow_region& r) {
  out << "chart: drop " << r.chart.axis_name(2) << ", u = " << r.chart.axis_name(0) << ", v = " << r.chart.axis_name(1)
      << "; receiver plane (" << to_string(r.chart.receiver_plane.a()) << ", " << to_string(r.chart.receiver_plane.b())
      << ", " << to_string(r.chart.receiver_plane.c()) << ", " << to_string(r.chart.receiver_plane.d()) << ")\n";
  out << "cases:";
  if (r.cases.empty()) out << " none";
  for (auto c : r.cases) out << ' ' << to_string(c);
  out << '\n';
  out << "chart area: " << to_string(r.chart_area) << '\n';
  out << "area scale squared (3D area^2 / chart area^2): " << to_string(r.chart.area_scale_squared) << '\n';
  out << "area_squared (exact square of the 3D area): " << to_string(r.area_squared) << '\n';
  char approx[32];
  const auto end = std::to_chars(approx, approx + sizeof approx, approximate_area(r)).ptr;
  out << "area (decimal approximation of sqrt(area_squared)): ~" << std::string(approx, end) << '\n';
  out << "polygons: " << r.polygons.size() << '\n';
  for (std::size_t i = 0; i < r.polygons.size(); ++i) {
    const auto& p = r.polygons[i];
    out << "  polygon " << i << ":\n";
    print_ring(out, "outer", p.outer, p.outer_3d);
    for (std::size_t h = 0; h < p.holes.size(); ++h) print_ring(out, "hole", p.holes[h], p.holes_3d[h]);
  }
  std::size_t points = 0;
  for (const auto& d : r.degenerate) points += d.is_point() ? 1 : 0;
  out << "degenerate segments: " << (r.degenerate.size() - points) << '\n';
  for (const auto& d : r.degenerate)
    if (!d.is_point())
      out << "  " << tuple_text(d.a) << " - " << tuple_text(d.b) << "  3D " << tuple_text(d.a_3d) << " - "
          << tuple_text(d.b_3d) << '\n';
  out << "degenerate points: " << points << '\n';
  for (const auto& d : r.degenerate)
    if (d.is_point()) out << "  " << tuple_text(d.a) << "  3D " << tuple_text(d.a_3d) << '\n';
}

scene make_demo_scene() {
  scene s;
  // An L-shaped floor z = 0 with a square hole, lit by a point light at (9, 4, 8).
  s.receiver.outer.vertices = {p3(0, 0, 0), p3(12, 0, 0), p3(12, 5, 0), p3(5, 5, 0), p3(5, 10, 0), p3(0, 10, 0)};
  s.receiver.holes.push_back(polygon3{{p3(1, 1, 0), p3(3, 1, 0), p3(3, 3, 0), p3(1, 3, 0)}});
  s.light_source = make_light<rational>(9, 4, 8, 1);
  caster tilted;
  tilted.name = "tilted square";
  tilted.is_polygon = true;
  tilted.vertices = {p3(5, 1, 3), p3(7, 1, 4), p3(7, 3, 4), p3(5, 3, 3)};
  tilted.faces = {{0, 1, 2, 3}};
  caster crossing;
  crossing.name = "triangle crossing the floor";
  crossing.is_polygon = true;
  crossing.vertices = {p3(10, 1, 2), p3(11, 3, -2), p3(9, 3, 2)};
  crossing.faces = {{0, 1, 2}};
  caster tall;
  tall.name = "panel reaching above the light";
  tall.is_polygon = true;
  tall.vertices = {p3(6, 6, 2), p3(7, 6, 2), p3(7, 6, 9), p3(6, 6, 9)};
  tall.faces = {{0, 1, 2, 3}};
  caster edge_on;
  edge_on.name = "edge-on triangle";
  edge_on.is_polygon = true;
  // In the plane x = 9, which contains the light: its shadow is a segment.
  edge_on.vertices = {p3(9, 1, 1), p3(9, 2, 1), p3(9, 1, 3)};
  edge_on.faces = {{0, 1, 2}};
  s.casters = {tilted, crossing, tall, edge_on};
  return s;
}

}  // namespace shadowproof
