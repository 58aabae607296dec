#pragma once
// The two region builders behind compute_shadow_region (shadow_region.cpp picks one).
#include "shadowproof/clip/shadow_region.h"

namespace shadowproof::detail {

/// The reference: every caster face split into convex pieces, each clipped in 3D and
/// projected exactly, one aggregate union of all pieces with CGAL's Boolean operations, then
/// the intersection with the receiver (union_of_pieces.cpp).
shadow_region union_of_pieces_region(const scene& s, const plane<rational>& P, const clip_options& options);

/// Boundary chains: faces classified against the light by filtered predicates, shared
/// half-edges cancelled combinatorially, the remaining edges projected exactly into one CGAL
/// arrangement with the receiver, winding numbers assigned by walking across edges
/// (silhouette.cpp).
shadow_region silhouette_region(const scene& s, const plane<rational>& P, const clip_options& options);

}  // namespace shadowproof::detail
