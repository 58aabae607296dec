// Textbook float camera code, written as tutorials write it: perspective with
// c = 1/tan(fovy/2) (project.h's perspective() over float or double, so every other entry is
// one rounding from exact), and look-at / target-to by normalising (look_at.h's
// look_at_float). std::tan and std::sqrt are the C library's (sqrt correctly rounded, tan
// within an ulp or so), so the error is a few ulps away from degeneracies.
#include <cmath>

#include "impls.h"
#include "shadowproof/constructions/handedness.h"
#include "shadowproof/constructions/look_at.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof::impls {
namespace {

template <class T, bool infinite>
void perspective_fov(const double* in, double* out) {
  const inputs_as<T, infinite ? 3 : 4> x(in);
  const T c = T(1) / std::tan(x[0] / T(2));
  // The float routine under test must not throw: with n = f it divides by zero as C does.
  mat4<T> m;
  const depth_range<T> z = ndc_depth_range<T>(depth_convention::gl);
  m(0, 0) = c / x[1];
  m(1, 1) = c;
  if constexpr (infinite) {
    m(2, 2) = -z.far_ndc;
    m(2, 3) = x[2] * (z.near_ndc - z.far_ndc);
  } else {
    const T n = x[2], f = x[infinite ? 2 : 3];
    m(2, 2) = (n * z.near_ndc - f * z.far_ndc) / (f - n);
    m(2, 3) = n * f * (z.near_ndc - z.far_ndc) / (f - n);
  }
  m(3, 2) = T(-1);
  for (std::size_t i = 0; i < 16; ++i) out[i] = static_cast<double>(m(i / 4, i % 4));
}

template <class T, bool placement>
void camera(const double* in, double* out) {
  const inputs_as<T, 9> x(in);
  const vec3<T> eye{x[0], x[1], x[2]}, target{x[3], x[4], x[5]}, up{x[6], x[7], x[8]};
  const mat4<T> v = look_at_float(eye, target, up, handedness::right);
  if (!placement) {
    for (std::size_t i = 0; i < 16; ++i) out[i] = static_cast<double>(v(i / 4, i % 4));
    return;
  }
  // The placement: the rotation's transpose and the eye itself.
  for (std::size_t r = 0; r < 4; ++r)
    for (std::size_t c = 0; c < 4; ++c) out[4 * r + c] = r < 3 && c < 3 ? static_cast<double>(v(c, r)) : 0.0;
  for (std::size_t r = 0; r < 3; ++r) out[4 * r + 3] = static_cast<double>(eye[r]);
  out[15] = 1;
}

// The width and height builders (D3DXMatrixOrthoRH / D3DXMatrixPerspectiveRH with OpenGL's
// depth range): 2/w, 2/h (orthographic) or 2n/w, 2n/h (perspective), and the depth row.
template <class T, bool perspective>
void view_size(const double* in, double* out) {
  const inputs_as<T, 4> x(in);
  const T w = x[0], h = x[1], n = x[2], f = x[3];
  mat4<T> m;
  m(0, 0) = (perspective ? T(2) * n : T(2)) / w;
  m(1, 1) = (perspective ? T(2) * n : T(2)) / h;
  if (perspective) {
    m(2, 2) = -(f + n) / (f - n);
    m(2, 3) = -(T(2) * f * n) / (f - n);
    m(3, 2) = T(-1);
  } else {
    m(2, 2) = T(-2) / (f - n);
    m(2, 3) = -(f + n) / (f - n);
    m(3, 3) = T(1);
  }
  for (std::size_t i = 0; i < 16; ++i) out[i] = static_cast<double>(m(i / 4, i % 4));
}

}  // namespace

void add_reference_camera(std::vector<implementation>& out) {
  const conventions c;
  out.push_back({"textbook-perspective-fov-f32", operation::perspective_fov, scalar_type::f32, c,
                 "textbook gluPerspective: c = 1/tanf(fovy/2), float", perspective_fov<float, false>});
  out.push_back({"textbook-perspective-fov-f64", operation::perspective_fov, scalar_type::f64, c,
                 "textbook gluPerspective: c = 1/tan(fovy/2), double", perspective_fov<double, false>});
  out.push_back({"textbook-perspective-fov-infinite-f32", operation::perspective_fov_infinite, scalar_type::f32, c,
                 "textbook infinite perspective: c = 1/tanf(fovy/2), float", perspective_fov<float, true>});
  out.push_back({"textbook-look-at-f32", operation::look_at, scalar_type::f32, c,
                 "textbook lookAt: normalize(eye − target), normalize(up × z), z × x, float", camera<float, false>});
  out.push_back({"textbook-look-at-f64", operation::look_at, scalar_type::f64, c,
                 "textbook lookAt: normalize(eye − target), normalize(up × z), z × x, double", camera<double, false>});
  out.push_back({"textbook-ortho-size-f32", operation::ortho_size, scalar_type::f32, c,
                 "textbook orthographic from width and height: 2/w, 2/h, −2/(f−n), −(f+n)/(f−n), float",
                 view_size<float, false>});
  out.push_back({"textbook-perspective-size-f32", operation::perspective_size, scalar_type::f32, c,
                 "textbook perspective from width and height at the near plane: 2n/w, 2n/h, float",
                 view_size<float, true>});
  out.push_back({"textbook-target-to-f32", operation::target_to, scalar_type::f32, c,
                 "textbook camera placement: the lookAt rotation transposed, the eye, float", camera<float, true>});
}

}  // namespace shadowproof::impls
