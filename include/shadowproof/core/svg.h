#pragma once
/// A small writer of standalone SVG pictures, shared by every plot and figure shadowproof draws:
/// coordinates printed with a fixed number of decimals (a picture, never a value), text escaped.
/// Exact values belong in the text and JSON outputs; SVG coordinates are doubles by nature.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace shadowproof {

/// `text` with &, <, > and " escaped for SVG text and attribute values.
std::string svg_escape(std::string_view text);

class svg_document {
 public:
  /// A width × height picture on a white background, sans-serif text of `font_size` pixels,
  /// coordinates printed with `decimals` digits after the point.
  svg_document(double width, double height, int font_size = 11, int decimals = 1);

  /// A straight line from (x1, y1) to (x2, y2).
  svg_document& line(double x1, double y1, double x2, double y2, std::string_view stroke, double stroke_width = 1);
  /// An axis-aligned rectangle; `stroke` "none" draws no outline.
  svg_document& rect(double x, double y, double w, double h, std::string_view fill, std::string_view stroke = "none");
  /// A disc; opacity below 1 lets overlapping marks show their density.
  svg_document& circle(double cx, double cy, double r, std::string_view fill, double opacity = 1);
  /// Text at (x, y) (baseline), anchored "start", "middle" or "end"; `fill` and `size` empty or
  /// 0 keep the document's defaults; `rotate` turns it by that many degrees about (x, y).
  svg_document& text(double x, double y, std::string_view text, std::string_view anchor = "start",
                     std::string_view fill = "", int size = 0, double rotate = 0);
  /// An open polyline through the points.
  svg_document& polyline(const std::vector<std::pair<double, double>>& points, std::string_view stroke,
                         double stroke_width = 1);
  /// A path with SVG path data `d` (build it with number()); `extra` holds further attributes
  /// (e.g. "stroke-dasharray=\"4 3\" fill-rule=\"evenodd\"").
  svg_document& path(std::string_view d, std::string_view fill, std::string_view stroke, double stroke_width = 1,
                     std::string_view extra = "");
  /// A coordinate as the document prints it.
  std::string number(double x) const;
  /// The whole document, closing tag included.
  std::string str() const;

 private:
  std::string body_;
  int decimals_;
};

}  // namespace shadowproof
