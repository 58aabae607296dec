// The SVG writer: elements appended to one string, numbers at a fixed precision.
#include "shadowproof/core/svg.h"

#include <cmath>
#include <cstdio>

namespace shadowproof {

std::string svg_escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

svg_document::svg_document(double width, double height, int font_size, int decimals) : decimals_(decimals) {
  body_ = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + number(width) + "\" height=\"" + number(height) +
          "\" font-family=\"sans-serif\" font-size=\"" + std::to_string(font_size) +
          "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

std::string svg_document::number(double x) const {
  if (!std::isfinite(x)) x = 0;  // a picture coordinate; never NaN in the file
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals_, x);
  return buf;
}

svg_document& svg_document::line(double x1, double y1, double x2, double y2, std::string_view stroke,
                                 double stroke_width) {
  body_ += "<line x1=\"" + number(x1) + "\" y1=\"" + number(y1) + "\" x2=\"" + number(x2) + "\" y2=\"" + number(y2) +
           "\" stroke=\"" + svg_escape(stroke) + "\"";
  if (stroke_width != 1) body_ += " stroke-width=\"" + number(stroke_width) + "\"";
  body_ += "/>\n";
  return *this;
}

svg_document& svg_document::rect(double x, double y, double w, double h, std::string_view fill, std::string_view stroke) {
  body_ += "<rect x=\"" + number(x) + "\" y=\"" + number(y) + "\" width=\"" + number(w) + "\" height=\"" + number(h) +
           "\" fill=\"" + svg_escape(fill) + "\" stroke=\"" + svg_escape(stroke) + "\"/>\n";
  return *this;
}

svg_document& svg_document::circle(double cx, double cy, double r, std::string_view fill, double opacity) {
  body_ += "<circle cx=\"" + number(cx) + "\" cy=\"" + number(cy) + "\" r=\"" + number(r) + "\" fill=\"" +
           svg_escape(fill) + "\"";
  if (opacity < 1) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", opacity);
    body_ += std::string(" fill-opacity=\"") + buf + "\"";
  }
  body_ += "/>\n";
  return *this;
}

svg_document& svg_document::text(double x, double y, std::string_view content, std::string_view anchor,
                                 std::string_view fill, int size, double rotate) {
  body_ += "<text x=\"" + number(x) + "\" y=\"" + number(y) + "\"";
  if (anchor != "start") body_ += " text-anchor=\"" + svg_escape(anchor) + "\"";
  if (!fill.empty()) body_ += " fill=\"" + svg_escape(fill) + "\"";
  if (size > 0) body_ += " font-size=\"" + std::to_string(size) + "\"";
  if (rotate != 0) body_ += " transform=\"rotate(" + number(rotate) + " " + number(x) + " " + number(y) + ")\"";
  body_ += ">" + svg_escape(content) + "</text>\n";
  return *this;
}

svg_document& svg_document::polyline(const std::vector<std::pair<double, double>>& points, std::string_view stroke,
                                     double stroke_width) {
  body_ += "<polyline fill=\"none\" stroke=\"" + svg_escape(stroke) + "\" stroke-width=\"" + number(stroke_width) +
           "\" points=\"";
  for (std::size_t i = 0; i < points.size(); ++i)
    body_ += (i ? " " : "") + number(points[i].first) + "," + number(points[i].second);
  body_ += "\"/>\n";
  return *this;
}

svg_document& svg_document::path(std::string_view d, std::string_view fill, std::string_view stroke,
                                 double stroke_width, std::string_view extra) {
  body_ += "<path d=\"" + svg_escape(d) + "\" fill=\"" + svg_escape(fill) + "\" stroke=\"" + svg_escape(stroke) +
           "\" stroke-width=\"" + number(stroke_width) + "\"";
  if (!extra.empty()) body_ += " " + std::string(extra);
  body_ += "/>\n";
  return *this;
}

std::string svg_document::str() const { return body_ + "</svg>\n"; }

}  // namespace shadowproof
