#pragma once
/// Every derivation, one per file under derivations/, in the order the document presents them.
#include <string>
#include <vector>

#include "checker.h"
#include "mat.h"
#include "term.h"

namespace shadowproof::proofs {

/// A new variable printed as `tex`.
inline term var(const std::string& name, const std::string& tex) { return term::variable(name, tex); }

derivation shadow_matrix();
derivation point_classes();
derivation seed000_directional();
derivation seed001_ground_plane();
derivation seed002_point_light_ground();
derivation seed003_shadow_polygon();
derivation reflection();
derivation seed003_reflection_frames();
derivation orthographic();
derivation oblique();
derivation perspective_normalisation();
derivation frustum();
derivation games101_perspective();
derivation normal_matrix();
derivation change_of_basis();

/// The slugs of all derivations, in document order.
std::vector<std::string> derivation_slugs();
/// Builds one derivation. Building may fail (the library throws, or a comparison its facts do not
/// decide): the derivation is then returned with its build_error set. Throws std::out_of_range
/// for an unknown slug.
derivation build_derivation(const std::string& slug);
/// All derivations in document order.
std::vector<derivation> all_derivations();

}  // namespace shadowproof::proofs
