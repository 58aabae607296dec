// Irrlicht (Debian libirrlicht-dev) through its public header matrix4.h:
// core::matrix4::buildShadowMatrix(light, plane3df(normal, D), point) and the right-handed
// projection builders buildProjectionMatrixOrthoRH / PerspectiveRH(width, height, n, f),
// which build symmetric volumes with depth 0..1 (Direct3D convention). Irrlicht stores
// matrices row-major and multiplies row vectors (translation in M[12..14]), and normalises
// the plane's normal itself: declared, so the result is graded up to scale.
#include <irrlicht.h>

#include "impls.h"

namespace shadowproof::impls {
namespace {

void shadow(const double* in, double* out) {
  const inputs_as<float, 8> x(in);
  irr::core::matrix4 m;
  m.buildShadowMatrix(irr::core::vector3df(x[4], x[5], x[6]),
                      irr::core::plane3df(irr::core::vector3df(x[0], x[1], x[2]), x[3]), x[7]);
  write_outputs(m.pointer(), 16, out);
}

// Symmetric volumes only: width = r − l = 2r and height = 2t are exact.
template <bool is_ortho>
void projection(const double* in, double* out) {
  const inputs_as<float, 6> x(in);
  irr::core::matrix4 m;
  if constexpr (is_ortho) m.buildProjectionMatrixOrthoRH(x[1] - x[0], x[3] - x[2], x[4], x[5]);
  else m.buildProjectionMatrixPerspectiveRH(x[1] - x[0], x[3] - x[2], x[4], x[5]);
  write_outputs(m.pointer(), 16, out);
}

}  // namespace

void add_irrlicht(std::vector<implementation>& out) {
  conventions projection_conv;
  projection_conv.vectors = vector_side::row;
  projection_conv.depth = depth_convention::d3d;
  projection_conv.symmetric_view = true;
  out.push_back({"irrlicht-ortho-rh-f32", operation::ortho, scalar_type::f32, projection_conv,
                 "Irrlicht " IRRLICHT_SDK_VERSION " matrix4::buildProjectionMatrixOrthoRH, float", projection<true>});
  out.push_back({"irrlicht-perspective-rh-f32", operation::frustum, scalar_type::f32, projection_conv,
                 "Irrlicht " IRRLICHT_SDK_VERSION " matrix4::buildProjectionMatrixPerspectiveRH, float",
                 projection<false>});
  conventions c;
  c.storage = storage_order::row_major;
  c.vectors = vector_side::row;
  c.normalises_plane = true;
  const std::string origin = "Irrlicht " IRRLICHT_SDK_VERSION " matrix4::buildShadowMatrix, float";
  out.push_back({"irrlicht-shadow-f32", operation::shadow_matrix, scalar_type::f32, c, origin, shadow});
  // The same routine on the planes it is usually given: unit normals (the ground y = h).
  conventions ground = c;
  ground.unit_normal = true;
  out.push_back({"irrlicht-shadow-unit-normal-f32", operation::shadow_matrix, scalar_type::f32, ground,
                 origin + ", planes with unit normals only", shadow});
}

}  // namespace shadowproof::impls
