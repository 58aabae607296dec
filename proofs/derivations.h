#pragma once
/// Every derivation, one per file under derivations/, in the order the document presents them.
#include <vector>

#include "checker.h"

namespace shadowproof::proofs {

derivation shadow_matrix();
derivation seed000_directional();
derivation seed001_ground_plane();
derivation seed002_point_light_ground();
derivation seed003_shadow_polygon();
derivation reflection();
derivation seed003_reflection_frames();
derivation orthographic();
derivation perspective_normalisation();
derivation frustum();
derivation games101_perspective();
derivation normal_matrix();
derivation change_of_basis();

/// All derivations in document order.
std::vector<derivation> all_derivations();

}  // namespace shadowproof::proofs
