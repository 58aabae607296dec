// SVG pictures of explanations. The geometry is exact; doubles appear only as drawing
// coordinates, rounded once each.
#include "shadowproof/explain/figure.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <set>
#include <sstream>

namespace shadowproof {

void figure_panel::polygon(std::vector<point3> corners, figure_style s, std::string label) {
  items.push_back({figure_item::shape::polygon, std::move(corners), s, std::move(label)});
}

void figure_panel::segment(const point3& a, const point3& b, figure_style s, std::string label) {
  items.push_back({figure_item::shape::segment, {a, b}, s, std::move(label)});
}

void figure_panel::arrow(const point3& from, const point3& to, figure_style s, std::string label) {
  items.push_back({figure_item::shape::arrow, {from, to}, s, std::move(label)});
}

void figure_panel::dot(const point3& p, figure_style s, std::string label) {
  items.push_back({figure_item::shape::dot, {p}, s, std::move(label)});
}

void figure_panel::hexahedron(const std::array<point3, 8>& c, figure_style s) {
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) segment(c[i], c[i | bit], s);
}

namespace {

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  std::string s = buf;
  return s == "-0.00" ? "0.00" : s;
}

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else o += c;
  }
  return o;
}

struct look {
  const char* stroke;
  const char* fill;
  const char* dash;
  double width;
  const char* legend;
};

look look_of(figure_style s) {
  switch (s) {
    case figure_style::receiver: return {"#8a8a8a", "#e4e4e4", "", 1.0, "receiver"};
    case figure_style::mirror: return {"#5b8db8", "#dcebf7", "", 1.0, "mirror"};
    case figure_style::plane: return {"#8a8a8a", "#eeeeee", "", 1.0, "projection plane"};
    case figure_style::light: return {"#b07800", "#ffd54a", "", 1.5, "light"};
    case figure_style::light_travel: return {"#c98a00", "none", "", 1.5, "light travels"};
    case figure_style::point: return {"#163f80", "#2f6fd6", "", 1.0, "point"};
    case figure_style::real_shadow: return {"#6e120c", "#b3261e", "", 1.0, "real shadow"};
    case figure_style::false_shadow: return {"#b3261e", "white", "", 1.8, "false shadow (behind the receiver)"};
    case figure_style::anti_shadow: return {"#4a1d7a", "#8e5cc7", "", 1.0, "anti-shadow (beyond the light)"};
    case figure_style::image: return {"#6e120c", "#b3261e", "", 1.0, "image"};
    case figure_style::ray: return {"#e08a00", "none", "", 1.6, "ray"};
    case figure_style::extension: return {"#e08a00", "none", "5,4", 1.3, "same line, no light on it"};
    case figure_style::volume: return {"#2b6cb0", "none", "", 1.4, "view volume"};
    case figure_style::canonical: return {"#2f855a", "none", "", 1.4, "canonical volume (NDC)"};
    case figure_style::axis: return {"#9a9a9a", "none", "", 1.0, "axes"};
    case figure_style::frame_axis: return {"#2f855a", "none", "", 2.0, "frame axes"};
    case figure_style::normal: return {"#222222", "none", "", 2.0, "normal"};
    case figure_style::tangent: return {"#2f6fd6", "none", "", 2.0, "tangent"};
    case figure_style::wrong: return {"#d11a1a", "none", "4,3", 1.6, "what the wrong formula gives"};
    case figure_style::link: return {"#777777", "none", "5,4", 1.3, "a point and its image"};
    case figure_style::walk: return {"#2f855a", "none", "5,4", 1.3, "O_c + a X_c + b Y_c + c Z_c"};
  }
  return {"black", "none", "", 1.0, ""};
}

struct projected {
  double x, y;
};

// The panel's parallel projection (see figure_view), computed exactly, rounded once.
projected view_of(const point3& p, figure_view v) {
  rational sx, sy;
  switch (v) {
    case figure_view::front: sx = p[0] - rational(2, 5) * p[2], sy = p[1] - rational(1, 2) * p[2]; break;
    case figure_view::side: sx = -p[2] - rational(3, 10) * p[0], sy = p[1] - rational(1, 5) * p[0]; break;
    case figure_view::depth: sx = p[0] + rational(2, 5) * p[2], sy = p[1] + rational(1, 2) * p[2]; break;
  }
  return {to_nearest_double(sx), to_nearest_double(sy)};
}

