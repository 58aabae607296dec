// Normal matrices as shaders get them: (A⁻¹)ᵀ computed in float and double, the
// division-free cofactor matrix (correct up to scale), and the classic mistake of
// transforming normals by the model matrix itself (seed 004 explains why that is wrong).
#include <limits>

#include "impls.h"
#include "shadowproof/constructions/normal_matrix.h"

namespace shadowproof::impls {
namespace {

template <class T>
mat4<T> linear_block(const double* in) {
  mat4<T> A = identity4<T>();
  for (std::size_t i = 0; i < 9; ++i) A(i / 3, i % 3) = static_cast<T>(in[i]);
  return A;
}

template <class T>
void write3(const mat4<T>& G, double* out) {
  for (std::size_t i = 0; i < 9; ++i) out[i] = static_cast<double>(G(i / 3, i % 3));
}

template <class T>
void inverse_transpose(const double* in, double* out) {
  try {
    write3(normal_matrix3(linear_block<T>(in)), out);
  } catch (const error&) {  // float determinant exactly 0
    for (std::size_t i = 0; i < 9; ++i) out[i] = std::numeric_limits<double>::quiet_NaN();
  }
}

template <class T>
void cofactor(const double* in, double* out) {
  write3(normal_matrix_adjugate(linear_block<T>(in)), out);
}

template <class T>
void model_matrix(const double* in, double* out) {
  write3(linear_block<T>(in), out);
}

}  // namespace

void add_seed_normal_matrix(std::vector<implementation>& out) {
  const conventions exact{};
  out.push_back({"normal-inverse-transpose-f32", operation::normal_matrix, scalar_type::f32, exact,
                 "(A⁻¹)ᵀ = transpose(adj(A) / det A) in float", inverse_transpose<float>});
  out.push_back({"normal-inverse-transpose-f64", operation::normal_matrix, scalar_type::f64, exact,
                 "(A⁻¹)ᵀ = transpose(adj(A) / det A) in double", inverse_transpose<double>});
  conventions up_to_scale;
  up_to_scale.homogeneous = true;  // normals are renormalised after the transform anyway
  out.push_back({"normal-cofactor-f32", operation::normal_matrix, scalar_type::f32, up_to_scale,
                 "cofactor matrix adj(A)ᵀ = det(A) (A⁻¹)ᵀ in float, graded up to scale", cofactor<float>});
  out.push_back({"normal-model-matrix-f32", operation::normal_matrix, scalar_type::f32, up_to_scale,
                 "the model matrix A itself used on normals (a common mistake), graded up to scale",
                 model_matrix<float>});
}

}  // namespace shadowproof::impls
