// The mirror matrix written the way engines write it: without normalising (divide by n·n),
// and after normalising the plane with a square root (the usual engine habit).
#include <cmath>

#include "impls.h"

namespace shadowproof::impls {
namespace {

// M = [I − 2 n nᵀ/(n·n), −2 d n/(n·n); 0 0 0 1]: one division, no square root.
template <class T, bool fma>
void unnormalised(const double* in, double* out) {
  const inputs_as<T, 4> x(in);
  const T* p = x.v;
  T nn;
  if constexpr (fma) nn = std::fma(p[2], p[2], std::fma(p[1], p[1], p[0] * p[0]));
  else nn = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
  T m[16] = {};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const T e = T(2) * p[i] * p[j] / nn;
      m[i * 4 + j] = (i == j ? T(1) : T(0)) - e;
    }
    m[i * 4 + 3] = T(-2) * p[3] * p[i] / nn;
  }
  m[15] = T(1);
  write_outputs(m, 16, out);
}

// Normalise (n, d) by |n| first, then M = [I − 2 n̂ n̂ᵀ, −2 d̂ n̂; 0 0 0 1].
template <class T>
void normalised(const double* in, double* out) {
  const inputs_as<T, 4> x(in);
  const T len = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  const T n[4] = {x[0] / len, x[1] / len, x[2] / len, x[3] / len};
  T m[16] = {};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m[i * 4 + j] = (i == j ? T(1) : T(0)) - T(2) * n[i] * n[j];
    m[i * 4 + 3] = T(-2) * n[3] * n[i];
  }
  m[15] = T(1);
  write_outputs(m, 16, out);
}

}  // namespace

void add_seed_reflection(std::vector<implementation>& out) {
  const conventions canonical{};
  out.push_back({"reflect-divide-f32", operation::reflection_matrix, scalar_type::f32, canonical,
                 "I − 2 n nᵀ/(n·n) in float, no square root", unnormalised<float, false>});
  out.push_back({"reflect-divide-f64", operation::reflection_matrix, scalar_type::f64, canonical,
                 "I − 2 n nᵀ/(n·n) in double, no square root", unnormalised<double, false>});
  out.push_back({"reflect-divide-fma-f32", operation::reflection_matrix, scalar_type::f32, canonical,
                 "I − 2 n nᵀ/(n·n) in float, n·n with std::fma", unnormalised<float, true>});
  conventions normalising;
  normalising.normalises_plane = true;
  out.push_back({"reflect-normalize-f32", operation::reflection_matrix, scalar_type::f32, normalising,
                 "normalise (n, d) with sqrt, then I − 2 n̂ n̂ᵀ, float", normalised<float>});
  out.push_back({"reflect-normalize-f64", operation::reflection_matrix, scalar_type::f64, normalising,
                 "normalise (n, d) with sqrt, then I − 2 n̂ n̂ᵀ, double", normalised<double>});
}

}  // namespace shadowproof::impls
