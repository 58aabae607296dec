// Shadows of single points, written as shaders write them.
#include <algorithm>
#include <cmath>

#include "impls.h"

namespace shadowproof::impls {
namespace {

template <class T>
T dot3(const T* a, const T* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

template <class T>
void normalize3(T* v) {
  const T len = std::sqrt(dot3(v, v));
  for (int i = 0; i < 3; ++i) v[i] = v[i] / len;
}

// The homogeneous image (P·L) V − (P·V) L, then divided by its w: the library's own formula
// evaluated in T. Robust except where the image's w cancels (point level with the light).
template <class T>
void homogeneous_image(const double* in, double* out) {
  const inputs_as<T, 11> x(in);
  const T* p = x.v;
  const T* l = x.v + 4;
  const T v[4] = {x[8], x[9], x[10], T(1)};
  const T s = p[0] * l[0] + p[1] * l[1] + p[2] * l[2] + p[3] * l[3];
  const T t = p[0] * v[0] + p[1] * v[1] + p[2] * v[2] + p[3];
  T h[4];
  for (int i = 0; i < 4; ++i) h[i] = s * v[i] - t * l[i];
  const T r[3] = {h[0] / h[3], h[1] / h[3], h[2] / h[3]};
  write_outputs(r, 3, out);
}

// Seed 001, method 1 (a vertex shader): lightDir = normalize(light), the receiver through p0
// with unit normal n; distance = dot(p0 − X, n) / dot(lightDir, n); image = X + distance·lightDir.
// Generalised from y = 0 to any plane by p0 = −d n / |n|², n normalised. Directional lights.
template <class T>
void shader_intersection(const double* in, double* out) {
  const inputs_as<T, 11> x(in);
  T n[3] = {x[0], x[1], x[2]};
  const T nn = dot3(n, n);
  const T p0[3] = {-x[3] * n[0] / nn, -x[3] * n[1] / nn, -x[3] * n[2] / nn};
  normalize3(n);
  T dir[3] = {x[4], x[5], x[6]};
  normalize3(dir);
  const T world[3] = {x[8], x[9], x[10]};
  const T diff[3] = {p0[0] - world[0], p0[1] - world[1], p0[2] - world[2]};
  const T distance = dot3(diff, n) / dot3(dir, n);
  const T r[3] = {world[0] + distance * dir[0], world[1] + distance * dir[1], world[2] + distance * dir[2]};
  write_outputs(r, 3, out);
}

// Seed 001, method 2 (similar triangles with clamping), generalised from the ground y = h to
// any plane: height = signed distance of X above the receiver, clamped at 0, and
// image = X − lightDir · height / dot(lightDir, n̂). Points below the receiver stay in place:
// a deliberate convention (declared), not an error.
template <class T>
void shader_clamped(const double* in, double* out) {
  const inputs_as<T, 11> x(in);
  T n[3] = {x[0], x[1], x[2]};
  const T len = std::sqrt(dot3(n, n));
  for (int i = 0; i < 3; ++i) n[i] = n[i] / len;
  const T d = x[3] / len;
  T dir[3] = {x[4], x[5], x[6]};
  normalize3(dir);
  const T world[3] = {x[8], x[9], x[10]};
  const T height = std::max(T(0), dot3(world, n) + d);
  const T k = height / dot3(dir, n);
  const T r[3] = {world[0] - dir[0] * k, world[1] - dir[1] * k, world[2] - dir[2] * k};
  write_outputs(r, 3, out);
}

// Seed 003's ray formula for a point light L: Q = L − (V − L)(⟨N, L⟩ + d) / ⟨N, V − L⟩.
template <class T>
void ray_from_point_light(const double* in, double* out) {
  const inputs_as<T, 11> x(in);
  const T n[3] = {x[0], x[1], x[2]};
  const T L[3] = {x[4] / x[7], x[5] / x[7], x[6] / x[7]};
  const T dir[3] = {x[8] - L[0], x[9] - L[1], x[10] - L[2]};
  const T k = (dot3(n, L) + x[3]) / dot3(n, dir);
  const T r[3] = {L[0] - dir[0] * k, L[1] - dir[1] * k, L[2] - dir[2] * k};
  write_outputs(r, 3, out);
}

}  // namespace

void add_seed_shadow_point(std::vector<implementation>& out) {
  const conventions canonical{};
  out.push_back({"homogeneous-image-f32", operation::shadow_point, scalar_type::f32, canonical,
                 "(P·L) V − (P·V) L in float, then divided by w", homogeneous_image<float>});
  out.push_back({"homogeneous-image-f64", operation::shadow_point, scalar_type::f64, canonical,
                 "(P·L) V − (P·V) L in double, then divided by w", homogeneous_image<double>});
  conventions directional;
  directional.directional_only = true;
  out.push_back({"seed001-shader-f32", operation::shadow_point, scalar_type::f32, directional,
                 "seed 001 method 1 shader: normalize(), ray/plane distance, float", shader_intersection<float>});
  conventions clamped = directional;
  clamped.clamps_behind_receiver = true;
  out.push_back({"seed001-clamped-f32", operation::shadow_point, scalar_type::f32, clamped,
                 "seed 001 method 2 shader: similar triangles with max(0, height), float", shader_clamped<float>});
  conventions point;
  point.point_light_only = true;
  out.push_back({"seed003-ray-f32", operation::shadow_point, scalar_type::f32, point,
                 "seed 003: Q = L − (V − L)(⟨N,L⟩ + d)/⟨N,V − L⟩, float", ray_from_point_light<float>});
  out.push_back({"seed003-ray-f64", operation::shadow_point, scalar_type::f64, point,
                 "seed 003: Q = L − (V − L)(⟨N,L⟩ + d)/⟨N,V − L⟩, double", ray_from_point_light<double>});
}

}  // namespace shadowproof::impls
