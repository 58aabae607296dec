#include "derivations.h"

#include <exception>
#include <stdexcept>
#include <utility>

namespace shadowproof::proofs {

namespace {

using factory = derivation (*)();

const std::vector<std::pair<std::string, factory>>& table() {
  static const std::vector<std::pair<std::string, factory>> all = {
      {"shadow_matrix", shadow_matrix},
      {"point_classes", point_classes},
      {"seed000_directional", seed000_directional},
      {"seed001_ground_plane", seed001_ground_plane},
      {"seed002_point_light_ground", seed002_point_light_ground},
      {"seed003_shadow_polygon", seed003_shadow_polygon},
      {"reflection", reflection},
      {"seed003_reflection_frames", seed003_reflection_frames},
      {"orthographic", orthographic},
      {"oblique", oblique},
      {"perspective_normalisation", perspective_normalisation},
      {"frustum", frustum},
      {"games101_perspective", games101_perspective},
      {"normal_matrix", normal_matrix},
      {"change_of_basis", change_of_basis}};
  return all;
}

}  // namespace

std::vector<std::string> derivation_slugs() {
  std::vector<std::string> slugs;
  for (const auto& entry : table()) slugs.push_back(entry.first);
  return slugs;
}

derivation build_derivation(const std::string& slug) {
  for (const auto& [name, make] : table()) {
    if (name != slug) continue;
    try {
      return make();
    } catch (const std::exception& e) {
      derivation d;
      d.slug = slug;
      d.title = slug;
      d.build_error = e.what();
      return d;
    }
  }
  throw std::out_of_range("no derivation named '" + slug + "'");
}

std::vector<derivation> all_derivations() {
  std::vector<derivation> all;
  for (const auto& slug : derivation_slugs()) all.push_back(build_derivation(slug));
  return all;
}

}  // namespace shadowproof::proofs
