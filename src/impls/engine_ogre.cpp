// Ogre 1.12 (Debian libogre-1.12-dev, libOgreMain): Ogre::Math::buildReflectionMatrix(Plane),
// which expects a normalised plane, so the wrapper calls Plane::normalise() first as Ogre's
// own callers do. Plane(a, b, c, d) is a x + b y + c z + d = 0 (beware Plane(normal, c),
// which stores d = −c). Row-major storage, column vectors; the Affine3 has no last row.
#include <OGRE/OgreMath.h>
#include <OGRE/OgreMatrix4.h>
#include <OGRE/OgrePlane.h>
#include <OGRE/OgrePrerequisites.h>

#include "impls.h"

namespace shadowproof::impls {
namespace {

void reflect(const double* in, double* out) {
  const inputs_as<Ogre::Real, 4> x(in);
  Ogre::Plane p(x[0], x[1], x[2], x[3]);
  p.normalise();
  const Ogre::Affine3 m = Ogre::Math::buildReflectionMatrix(p);
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < 4; ++c) out[r * 4 + c] = static_cast<double>(m[r][c]);
  out[12] = out[13] = out[14] = 0;
  out[15] = 1;
}

}  // namespace

void add_ogre(std::vector<implementation>& out) {
  conventions c;
  c.normalises_plane = true;
  const std::string version = std::to_string(OGRE_VERSION_MAJOR) + "." + std::to_string(OGRE_VERSION_MINOR) +
                              "." + std::to_string(OGRE_VERSION_PATCH);
  out.push_back({"ogre-reflection-f32", operation::reflection_matrix, scalar_type::f32, c,
                 "Ogre " + version + " Math::buildReflectionMatrix(Plane::normalise()), float", reflect});
}

}  // namespace shadowproof::impls
