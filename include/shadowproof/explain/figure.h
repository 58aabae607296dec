#pragma once
/// Pictures of the derivations, drawn from exact numbers: points, segments, arrows and polygons
/// in 3D with rational coordinates, grouped in panels, and an SVG writer. Doubles appear only as
/// drawing coordinates (every coordinate is rounded to the nearest double, then to 0.01 px).
#include <array>
#include <string>
#include <vector>

#include "shadowproof/core/number.h"

namespace shadowproof {

/// A point (x, y, z) of a figure.
using point3 = std::array<rational, 3>;

/// What an element stands for; the SVG writer gives each its own look and lists the ones used in
/// a legend.
enum class figure_style {
  receiver,       ///< the plane that receives shadows (grey patch)
  mirror,         ///< a mirror plane (blue patch)
  plane,          ///< another plane, e.g. z = 0 of a parallel projection
  light,          ///< a point light (yellow)
  light_travel,   ///< the direction light travels (arrow)
  eye,            ///< the eye of a projection (yellow)
  point,          ///< an input point (blue)
  real_shadow,    ///< its image when it is a real shadow (dark red)
  false_shadow,   ///< its image behind the receiver (hollow red)
  anti_shadow,    ///< its image beyond the light (purple)
  image,          ///< any other image of a point (dark red)
  ray,            ///< the line a point is projected along
  extension,      ///< the same line continued where no light travels (dashed)
  volume,         ///< a view volume: frustum or box (blue)
  canonical,      ///< the canonical view volume, NDC (green)
  axis,           ///< a coordinate axis (grey)
  frame_axis,     ///< an axis of a frame or basis (green)
  normal,         ///< a normal vector (black arrow)
  tangent,        ///< a tangent vector (blue arrow)
  wrong,          ///< what a wrong formula gives (dashed red)
  link,           ///< joins a point to its image (dashed grey)
  walk,           ///< a path along axes, e.g. O_c + a X_c + b Y_c + c Z_c (dashed green)
};

/// One element: a polygon (corners), a segment or arrow (two ends) or a dot, with a label.
struct figure_item {
  enum class shape { polygon, segment, arrow, dot };
  shape kind = shape::dot;
  std::vector<point3> at;
  figure_style style = figure_style::point;
  std::string label;
};

/// How a panel looks at its 3D elements (all are parallel projections, y up):
///   front: (x, y, z) is drawn at (x − 2z/5, y − z/2): −z recedes up and to the right, as a camera
///          looking down −z sees it from behind;
///   side:  at (−z − 3x/10, y − x/5): −z runs to the right, +x comes towards the reader (for
///          frusta and boxes along the view axis);
///   depth: at (x + 2z/5, y + z/2): +z recedes (for NDC volumes whose far plane has the larger z);
///   xz:    at (x, z): the plane y = 0 seen face on, z up (for angles measured in the xz-plane).
enum class figure_view { front, side, depth, xz };

/// One view of a figure, drawn in its own frame with its own scale.
struct figure_panel {
  std::string title;
  std::vector<figure_item> items;
  figure_view view = figure_view::front;

  void polygon(std::vector<point3> corners, figure_style s, std::string label = {});
  void segment(const point3& a, const point3& b, figure_style s, std::string label = {});
  void arrow(const point3& from, const point3& to, figure_style s, std::string label = {});
  void dot(const point3& p, figure_style s, std::string label = {});
  /// The 12 edges of a hexahedron given by its corners in the order (x, y, z) bits: corner i has
  /// the x side (i & 1), the y side (i & 2) and the z side (i & 4).
  void hexahedron(const std::array<point3, 8>& corners, figure_style s);
};

/// A figure: a title, panels side by side, and a caption (Markdown) naming its exact numbers.
struct figure {
  std::string title;
  std::vector<figure_panel> panels;
  std::string caption;
  bool empty() const { return panels.empty(); }
};

/// The SVG of a figure. Each panel shows its elements in its view (figure_view), scaled to fit
/// the panel, with a legend of the styles used. Deterministic: the same figure gives the same
/// bytes.
std::string to_svg(const figure& f);

}  // namespace shadowproof
