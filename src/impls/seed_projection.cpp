// Projection matrices as engines build them in float: the library's own closed forms
// instantiated in float and double, seed 002's orthographic normalisation as the product
// S · T of its two factors (two roundings per entry instead of one), and the perspective's
// reciprocal form (one division shared by the depth row).
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

// perspective(c, aspect, n, f, gl) of project.h: c/aspect, c, A = −(f+n)/(f−n) and
// B = −2fn/(f−n), each with its own roundings.
template <class T>
void perspective_closed_form(const double* in, double* out) {
  const inputs_as<T, 4> x(in);
  mat4<T> M;
  try {
    M = perspective<T>(x[0], x[1], x[2], x[3], depth_convention::gl);
  } catch (const error&) {
    for (std::size_t i = 0; i < 16; ++i) out[i] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  for (std::size_t i = 0; i < 16; ++i) out[i] = static_cast<double>(M(i / 4, i % 4));
}

// The reciprocal form many libraries use (gl-matrix's perspective, for one): r = 1/(n − f)
// once, then A = (f + n) r and B = 2 f n r, trading a division for a rounding more.
template <class T>
void perspective_reciprocal(const double* in, double* out) {
  const inputs_as<T, 4> x(in);
  const T c = x[0], aspect = x[1], n = x[2], f = x[3];
  const T r = T(1) / (n - f);
  T M[16] = {};
  M[0] = c / aspect;
  M[5] = c;
  M[10] = (f + n) * r;
  M[11] = T(2) * f * n * r;
  M[14] = T(-1);
  write_outputs(M, 16, out);
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
  out.push_back({"perspective-closed-form-f32", operation::perspective, scalar_type::f32, gl,
                 "perspective(cot(fovy/2), aspect, n, f, gl) of project.h instantiated in float",
                 perspective_closed_form<float>});
  out.push_back({"perspective-closed-form-f64", operation::perspective, scalar_type::f64, gl,
                 "perspective(cot(fovy/2), aspect, n, f, gl) of project.h instantiated in double",
                 perspective_closed_form<double>});
  out.push_back({"perspective-reciprocal-f32", operation::perspective, scalar_type::f32, gl,
                 "the reciprocal form r = 1/(n − f), A = (f + n) r, B = 2 f n r (as gl-matrix writes it), in float",
                 perspective_reciprocal<float>});
}

}  // namespace shadowproof::impls