struct frame {
  double x0, y0, scale, left, top;
  double x(const projected& p) const { return left + (p.x - x0) * scale; }
  double y(const projected& p) const { return top - (p.y - y0) * scale; }
};

constexpr double panel_height = 400, margin = 48, title_height = 56, legend_line = 18, legend_column = 250;

frame fit(const figure_panel& panel, double left, double top, double panel_width) {
  double x0 = std::numeric_limits<double>::max(), x1 = std::numeric_limits<double>::lowest();
  double y0 = x0, y1 = x1;
  for (const auto& item : panel.items)
    for (const auto& p : item.at) {
      const projected q = view_of(p, panel.view);
      x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
    }
  if (x0 > x1) x0 = x1 = y0 = y1 = 0;
  const double w = std::max(x1 - x0, 1e-9), h = std::max(y1 - y0, 1e-9);
  // Labels go to the right of their points: keep more room on that side.
  const double right_room = 140;
  const double scale = std::min((panel_width - margin - right_room) / w, (panel_height - 2 * margin - 20) / h);
  const double used_w = w * scale, used_h = h * scale;
  const double l = left + margin + (panel_width - margin - right_room - used_w) / 2;
  const double t = top + 20 + (panel_height - 20 - used_h) / 2 + used_h;
  return {x0, y0, scale, l, t};
}

std::string stroke_attributes(const look& k) {
  std::string s = " stroke=\"" + std::string(k.stroke) + "\" stroke-width=\"" + fmt(k.width) + "\"";
  if (*k.dash) s += " stroke-dasharray=\"" + std::string(k.dash) + "\"";
  return s;
}

void draw_item(std::ostringstream& out, const figure_item& item, const frame& f, figure_view v) {
  const look k = look_of(item.style);
  switch (item.kind) {
    case figure_item::shape::polygon: {
      out << "<path d=\"";
      for (std::size_t i = 0; i < item.at.size(); ++i) {
        const projected p = view_of(item.at[i], v);
        out << (i ? " L" : "M") << fmt(f.x(p)) << ',' << fmt(f.y(p));
      }
      out << " Z\" fill=\"" << k.fill << "\" fill-opacity=\"0.75\"" << stroke_attributes(k) << "/>\n";
      break;
    }
    case figure_item::shape::segment:
    case figure_item::shape::arrow: {
      const projected a = view_of(item.at[0], v), b = view_of(item.at[1], v);
      out << "<line x1=\"" << fmt(f.x(a)) << "\" y1=\"" << fmt(f.y(a)) << "\" x2=\"" << fmt(f.x(b)) << "\" y2=\""
          << fmt(f.y(b)) << "\"" << stroke_attributes(k);
      if (item.kind == figure_item::shape::arrow) out << " marker-end=\"url(#head" << static_cast<int>(item.style) << ")\"";
      out << "/>\n";
      break;
    }
    case figure_item::shape::dot: {
      const projected p = view_of(item.at[0], v);
      const double r = item.style == figure_style::light ? 7.5 : 4.5;
      out << "<circle cx=\"" << fmt(f.x(p)) << "\" cy=\"" << fmt(f.y(p)) << "\" r=\"" << fmt(r) << "\" fill=\"" << k.fill
          << "\"" << stroke_attributes(k) << "/>\n";
      break;
    }
  }
}

void draw_label(std::ostringstream& out, const figure_item& item, const frame& f, figure_view v) {
  if (item.label.empty()) return;
  projected at{0, 0};
  if (item.kind == figure_item::shape::dot) {
    at = view_of(item.at[0], v);
  } else if (item.kind == figure_item::shape::polygon) {
    at = view_of(item.at[0], v);
  } else {
    at = view_of(item.at[1], v);
  }
  out << "<text x=\"" << fmt(f.x(at) + 8) << "\" y=\"" << fmt(f.y(at) - 7) << "\" font-size=\"12\" fill=\"#222\""
      << " stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">" << escape(item.label) << "</text>\n";
}

}  // namespace

