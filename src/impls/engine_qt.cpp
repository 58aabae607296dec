// Qt 5 (Debian qtbase5-dev, libQt5Gui) QMatrix4x4, all in float: perspective (vertical angle
// in degrees), frustum, ortho (OpenGL depth −1..1, right-handed), lookAt, and normalMatrix()
// (the 3x3 normal matrix of the upper-left block). Each builder multiplies the matrix it is
// called on, so the wrapper calls it on the identity, as Qt's own examples do; entries are
// read with operator()(row, column), so the outputs are row-major, column vectors.
#include <QtGui/QGenericMatrix>
#include <QtGui/QMatrix4x4>
#include <QtGui/QVector3D>

#include "impls.h"

namespace shadowproof::impls {
namespace {

void write_matrix(const QMatrix4x4& m, double* out) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[4 * r + c] = static_cast<double>(m(r, c));
}

void perspective(const double* in, double* out) {
  const inputs_as<float, 4> x(in);
  QMatrix4x4 m;
  m.perspective(x[0], x[1], x[2], x[3]);
  write_matrix(m, out);
}

template <int which>
void box(const double* in, double* out) {
  const inputs_as<float, 6> x(in);
  QMatrix4x4 m;
  if constexpr (which == 0) m.ortho(x[0], x[1], x[2], x[3], x[4], x[5]);
  else m.frustum(x[0], x[1], x[2], x[3], x[4], x[5]);
  write_matrix(m, out);
}

void look_at(const double* in, double* out) {
  const inputs_as<float, 9> x(in);
  QMatrix4x4 m;
  m.lookAt(QVector3D(x[0], x[1], x[2]), QVector3D(x[3], x[4], x[5]), QVector3D(x[6], x[7], x[8]));
  write_matrix(m, out);
}

void normal_matrix(const double* in, double* out) {
  const inputs_as<float, 9> x(in);
  QMatrix4x4 m;  // the identity, with the 3x3 block set: an affine map without translation
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = x[static_cast<std::size_t>(3 * r + c)];
  const QMatrix3x3 g = m.normalMatrix();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[3 * r + c] = static_cast<double>(g(r, c));
}

}  // namespace

void add_qt(std::vector<implementation>& out) {
  const std::string qt = std::string("Qt ") + QT_VERSION_STR + " QMatrix4x4::";
  conventions c;  // row-major reads, column vectors, right-handed, gl depth
  // Qt documents the identity where there is no answer: normalMatrix() of a matrix that is not
  // invertible, and ortho, frustum, perspective and lookAt leave the matrix unchanged for a flat
  // volume or eye = center.
  c.sentinel = sentinel_kind::identity;
  conventions degrees = c;
  degrees.angle = angle_unit::degrees;
  out.push_back({"qt-perspective-f32", operation::perspective_fov, scalar_type::f32, degrees,
                 qt + "perspective(verticalAngle in degrees, aspect, near, far), float", perspective});
  out.push_back({"qt-ortho-f32", operation::ortho, scalar_type::f32, c, qt + "ortho, float", box<0>});
  out.push_back({"qt-frustum-f32", operation::frustum, scalar_type::f32, c, qt + "frustum, float", box<1>});
  out.push_back({"qt-lookat-f32", operation::look_at, scalar_type::f32, c, qt + "lookAt, float", look_at});
  out.push_back({"qt-normal-matrix-f32", operation::normal_matrix, scalar_type::f32, c,
                 qt + "normalMatrix() of [A 0; 0 1], float", normal_matrix});
}

}  // namespace shadowproof::impls
