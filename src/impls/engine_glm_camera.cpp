// GLM's camera builders (Debian libglm-dev, ext/matrix_clip_space and ext/matrix_transform):
// glm::perspective (fovy in radians; right-handed, depth −1..1), glm::perspectiveLH_ZO,
// glm::perspectiveRH_ZO, glm::infinitePerspective, glm::lookAt (right-handed) and
// glm::lookAtLH. Column-major storage, column vectors.
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "impls.h"

namespace shadowproof::impls {
namespace {

enum class builder { rh_no, lh_zo, rh_zo, infinite };

template <class T, builder b>
void perspective(const double* in, double* out) {
  // fovy, aspect, near, far; the infinite builder takes no far plane (three inputs).
  const inputs_as<T, b == builder::infinite ? 3 : 4> x(in);
  glm::mat<4, 4, T, glm::defaultp> m;
  if constexpr (b == builder::rh_no) m = glm::perspective(x[0], x[1], x[2], x[3]);
  else if constexpr (b == builder::lh_zo) m = glm::perspectiveLH_ZO(x[0], x[1], x[2], x[3]);
  else if constexpr (b == builder::rh_zo) m = glm::perspectiveRH_ZO(x[0], x[1], x[2], x[3]);
  else m = glm::infinitePerspective(x[0], x[1], x[2]);
  write_outputs(glm::value_ptr(m), 16, out);
}

template <class T, bool left>
void look_at(const double* in, double* out) {
  using vec3 = glm::vec<3, T, glm::defaultp>;
  const inputs_as<T, 9> x(in);
  const vec3 eye(x[0], x[1], x[2]), center(x[3], x[4], x[5]), up(x[6], x[7], x[8]);
  const auto m = left ? glm::lookAtLH(eye, center, up) : glm::lookAtRH(eye, center, up);
  write_outputs(glm::value_ptr(m), 16, out);
}

}  // namespace

void add_glm_camera(std::vector<implementation>& out) {
  const std::string glm = "GLM " + std::to_string(GLM_VERSION_MAJOR) + "." + std::to_string(GLM_VERSION_MINOR) + "." +
                          std::to_string(GLM_VERSION_PATCH) + "." + std::to_string(GLM_VERSION_REVISION) + " ";
  conventions c;
  c.storage = storage_order::column_major;
  conventions lh_zo = c;
  lh_zo.hand = handedness::left;
  lh_zo.depth = depth_convention::d3d;
  conventions rh_zo = c;
  rh_zo.depth = depth_convention::d3d;
  out.push_back({"glm-perspective-f32", operation::perspective_fov, scalar_type::f32, c,
                 glm + "glm::perspective (right-handed, depth −1..1), float", perspective<float, builder::rh_no>});
  out.push_back({"glm-perspective-f64", operation::perspective_fov, scalar_type::f64, c,
                 glm + "glm::perspective (right-handed, depth −1..1), double", perspective<double, builder::rh_no>});
  out.push_back({"glm-perspective-lh-zo-f32", operation::perspective_fov, scalar_type::f32, lh_zo,
                 glm + "glm::perspectiveLH_ZO, float", perspective<float, builder::lh_zo>});
  out.push_back({"glm-perspective-rh-zo-f32", operation::perspective_fov, scalar_type::f32, rh_zo,
                 glm + "glm::perspectiveRH_ZO, float", perspective<float, builder::rh_zo>});
  out.push_back({"glm-infinite-perspective-f32", operation::perspective_fov_infinite, scalar_type::f32, c,
                 glm + "glm::infinitePerspective (right-handed, depth −1..1), float",
                 perspective<float, builder::infinite>});
  out.push_back({"glm-lookat-f32", operation::look_at, scalar_type::f32, c, glm + "glm::lookAtRH, float",
                 look_at<float, false>});
  out.push_back({"glm-lookat-f64", operation::look_at, scalar_type::f64, c, glm + "glm::lookAtRH, double",
                 look_at<double, false>});
  conventions lh = c;
  lh.hand = handedness::left;
  out.push_back({"glm-lookat-lh-f32", operation::look_at, scalar_type::f32, lh, glm + "glm::lookAtLH, float",
                 look_at<float, true>});
}

}  // namespace shadowproof::impls
