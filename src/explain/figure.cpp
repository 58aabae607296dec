// Pictures of explanations, written with the shared SVG writer. The geometry is exact; doubles
// appear only as drawing coordinates, rounded once each.
#include "shadowproof/explain/figure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <iterator>
#include <set>
#include <utility>
#include <vector>

#include "shadowproof/core/svg.h"

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
    case figure_style::eye: return {"#b07800", "#ffd54a", "", 1.5, "eye"};
    case figure_style::point: return {"#163f80", "#2f6fd6", "", 1.0, "point"};
    case figure_style::real_shadow: return {"#6e120c", "#b3261e", "", 1.0, "real shadow"};
    case figure_style::false_shadow: return {"#b3261e", "white", "", 1.8, "false shadow (behind the receiver)"};
    case figure_style::anti_shadow: return {"#4a1d7a", "#8e5cc7", "", 1.0, "anti-shadow (beyond the light)"};
    case figure_style::image: return {"#6e120c", "#b3261e", "", 1.0, "image"};
    case figure_style::ray: return {"#e08a00", "none", "", 1.6, "ray"};
    case figure_style::extension: return {"#e08a00", "none", "5 4", 1.3, "same line, no light on it"};
    case figure_style::volume: return {"#2b6cb0", "none", "", 1.4, "view volume"};
    case figure_style::canonical: return {"#2f855a", "none", "", 1.4, "canonical volume (NDC)"};
    case figure_style::axis: return {"#9a9a9a", "none", "", 1.0, "axes"};
    case figure_style::frame_axis: return {"#2f855a", "none", "", 2.0, "frame axes"};
    case figure_style::normal: return {"#222222", "none", "", 2.0, "normal"};
    case figure_style::tangent: return {"#2f6fd6", "none", "", 2.0, "tangent"};
    case figure_style::wrong: return {"#d11a1a", "none", "4 3", 1.6, "what the wrong formula gives"};
    case figure_style::link: return {"#777777", "none", "5 4", 1.3, "a point and its image"};
    case figure_style::walk: return {"#2f855a", "none", "5 4", 1.3, "O_c + a X_c + b Y_c + c Z_c"};
  }
  return {"black", "none", "", 1.0, ""};
}

bool is_area(figure_style s) {
  return s == figure_style::receiver || s == figure_style::mirror || s == figure_style::plane;
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
    case figure_view::xz: sx = p[0], sy = p[2]; break;
  }
  return {to_nearest_double(sx), to_nearest_double(sy)};
}

struct frame {
  double x0, y0, scale, left, top;
  projected at(const projected& p) const { return {left + (p.x - x0) * scale, top - (p.y - y0) * scale}; }
};

constexpr double panel_height = 400, margin = 48, title_height = 56, legend_line = 18, legend_column = 250;
// Labels go to the right of their points: keep more room on that side.
constexpr double right_room = 140;

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
  const double scale = std::min((panel_width - margin - right_room) / w, (panel_height - 2 * margin - 20) / h);
  const double used_w = w * scale, used_h = h * scale;
  const double l = left + margin + (panel_width - margin - right_room - used_w) / 2;
  const double t = top + 20 + (panel_height - 20 - used_h) / 2 + used_h;
  return {x0, y0, scale, l, t};
}

std::string dash_of(const look& k) {
  return *k.dash ? "stroke-dasharray=\"" + std::string(k.dash) + "\"" : std::string();
}

void stroke_line(svg_document& svg, const projected& a, const projected& b, const look& k) {
  svg.path("M" + svg.number(a.x) + "," + svg.number(a.y) + " L" + svg.number(b.x) + "," + svg.number(b.y), "none",
           k.stroke, k.width, dash_of(k));
}

// A filled arrowhead at b, pointing from a to b.
void arrowhead(svg_document& svg, const projected& a, const projected& b, const look& k) {
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
  if (len < 1e-9) return;
  const double ux = dx / len, uy = dy / len, size = 9, half = 4;
  const projected base{b.x - ux * size, b.y - uy * size};
  svg.path("M" + svg.number(b.x) + "," + svg.number(b.y) + " L" + svg.number(base.x - uy * half) + "," +
               svg.number(base.y + ux * half) + " L" + svg.number(base.x + uy * half) + "," +
               svg.number(base.y - ux * half) + " Z",
           k.stroke, k.stroke, 1);
}

