// The list of built-in implementations: an explicit list (not static registrars), so every
// file of this static library is linked wherever the list is used.
#include <algorithm>

#include "impls.h"
#include "shadowproof/core/error.h"

namespace shadowproof {

const std::vector<implementation>& builtin_implementations() {
  static const std::vector<implementation> all = [] {
    std::vector<implementation> v;
    impls::add_seed_shadow_matrix(v);
    impls::add_seed_shadow_point(v);
    impls::add_seed_reflection(v);
    impls::add_seed_projection(v);
    impls::add_seed_normal_matrix(v);
    impls::add_reference(v);
    impls::add_reference_camera(v);
#ifdef SHADOWPROOF_HAVE_GLM
    impls::add_glm(v);
    impls::add_glm_camera(v);
#endif
#ifdef SHADOWPROOF_HAVE_EIGEN
    impls::add_eigen(v);
#endif
#ifdef SHADOWPROOF_HAVE_IRRLICHT
    impls::add_irrlicht(v);
#endif
#ifdef SHADOWPROOF_HAVE_OGRE
    impls::add_ogre(v);
#endif
#ifdef SHADOWPROOF_HAVE_QT
    impls::add_qt(v);
#endif
#ifdef SHADOWPROOF_HAVE_OSG
    impls::add_osg(v);
#endif
    std::sort(v.begin(), v.end(), [](const implementation& a, const implementation& b) { return a.name < b.name; });
    return v;
  }();
  return all;
}

const implementation& find_builtin_implementation(std::string_view name) {
  for (const auto& i : builtin_implementations())
    if (i.name == name) return i;
  throw error(errc::verify_unknown_impl,
              "no implementation named '" + std::string(name) + "' (see 'shadowproof check --list')");
}

}  // namespace shadowproof
