#pragma once
// Internal to shadowproof_impls: each file adds its implementations to the list.
#include <vector>

#include "shadowproof/verify/implementation.h"

namespace shadowproof::impls {

void add_seed_shadow_matrix(std::vector<implementation>& out);
void add_seed_shadow_point(std::vector<implementation>& out);
void add_seed_reflection(std::vector<implementation>& out);
void add_seed_projection(std::vector<implementation>& out);
void add_seed_normal_matrix(std::vector<implementation>& out);
void add_reference(std::vector<implementation>& out);
void add_glm(std::vector<implementation>& out);
void add_eigen(std::vector<implementation>& out);
void add_irrlicht(std::vector<implementation>& out);
void add_ogre(std::vector<implementation>& out);
void add_reference_camera(std::vector<implementation>& out);
void add_glm_camera(std::vector<implementation>& out);
void add_qt(std::vector<implementation>& out);
void add_osg(std::vector<implementation>& out);

/// Copies n inputs into T (exact: they are representable) and n outputs back (exact widening).
template <class T, std::size_t N>
struct inputs_as {
  T v[N];
  explicit inputs_as(const double* in) {
    for (std::size_t i = 0; i < N; ++i) v[i] = static_cast<T>(in[i]);
  }
  const T& operator[](std::size_t i) const { return v[i]; }
};

template <class T>
void write_outputs(const T* values, std::size_t n, double* out) {
  for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<double>(values[i]);
}

}  // namespace shadowproof::impls
