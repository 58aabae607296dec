#pragma once
/// SVG pictures of a shadow region in the receiver's chart.
#include <ostream>
#include <string>

#include "shadowproof/clip/shadow_region.h"

namespace shadowproof {

/// Writes a self-contained SVG of `r` in its chart (u to the right, v up): the receiver
/// (grey, holes white), the projected casters before the receiver clip (dashed blue outline,
/// cut to the view box), the shadow region (dark), the zero-area pieces (red segments and
/// dots), axis labels naming the 3D coordinates of the chart, tick values, a legend, the exact
/// area and the named cases. Coordinates are drawn as doubles (the picture only; the exact
/// values are in the text and JSON outputs). `title` is printed at the top.
void write_svg(std::ostream& out, const shadow_region& r, const std::string& title);

}  // namespace shadowproof
