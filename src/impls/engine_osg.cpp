// OpenSceneGraph 3.6 (Debian libopenscenegraph-dev, libosg): osg::Matrixf (float storage) and
// osg::Matrixd (double) makePerspective (fovy in degrees), makeFrustum, makeOrtho (OpenGL
// depth −1..1, right-handed), makeLookAt, and invert. The builders take double arguments and
// compute in double; Matrixf rounds the results to float when it stores them. OSG multiplies
// row vectors (v M) and stores rows, so its memory is the transpose of the column-vector
// matrix: conventions vectors = row. Its normal matrix is the inverse's transpose, so the
// wrapper transposes invert()'s 3x3 block (a data move).
#include <limits>

#include <osg/Matrixd>
#include <osg/Matrixf>
#include <osg/Version>

#include "impls.h"

namespace shadowproof::impls {
namespace {

template <class M>
void write_rows(const M& m, double* out) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[4 * r + c] = static_cast<double>(m(r, c));
}

template <class M>
void perspective(const double* in, double* out) {
  M m;
  m.makePerspective(in[0], in[1], in[2], in[3]);
  write_rows(m, out);
}

template <class M, int which>
void box(const double* in, double* out) {
  M m;
  if constexpr (which == 0) m.makeOrtho(in[0], in[1], in[2], in[3], in[4], in[5]);
  else m.makeFrustum(in[0], in[1], in[2], in[3], in[4], in[5]);
  write_rows(m, out);
}

template <class M>
void look_at(const double* in, double* out) {
  M m;
  m.makeLookAt(osg::Vec3d(in[0], in[1], in[2]), osg::Vec3d(in[3], in[4], in[5]), osg::Vec3d(in[6], in[7], in[8]));
  write_rows(m, out);
}

// The normal matrix G = (A⁻¹)ᵀ as an OSG user gets it: the map A is the OSG matrix X = Aᵀ
// (row vectors: v X = (A v)ᵀ); X.invert gives X⁻¹ = (A⁻¹)ᵀ = G, whose OSG form is its
// transpose Gᵀ, read back as G under the row-vector convention.
template <class M>
void inverse_transposed(const double* in, double* out) {
  using T = typename M::value_type;
  M a;  // identity
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a(r, c) = static_cast<T>(in[3 * c + r]);  // X = Aᵀ
  M inv;
  if (!inv.invert(a)) {  // OSG reports a singular matrix by returning false
    for (int i = 0; i < 9; ++i) out[i] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[3 * r + c] = static_cast<double>(inv(c, r));
}

}  // namespace

void add_osg(std::vector<implementation>& out) {
  const std::string osg = std::string("OpenSceneGraph ") + osgGetVersion() + " ";
  conventions rows;
  rows.vectors = vector_side::row;
  conventions degrees = rows;
  degrees.angle = angle_unit::degrees;
  out.push_back({"osg-matrixf-perspective-f32", operation::perspective_fov, scalar_type::f32, degrees,
                 osg + "Matrixf::makePerspective(fovy in degrees, ...), float storage", perspective<osg::Matrixf>});
  out.push_back({"osg-matrixd-perspective-f64", operation::perspective_fov, scalar_type::f64, degrees,
                 osg + "Matrixd::makePerspective(fovy in degrees, ...), double", perspective<osg::Matrixd>});
  out.push_back({"osg-matrixf-ortho-f32", operation::ortho, scalar_type::f32, rows, osg + "Matrixf::makeOrtho",
                 box<osg::Matrixf, 0>});
  out.push_back({"osg-matrixd-ortho-f64", operation::ortho, scalar_type::f64, rows, osg + "Matrixd::makeOrtho",
                 box<osg::Matrixd, 0>});
  out.push_back({"osg-matrixf-frustum-f32", operation::frustum, scalar_type::f32, rows, osg + "Matrixf::makeFrustum",
                 box<osg::Matrixf, 1>});
  out.push_back({"osg-matrixd-frustum-f64", operation::frustum, scalar_type::f64, rows, osg + "Matrixd::makeFrustum",
                 box<osg::Matrixd, 1>});
  out.push_back({"osg-matrixf-lookat-f32", operation::look_at, scalar_type::f32, rows, osg + "Matrixf::makeLookAt",
                 look_at<osg::Matrixf>});
  out.push_back({"osg-matrixd-lookat-f64", operation::look_at, scalar_type::f64, rows, osg + "Matrixd::makeLookAt",
                 look_at<osg::Matrixd>});
  out.push_back({"osg-matrixf-inverse-f32", operation::normal_matrix, scalar_type::f32, rows,
                 osg + "Matrixf::invert, transposed (the normal matrix), float", inverse_transposed<osg::Matrixf>});
  out.push_back({"osg-matrixd-inverse-f64", operation::normal_matrix, scalar_type::f64, rows,
                 osg + "Matrixd::invert, transposed (the normal matrix), double", inverse_transposed<osg::Matrixd>});
}

}  // namespace shadowproof::impls
