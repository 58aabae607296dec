// Fuzz target: the silhouette region builder against the union-of-pieces reference, exactly.
// The input decodes (generate_clip_scene over the fuzzer's bytes) to a small scene biased to
// exact degeneracies: closed, open, non-manifold and flipped meshes and triangle soups on a
// small integer grid, lights on, above, below and parallel to the receiver or at a caster's
// vertex. Invariants:
// - both builders reject the same scenes with the same shadowproof::error (the only exception
//   swallowed here: a rejected input); shadowproof::internal_error and anything else escape,
//   and libFuzzer reports them;
// - otherwise they give the identical region: polygons in the chart and in 3D, chart area,
//   area_squared, zero-area pieces, cases, and the projected outlines of the picture;
// - the region lies in the receiver: its chart area is at most the receiver's.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "byte_source.h"
#include "shadowproof/clip/generate_scene.h"
#include "shadowproof/clip/shadow_region.h"
#include "shadowproof/core/error.h"

namespace {

using namespace shadowproof;

bool same_region(const shadow_region& a, const shadow_region& b) {
  if (a.area_squared != b.area_squared || a.chart_area != b.chart_area || a.cases != b.cases) return false;
  if (a.polygons.size() != b.polygons.size() || a.degenerate.size() != b.degenerate.size()) return false;
  for (std::size_t i = 0; i < a.polygons.size(); ++i)
    if (a.polygons[i].outer != b.polygons[i].outer || a.polygons[i].holes != b.polygons[i].holes ||
        a.polygons[i].outer_3d != b.polygons[i].outer_3d || a.polygons[i].holes_3d != b.polygons[i].holes_3d)
      return false;
  for (std::size_t i = 0; i < a.degenerate.size(); ++i)
    if (a.degenerate[i].a != b.degenerate[i].a || a.degenerate[i].b != b.degenerate[i].b ||
        a.degenerate[i].a_3d != b.degenerate[i].a_3d || a.degenerate[i].b_3d != b.degenerate[i].b_3d)
      return false;
  return a.projected_loops == b.projected_loops && a.projected_degenerate == b.projected_degenerate;
}

rational ring_area(const std::vector<point2>& p) {
  rational twice = 0;
  for (std::size_t i = 0; i < p.size(); ++i) twice += p[i][0] * p[(i + 1) % p.size()][1] - p[i][1] * p[(i + 1) % p.size()][0];
  return twice / 2;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  byte_source src(data, size);
  const scene s = generate_clip_scene(src, 3, 8);
  clip_options reference, silhouette;
  reference.method = clip_method::union_of_pieces;
  silhouette.method = clip_method::silhouette;
  std::string reference_error, silhouette_error;
  shadow_region a, b;
  try {
    a = compute_shadow_region(s, reference);
  } catch (const error& e) {
    reference_error = e.what();
  }
  try {
    b = compute_shadow_region(s, silhouette);
  } catch (const error& e) {
    silhouette_error = e.what();
  }
  if (reference_error != silhouette_error) std::abort();  // one builder rejects what the other accepts
  if (!reference_error.empty()) return 0;
  if (!same_region(a, b)) std::abort();
  rational receiver_area = ring_area(a.receiver_outer);
  for (const auto& h : a.receiver_holes) receiver_area += ring_area(h);  // clockwise: negative
  if (a.chart_area > receiver_area) std::abort();
  return 0;
}
