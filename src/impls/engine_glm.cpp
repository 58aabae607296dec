// GLM (Debian libglm-dev) through its public headers: glm::reflect3D (gtx/transform2),
// glm::ortho, glm::frustum, glm::frustumRH_ZO (ext/matrix_clip_space) and
// glm::inverseTranspose (gtc/matrix_inverse). reflect3D mirrors about a plane through the
// origin with a unit normal, so the wrapper does what a GLM user does: normalise (n, d), move
// the mirror to the origin and back. GLM stores matrices column-major, column vectors.
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/glm.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/transform2.hpp>

#include "impls.h"

namespace shadowproof::impls {
namespace {

template <class T>
void reflect(const double* in, double* out) {
  using vec3 = glm::vec<3, T, glm::defaultp>;
  using mat4 = glm::mat<4, 4, T, glm::defaultp>;
  const inputs_as<T, 4> x(in);
  const vec3 n(x[0], x[1], x[2]);
  const T len = glm::length(n);
  const vec3 unit = n / len;
  const vec3 on_plane = unit * (-x[3] / len);  // the point of the mirror nearest the origin
  const mat4 m = glm::translate(mat4(T(1)), on_plane) * glm::reflect3D(mat4(T(1)), unit) *
                 glm::translate(mat4(T(1)), -on_plane);
  write_outputs(glm::value_ptr(m), 16, out);
}

template <class T, int which>
void projection(const double* in, double* out) {
  const inputs_as<T, 6> x(in);
  glm::mat<4, 4, T, glm::defaultp> m;
  if constexpr (which == 0) m = glm::ortho(x[0], x[1], x[2], x[3], x[4], x[5]);
  else if constexpr (which == 1) m = glm::frustum(x[0], x[1], x[2], x[3], x[4], x[5]);
  else m = glm::frustumRH_ZO(x[0], x[1], x[2], x[3], x[4], x[5]);
  write_outputs(glm::value_ptr(m), 16, out);
}

template <class T>
void inverse_transpose(const double* in, double* out) {
  const inputs_as<T, 9> x(in);
  glm::mat<3, 3, T, glm::defaultp> a;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[c][r] = x[static_cast<std::size_t>(3 * r + c)];  // a[column][row]
  const auto g = glm::inverseTranspose(a);
  write_outputs(glm::value_ptr(g), 9, out);
}

std::string version() {
  return "GLM " + std::to_string(GLM_VERSION_MAJOR) + "." + std::to_string(GLM_VERSION_MINOR) + "." +
         std::to_string(GLM_VERSION_PATCH) + "." + std::to_string(GLM_VERSION_REVISION);
}

}  // namespace

void add_glm(std::vector<implementation>& out) {
  const std::string glm_version = version();
  conventions column_major;
  column_major.storage = storage_order::column_major;
  out.push_back({"glm-ortho-f32", operation::ortho, scalar_type::f32, column_major,
                 glm_version + " glm::ortho (right-handed, depth −1..1), float", projection<float, 0>});
  out.push_back({"glm-frustum-f32", operation::frustum, scalar_type::f32, column_major,
                 glm_version + " glm::frustum (right-handed, depth −1..1), float", projection<float, 1>});
  out.push_back({"glm-frustum-f64", operation::frustum, scalar_type::f64, column_major,
                 glm_version + " glm::frustum (right-handed, depth −1..1), double", projection<double, 1>});
  conventions zero_to_one = column_major;
  zero_to_one.depth = depth_convention::d3d;
  out.push_back({"glm-frustum-zo-f32", operation::frustum, scalar_type::f32, zero_to_one,
                 glm_version + " glm::frustumRH_ZO (depth 0..1), float", projection<float, 2>});
  out.push_back({"glm-inverse-transpose-f32", operation::normal_matrix, scalar_type::f32, column_major,
                 glm_version + " glm::inverseTranspose(mat3), float", inverse_transpose<float>});
  out.push_back({"glm-inverse-transpose-f64", operation::normal_matrix, scalar_type::f64, column_major,
                 glm_version + " glm::inverseTranspose(mat3), double", inverse_transpose<double>});
  conventions c;
  c.storage = storage_order::column_major;
  c.normalises_plane = true;
  out.push_back({"glm-reflect3d-f32", operation::reflection_matrix, scalar_type::f32, c,
                 version() + " translate · reflect3D(normalize(n)) · translate, float",
                 reflect<float>});
  out.push_back({"glm-reflect3d-f64", operation::reflection_matrix, scalar_type::f64, c,
                 version() + " translate · reflect3D(normalize(n)) · translate, double",
                 reflect<double>});
}

}  // namespace shadowproof::impls
