#pragma once
// The boundary chain of a caster's shadow: every face that casts contributes its projected
// boundary, oriented counter-clockwise in the chart, and half-edges shared by two faces with
// opposite directions cancel. The winding number of the chain at a chart point off its edges
// is the number of projected faces covering it (chain.cpp).
#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include "region_setup.h"

namespace shadowproof::detail {

/// A directed chart segment points[a] → points[b] counted `weight` times (negative: the
/// other way round).
struct chain_segment {
  std::size_t a = 0, b = 0;
  long weight = 1;
};

/// What the faces of one caster contribute.
struct caster_chain {
  std::vector<point2> points;            ///< chart points, each once per vertex or piece corner
  std::vector<chain_segment> segments;   ///< after cancellation
  std::size_t half_edges = 0;            ///< before cancellation (face boundaries that cast)
  std::size_t exact_faces = 0;           ///< faces decided by exact arithmetic (filter failed or clipped)
};

/// Builds the chain of caster ci: triangles whose vertices all lie inside the clip
/// half-spaces are classified by interval filters (exact rationals only when a filter cannot
/// decide) and contribute vertex-index half-edges, cancelled combinatorially before any
/// projection; every other face is validated, split into convex pieces, clipped and projected
/// exactly like the reference builder. Zero-area projected pieces go to `degenerate`.
/// `progress(done)` is called now and then with the number of faces processed.
caster_chain build_chain(const clip_setup& setup, std::size_t ci, case_set& cases,
                         std::vector<std::array<point2, 2>>& degenerate, const std::function<void(std::size_t)>& progress);

}  // namespace shadowproof::detail