void draw_item(svg_document& svg, const figure_item& item, const frame& f, figure_view v) {
  const look k = look_of(item.style);
  switch (item.kind) {
    case figure_item::shape::polygon: {
      std::string d;
      for (std::size_t i = 0; i < item.at.size(); ++i) {
        const projected p = f.at(view_of(item.at[i], v));
        d += (i ? " L" : "M") + svg.number(p.x) + "," + svg.number(p.y);
      }
      svg.path(d + " Z", k.fill, k.stroke, k.width, "fill-opacity=\"0.75\"");
      break;
    }
    case figure_item::shape::segment:
    case figure_item::shape::arrow: {
      const projected a = f.at(view_of(item.at[0], v)), b = f.at(view_of(item.at[1], v));
      stroke_line(svg, a, b, k);
      if (item.kind == figure_item::shape::arrow) arrowhead(svg, a, b, k);
      break;
    }
    case figure_item::shape::dot: {
      const projected p = f.at(view_of(item.at[0], v));
      const double r = item.style == figure_style::light || item.style == figure_style::eye ? 7.5 : 4.5;
      const std::string d = "M" + svg.number(p.x - r) + "," + svg.number(p.y) + " a" + svg.number(r) + "," +
                            svg.number(r) + " 0 1,0 " + svg.number(2 * r) + ",0 a" + svg.number(r) + "," +
                            svg.number(r) + " 0 1,0 " + svg.number(-2 * r) + ",0 Z";
      svg.path(d, k.fill, k.stroke, k.width, dash_of(k));
      break;
    }
  }
}

