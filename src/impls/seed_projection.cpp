// Projection matrices as engines build them in float: the library's own closed forms
// instantiated in float and double, and seed 002's orthographic normalisation as the product
// S · T of its two factors (two roundings per entry instead of one).
#include <limits>

#include "impls.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof::impls {
namespace {

template <class T, bool is_ortho>
void closed_form(const double* in, double* out) {
  const inputs_as<T, 6> x(in);
  mat4<T> M;
  try {
    M = is_ortho ? orthographic<T>(x[0], x[1], x[2], x[3], x[4], x[5], depth_convention::gl)
                 : frustum<T>(x[0], x[1], x[2], x[3], x[4], x[5], depth_convention::gl, false);
  } catch (const error&) {  // a flat volume: report "no matrix" as NaN, as a shader would see
    for (std::size_t i = 0; i < 16; ++i) out[i] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  for (std::size_t i = 0; i < 16; ++i) out[i] = static_cast<double>(M(i / 4, i % 4));
}

template <class T>
void seed002_product(const double* in, double* out) {
  const inputs_as<T, 6> x(in);
  mat4<T> M;
  try {
    M = orthographic_normalization_seed002<T>(x[0], x[1], x[2], x[3], x[4], x[5]);
  } catch (const error&) {
    for (std::size_t i = 0; i < 16; ++i) out[i] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  for (std::size_t i = 0; i < 16; ++i) out[i] = static_cast<double>(M(i / 4, i % 4));
}

}  // namespace

void add_seed_projection(std::vector<implementation>& out) {
  const conventions gl{};
  out.push_back({"ortho-closed-form-f32", operation::ortho, scalar_type::f32, gl,
                 "orthographic(l, r, b, t, n, f, gl) of project.h instantiated in float", closed_form<float, true>});
  out.push_back({"ortho-seed002-product-f32", operation::ortho, scalar_type::f32, gl,
                 "seed 002's S(2/(r−l), 2/(t−b), −2/(f−n)) · T(−(r+l)/2, −(t+b)/2, (f+n)/2) multiplied in float",
                 seed002_product<float>});
  out.push_back({"frustum-closed-form-f32", operation::frustum, scalar_type::f32, gl,
                 "frustum(l, r, b, t, n, f, gl) of project.h instantiated in float", closed_form<float, false>});
  out.push_back({"frustum-closed-form-f64", operation::frustum, scalar_type::f64, gl,
                 "frustum(l, r, b, t, n, f, gl) of project.h instantiated in double", closed_form<double, false>});
}

}  // namespace shadowproof::impls
