#include "derivations.h"

namespace shadowproof::proofs {

std::vector<derivation> all_derivations() {
  // Built in a fixed order: symbols are numbered as they are made, and GiNaC's internal term
  // order depends on those numbers (the document printer sorts on its own, but messages do not).
  std::vector<derivation> all;
  all.push_back(shadow_matrix());
  all.push_back(seed000_directional());
  all.push_back(seed001_ground_plane());
  all.push_back(seed002_point_light_ground());
  all.push_back(seed003_shadow_polygon());
  all.push_back(reflection());
  all.push_back(seed003_reflection_frames());
  all.push_back(orthographic());
  all.push_back(perspective_normalisation());
  all.push_back(frustum());
  all.push_back(games101_perspective());
  all.push_back(normal_matrix());
  all.push_back(change_of_basis());
  return all;
}

}  // namespace shadowproof::proofs