std::string to_svg(const figure& fig) {
  const std::size_t panels = std::max<std::size_t>(fig.panels.size(), 1);
  const double panel_width = panels == 1 ? 620 : 450;
  std::set<int> used;
  for (const auto& panel : fig.panels)
    for (const auto& item : panel.items) used.insert(static_cast<int>(item.style));
  // One legend entry per look; several styles may share a legend text.
  std::vector<int> legend;
  std::set<std::string> legend_texts;
  for (int s : used)
    if (legend_texts.insert(look_of(static_cast<figure_style>(s)).legend).second) legend.push_back(s);
  // Wide enough for the title (about 9 px a character at 17 px bold).
  const double width = std::max(static_cast<double>(panels) * panel_width + 20, 9.0 * static_cast<double>(fig.title.size()) + 40);
  const std::size_t per_row = std::max<std::size_t>(1, static_cast<std::size_t>((width - 20) / legend_column));
  const double legend_height = 16 + legend_line * static_cast<double>((legend.size() + per_row - 1) / per_row);
  const double height = title_height + panel_height + legend_height + 10;

  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fmt(width) << "\" height=\"" << fmt(height)
      << "\" viewBox=\"0 0 " << fmt(width) << ' ' << fmt(height) << "\" font-family=\"sans-serif\" font-size=\"14\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<defs>\n";
  for (int s : used) {
    const look k = look_of(static_cast<figure_style>(s));
    out << "<marker id=\"head" << s << "\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" markerHeight=\"7\""
        << " orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"" << k.stroke << "\"/></marker>\n";
  }
  out << "</defs>\n";
  out << "<text x=\"16\" y=\"30\" font-size=\"17\" font-weight=\"bold\">" << escape(fig.title) << "</text>\n";
  for (std::size_t i = 0; i < fig.panels.size(); ++i) {
    const figure_panel& panel = fig.panels[i];
    const double left = 10 + static_cast<double>(i) * panel_width, top = title_height;
    out << "<rect x=\"" << fmt(left + 4) << "\" y=\"" << fmt(top) << "\" width=\"" << fmt(panel_width - 8)
        << "\" height=\"" << fmt(panel_height) << "\" fill=\"#fcfcfc\" stroke=\"#dddddd\"/>\n";
    out << "<text x=\"" << fmt(left + 14) << "\" y=\"" << fmt(top + 20) << "\" font-size=\"14\" fill=\"#333\">"
        << escape(panel.title) << "</text>\n";
    const frame f = fit(panel, left, top, panel_width);
    // Planes first, then lines, then points, then labels on top.
    for (const auto kind : {figure_item::shape::polygon, figure_item::shape::segment, figure_item::shape::arrow,
                            figure_item::shape::dot})
      for (const auto& item : panel.items)
        if (item.kind == kind) draw_item(out, item, f, panel.view);
    for (const auto& item : panel.items) draw_label(out, item, f, panel.view);
  }
  // Legend.
  const double legend_top = title_height + panel_height + 22;
  for (std::size_t i = 0; i < legend.size(); ++i) {
    const look k = look_of(static_cast<figure_style>(legend[i]));
    const double x = 20 + static_cast<double>(i % per_row) * legend_column, y = legend_top + legend_line * static_cast<double>(i / per_row);
    const bool area = std::string(k.fill) != "none" && legend[i] <= static_cast<int>(figure_style::plane);
    const bool dot = std::string(k.fill) != "none" && !area;
    if (area) {
      out << "<rect x=\"" << fmt(x) << "\" y=\"" << fmt(y - 9) << "\" width=\"18\" height=\"11\" fill=\"" << k.fill << "\""
          << stroke_attributes(k) << "/>\n";
    } else if (dot) {
      out << "<circle cx=\"" << fmt(x + 9) << "\" cy=\"" << fmt(y - 4) << "\" r=\"4.5\" fill=\"" << k.fill << "\""
          << stroke_attributes(k) << "/>\n";
    } else {
      out << "<line x1=\"" << fmt(x) << "\" y1=\"" << fmt(y - 4) << "\" x2=\"" << fmt(x + 18) << "\" y2=\"" << fmt(y - 4)
          << "\"" << stroke_attributes(k) << "/>\n";
    }
    out << "<text x=\"" << fmt(x + 26) << "\" y=\"" << fmt(y) << "\" font-size=\"12\" fill=\"#333\">" << escape(k.legend)
        << "</text>\n";
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace shadowproof
