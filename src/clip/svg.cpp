// SVG picture of a shadow region. Doubles appear only as drawing coordinates.
#include "shadowproof/clip/svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace shadowproof {

namespace {

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

// Short label for a tick: up to 4 significant digits.
std::string tick_label(const rational& q) {
  if (q.get_den() == 1 && bit_size(q) < 40) return to_string(q);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", to_nearest_double(q));
  return std::string("~") + buf;
}

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

struct view {
  double u0, v0, u1, v1, scale, left, top;
  double x(const rational& u) const { return left + (to_nearest_double(u) - u0) * scale; }
  double y(const rational& v) const { return top + (v1 - to_nearest_double(v)) * scale; }
};

std::string ring_path(const view& w, const std::vector<point2>& ring) {
  std::ostringstream p;
  for (std::size_t i = 0; i < ring.size(); ++i)
    p << (i == 0 ? "M" : "L") << fmt(w.x(ring[i][0])) << ',' << fmt(w.y(ring[i][1])) << ' ';
  if (!ring.empty()) p << "Z ";
  return p.str();
}

}  // namespace

void write_svg(std::ostream& out, const shadow_region& r, const std::string& title) {
  const double plot = 560.0;
  const double u0 = to_nearest_double(r.view_box[0]), v0 = to_nearest_double(r.view_box[1]);
  const double u1 = to_nearest_double(r.view_box[2]), v1 = to_nearest_double(r.view_box[3]);
  const double span = std::max(u1 - u0, v1 - v0);
  const double scale = span > 0 ? plot / span : 1.0;
  const view w{u0, v0, u1, v1, scale, 80.0, 110.0};
  const double pw = (u1 - u0) * scale, ph = (v1 - v0) * scale;
  const double legend_x = w.left + pw + 40.0;
  const double width = legend_x + 330.0;
  const double height = w.top + ph + 80.0;

  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(width) << "\" height=\"" << fmt(height)
      << "\" viewBox=\"0 0 " << fmt(width) << ' ' << fmt(height) << "\" font-family=\"sans-serif\" font-size=\"14\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out << "<text x=\"20\" y=\"30\" font-size=\"18\" font-weight=\"bold\">" << escape(title) << "</text>\n";
  std::string cases;
  for (auto c : r.cases) cases += (cases.empty() ? "" : ", ") + std::string(to_string(c));
  // Exact values that fit the line; a long rational (a mesh with decimal coordinates) as its
  // approximation, the exact value being in the text and JSON outputs.
  const std::string chart_area = to_string(r.chart_area), area_squared = to_string(r.area_squared);
  if (chart_area.size() + area_squared.size() <= 80) {
    out << "<text x=\"20\" y=\"55\">shadow area in the chart: " << escape(chart_area) << "   (3D area)\u00b2: "
        << escape(area_squared) << "</text>\n";
  } else {
    char approx[64];
    std::snprintf(approx, sizeof approx, "%.10g", approximate_area(r));
    out << "<text x=\"20\" y=\"55\">shadow area (3D): ~" << approx
        << " (the exact area_squared, a rational of " << area_squared.size() << " digits, is in the text and JSON output)</text>\n";
  }
  out << "<text x=\"20\" y=\"78\">cases: " << escape(cases.empty() ? "none" : cases) << "</text>\n";

  // Plot frame and clip to it (projected casters may leave the view box only by rounding).
  out << "<defs><clipPath id=\"plot\"><rect x=\"" << fmt(w.left) << "\" y=\"" << fmt(w.top) << "\" width=\""
      << fmt(pw) << "\" height=\"" << fmt(ph) << "\"/></clipPath></defs>\n";
  out << "<rect x=\"" << fmt(w.left) << "\" y=\"" << fmt(w.top) << "\" width=\"" << fmt(pw) << "\" height=\""
      << fmt(ph) << "\" fill=\"#fbfbfb\" stroke=\"#999\"/>\n";
  out << "<g clip-path=\"url(#plot)\">\n";

  // Receiver with holes.
  std::string rp = ring_path(w, r.receiver_outer);
  for (const auto& h : r.receiver_holes) rp += ring_path(w, h);
  out << "<path d=\"" << rp << "\" fill=\"#d9d9d9\" fill-rule=\"evenodd\" stroke=\"#555\" stroke-width=\"1.5\"/>\n";

  // Shadow region.
  for (const auto& p : r.polygons) {
    std::string sp = ring_path(w, p.outer);
    for (const auto& h : p.holes) sp += ring_path(w, h);
    out << "<path d=\"" << sp << "\" fill=\"#3a3a4a\" fill-opacity=\"0.85\" fill-rule=\"evenodd\" stroke=\"black\" stroke-width=\"1\"/>\n";
  }

  // Projected casters before the receiver clip: dashed.
  std::string pp;
  for (const auto& l : r.projected_loops) pp += ring_path(w, l);
  if (!pp.empty())
    out << "<path d=\"" << pp << "\" fill=\"#1f5fbf\" fill-opacity=\"0.08\" fill-rule=\"evenodd\" stroke=\"#1f5fbf\" stroke-width=\"1.5\" stroke-dasharray=\"7,4\"/>\n";
  for (const auto& d : r.projected_degenerate)
    out << "<line x1=\"" << fmt(w.x(d[0][0])) << "\" y1=\"" << fmt(w.y(d[0][1])) << "\" x2=\"" << fmt(w.x(d[1][0]))
        << "\" y2=\"" << fmt(w.y(d[1][1])) << "\" stroke=\"#1f5fbf\" stroke-width=\"1.5\" stroke-dasharray=\"7,4\"/>\n";

  // Degenerate pieces, highlighted.
  for (const auto& d : r.degenerate) {
    if (d.is_point())
      out << "<circle cx=\"" << fmt(w.x(d.a[0])) << "\" cy=\"" << fmt(w.y(d.a[1]))
          << "\" r=\"5\" fill=\"#e01010\" stroke=\"white\" stroke-width=\"1\"/>\n";
    else
      out << "<line x1=\"" << fmt(w.x(d.a[0])) << "\" y1=\"" << fmt(w.y(d.a[1])) << "\" x2=\"" << fmt(w.x(d.b[0]))
          << "\" y2=\"" << fmt(w.y(d.b[1])) << "\" stroke=\"#e01010\" stroke-width=\"4\" stroke-linecap=\"round\"/>\n";
  }
  // The light: a point light's position seen along the dropped axis (when in view).
  const auto& L = r.light;
  const bool point_light = sgn(L[3]) != 0;
  if (point_light) {
    const int k = r.chart.dropped_axis;
    const rational lu = L[static_cast<std::size_t>((k + 1) % 3)] / L[3], lv = L[static_cast<std::size_t>((k + 2) % 3)] / L[3];
    out << "<circle cx=\"" << fmt(w.x(lu)) << "\" cy=\"" << fmt(w.y(lv)) << "\" r=\"7\" fill=\"#ffd21f\" stroke=\"#8a6d00\" stroke-width=\"1.5\"/>\n";
  }
  out << "</g>\n";

  // Axes: ticks at the receiver's extent and the view box ends, labelled exactly when short.
  rational umin = r.receiver_outer[0][0], umax = umin, vmin = r.receiver_outer[0][1], vmax = vmin;
  for (const auto& p : r.receiver_outer) {
    umin = std::min(umin, p[0]); umax = std::max(umax, p[0]);
    vmin = std::min(vmin, p[1]); vmax = std::max(vmax, p[1]);
  }
  const double base_y = w.top + ph, base_x = w.left;
  for (const rational& u : {umin, umax}) {
    const double x = w.x(u);
    out << "<line x1=\"" << fmt(x) << "\" y1=\"" << fmt(base_y) << "\" x2=\"" << fmt(x) << "\" y2=\"" << fmt(base_y + 6)
        << "\" stroke=\"black\"/><text x=\"" << fmt(x) << "\" y=\"" << fmt(base_y + 22) << "\" text-anchor=\"middle\">"
        << escape(tick_label(u)) << "</text>\n";
  }
  for (const rational& v : {vmin, vmax}) {
    const double y = w.y(v);
    out << "<line x1=\"" << fmt(base_x - 6) << "\" y1=\"" << fmt(y) << "\" x2=\"" << fmt(base_x) << "\" y2=\"" << fmt(y)
        << "\" stroke=\"black\"/><text x=\"" << fmt(base_x - 10) << "\" y=\"" << fmt(y + 5) << "\" text-anchor=\"end\">"
        << escape(tick_label(v)) << "</text>\n";
  }
  const std::string ua(r.chart.axis_name(0)), va(r.chart.axis_name(1));
  const std::string dropped(r.chart.axis_name(2));
  out << "<text x=\"" << fmt(w.left + pw / 2) << "\" y=\"" << fmt(base_y + 50) << "\" text-anchor=\"middle\" font-style=\"italic\">u = "
      << ua << "  (chart of the receiver plane; " << dropped << " is dropped)</text>\n";
  out << "<text transform=\"translate(" << fmt(w.left - 55) << ',' << fmt(w.top + ph / 2)
      << ") rotate(-90)\" text-anchor=\"middle\" font-style=\"italic\">v = " << va << "</text>\n";

  // Legend.
  double ly = w.top + 10;
  const auto item = [&](const std::string& swatch, const std::string& text) {
    out << "<g transform=\"translate(" << fmt(legend_x) << ',' << fmt(ly) << ")\">" << swatch << "<text x=\"42\" y=\"14\">"
        << escape(text) << "</text></g>\n";
    ly += 30;
  };
  out << "<text x=\"" << fmt(legend_x) << "\" y=\"" << fmt(ly - 2) << "\" font-weight=\"bold\">legend</text>\n";
  ly += 10;
  item("<rect width=\"32\" height=\"18\" fill=\"#d9d9d9\" stroke=\"#555\"/>", "receiver (holes white)");
  item("<rect width=\"32\" height=\"18\" fill=\"#3a3a4a\" stroke=\"black\"/>", "exact shadow region");
  item("<rect width=\"32\" height=\"18\" fill=\"#1f5fbf\" fill-opacity=\"0.08\" stroke=\"#1f5fbf\" stroke-dasharray=\"7,4\"/>",
       "projected casters, before the clip");
  item("<line x1=\"0\" y1=\"9\" x2=\"32\" y2=\"9\" stroke=\"#e01010\" stroke-width=\"4\"/>", "zero-area shadow: segment");
  item("<circle cx=\"16\" cy=\"9\" r=\"5\" fill=\"#e01010\"/>", "zero-area shadow: point");
  if (point_light)
    item("<circle cx=\"16\" cy=\"9\" r=\"7\" fill=\"#ffd21f\" stroke=\"#8a6d00\"/>",
         "point light (" + tick_label(L[0] / L[3]) + ", " + tick_label(L[1] / L[3]) + ", " + tick_label(L[2] / L[3]) + ")");
  else
    item("<text x=\"4\" y=\"15\" font-size=\"18\">\u2600</text>",
         "sun towards (" + tick_label(L[0]) + ", " + tick_label(L[1]) + ", " + tick_label(L[2]) + ")");
  std::size_t npts = 0;
  for (const auto& d : r.degenerate) npts += d.is_point() ? 1 : 0;
  ly += 10;
  out << "<text x=\"" << fmt(legend_x) << "\" y=\"" << fmt(ly) << "\">" << r.polygons.size() << " polygon(s), "
      << (r.degenerate.size() - npts) << " segment(s), " << npts << " point(s)</text>\n";
  out << "<text x=\"" << fmt(legend_x) << "\" y=\"" << fmt(ly + 22) << "\">area scale\u00b2 (3D/chart): "
      << escape(to_string(r.chart.area_scale_squared)) << "</text>\n";
  out << "</svg>\n";
}

}  // namespace shadowproof
