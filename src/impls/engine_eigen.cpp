// Eigen (Debian libeigen3-dev): the shadow of a point as the intersection of the light ray
// through it with the receiver, Eigen::ParametrizedLine::intersectionPoint(Eigen::Hyperplane).
// Hyperplane(n, d) is n·x + d = 0, the library's own plane convention.
#include <Eigen/Geometry>

#include "impls.h"

namespace shadowproof::impls {
namespace {

template <class T>
void intersection(const double* in, double* out) {
  using vec3 = Eigen::Matrix<T, 3, 1>;
  const inputs_as<T, 11> x(in);
  const Eigen::Hyperplane<T, 3> receiver(vec3(x[0], x[1], x[2]), x[3]);
  const vec3 point(x[8], x[9], x[10]);
  // Directional light: the ray leaves the point along the light's direction; point light:
  // along the line from the light through the point.
  const vec3 direction = x[7] == T(0) ? vec3(x[4], x[5], x[6])
                                      : vec3(point - vec3(x[4], x[5], x[6]) / x[7]);
  const vec3 image = Eigen::ParametrizedLine<T, 3>(point, direction).intersectionPoint(receiver);
  write_outputs(image.data(), 3, out);
}

}  // namespace

void add_eigen(std::vector<implementation>& out) {
  const conventions c{};
  const std::string version = std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
                              "." + std::to_string(EIGEN_MINOR_VERSION);
  out.push_back({"eigen-intersection-f32", operation::shadow_point, scalar_type::f32, c,
                 "Eigen " + version + " ParametrizedLine::intersectionPoint(Hyperplane), float", intersection<float>});
  out.push_back({"eigen-intersection-f64", operation::shadow_point, scalar_type::f64, c,
                 "Eigen " + version + " ParametrizedLine::intersectionPoint(Hyperplane), double", intersection<double>});
}

}  // namespace shadowproof::impls