// Label placement: each label takes the first of a few spots around its anchor that overlaps no
// label placed before it, no dot and no drawn line, and stays inside its panel; failing that, the
// spot with the fewest conflicts. Text is 12 px; its width is estimated at 7 px a character.
struct box {
  double x0, y0, x1, y1;
  bool meets(const box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

std::size_t characters(const std::string& utf8) {
  std::size_t n = 0;
  for (unsigned char c : utf8) n += (c & 0xC0) != 0x80;
  return n;
}

// True when the segment a-b passes through the box (tested at a few points along it).
bool crosses(const projected& a, const projected& b, const box& r) {
  for (int i = 0; i <= 24; ++i) {
    const double t = i / 24.0, x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
    if (x > r.x0 && x < r.x1 && y > r.y0 && y < r.y1) return true;
  }
  return false;
}

struct label_placer {
  box panel;
  std::vector<box> taken;  // labels placed and dots drawn
  std::vector<std::pair<projected, projected>> lines;

  // Returns the text position and anchor ("start" or "end").
  std::pair<projected, bool> place(const projected& at, const std::string& text) {
    const double w = 7.0 * static_cast<double>(characters(text)), h = 13;
    struct spot {
      double dx, dy;
      bool left;
    };
    static const spot spots[] = {{8, -7, false},  {8, 17, false},  {-8, -7, true},  {-8, 17, true},
                                 {11, 5, false},  {-11, 5, true},  {8, -22, false}, {-8, -22, true},
                                 {8, 32, false},  {-8, 32, true},  {-w / 2 + 0, -14, false}, {-w / 2, 26, false}};
    double best_cost = std::numeric_limits<double>::max();
    projected best_at{at.x + 8, at.y - 7};
    bool best_left = false;
    for (std::size_t i = 0; i < std::size(spots); ++i) {
      const spot& s = spots[i];
      const projected p{at.x + s.dx, at.y + s.dy};
      const box b = s.left ? box{p.x - w, p.y - h + 3, p.x, p.y + 3} : box{p.x, p.y - h + 3, p.x + w, p.y + 3};
      double cost = 0.01 * static_cast<double>(i);
      if (b.x0 < panel.x0 || b.x1 > panel.x1 || b.y0 < panel.y0 || b.y1 > panel.y1) cost += 1000;
      for (const box& t : taken) cost += b.meets(t) ? 100 : 0;
      for (const auto& [a0, a1] : lines) cost += crosses(a0, a1, b) ? 3 : 0;
      if (cost < best_cost) best_cost = cost, best_at = p, best_left = s.left;
    }
    const box chosen = best_left ? box{best_at.x - w, best_at.y - h + 3, best_at.x, best_at.y + 3}
                                 : box{best_at.x, best_at.y - h + 3, best_at.x + w, best_at.y + 3};
    taken.push_back(chosen);
    return {best_at, best_left};
  }
};

void draw_label(svg_document& svg, const figure_item& item, const frame& f, figure_view v, label_placer& placer) {
  if (item.label.empty()) return;
  const point3& anchor = item.kind == figure_item::shape::segment || item.kind == figure_item::shape::arrow ? item.at[1]
                                                                                                       : item.at[0];
  const auto [at, left] = placer.place(f.at(view_of(anchor, v)), item.label);
  svg.text(at.x, at.y, item.label, left ? "end" : "start", "#222", 12);
}

// The legend swatch of a style: an area, a dot or a line.
void swatch(svg_document& svg, figure_style s, double x, double y) {
  const look k = look_of(s);
  if (is_area(s)) {
    svg.path("M" + svg.number(x) + "," + svg.number(y - 9) + " h18 v11 h-18 Z", k.fill, k.stroke, k.width);
  } else if (std::string(k.fill) != "none") {
    const double r = 4.5, cx = x + 9, cy = y - 4;
    svg.path("M" + svg.number(cx - r) + "," + svg.number(cy) + " a4.5,4.5 0 1,0 9,0 a4.5,4.5 0 1,0 -9,0 Z", k.fill,
             k.stroke, k.width);
  } else {
    stroke_line(svg, {x, y - 4}, {x + 18, y - 4}, k);
  }
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

  svg_document svg(width, height, 14, 2);
  svg.text(16, 30, fig.title, "start", "", 17);
  for (std::size_t i = 0; i < fig.panels.size(); ++i) {
    const figure_panel& panel = fig.panels[i];
    const double left = 10 + static_cast<double>(i) * panel_width, top = title_height;
    svg.rect(left + 4, top, panel_width - 8, panel_height, "#fcfcfc", "#dddddd");
    svg.text(left + 14, top + 20, panel.title, "start", "#333", 14);
    const frame f = fit(panel, left, top, panel_width);
    // Planes first, then lines, then points, then labels on top.
    for (const auto kind : {figure_item::shape::polygon, figure_item::shape::segment, figure_item::shape::arrow,
                            figure_item::shape::dot})
      for (const auto& item : panel.items)
        if (item.kind == kind) draw_item(svg, item, f, panel.view);
    label_placer placer{{left + 6, top + 26, left + panel_width - 6, top + panel_height - 2}, {}, {}};
    for (const auto& item : panel.items) {
      if (item.kind == figure_item::shape::dot) {
        const projected p = f.at(view_of(item.at[0], panel.view));
        placer.taken.push_back({p.x - 6, p.y - 6, p.x + 6, p.y + 6});
      } else if (item.kind != figure_item::shape::polygon) {
        placer.lines.push_back({f.at(view_of(item.at[0], panel.view)), f.at(view_of(item.at[1], panel.view))});
      } else {
        for (std::size_t k = 0; k < item.at.size(); ++k)
          placer.lines.push_back({f.at(view_of(item.at[k], panel.view)),
                                  f.at(view_of(item.at[(k + 1) % item.at.size()], panel.view))});
      }
    }
    for (const auto& item : panel.items) draw_label(svg, item, f, panel.view, placer);
  }
  const double legend_top = title_height + panel_height + 22;
  for (std::size_t i = 0; i < legend.size(); ++i) {
    const double x = 20 + static_cast<double>(i % per_row) * legend_column;
    const double y = legend_top + legend_line * static_cast<double>(i / per_row);
    swatch(svg, static_cast<figure_style>(legend[i]), x, y);
    svg.text(x + 26, y, look_of(static_cast<figure_style>(legend[i])).legend, "start", "#333", 12);
  }
  return svg.str();
}

}  // namespace shadowproof
