// The shadow matrix M = (P·L) I − L Pᵀ written the way a shader or engine writes it: in float
// or double, left-to-right sums, with and without fused multiply-add. Robustness: the
// diagonal entries P·L − Lᵢ Pᵢ cancel when the light is nearly parallel to (or nearly on) the
// receiver, so relative error grows like 1 / |P·L| there; the closed form of seed 000 avoids
// that cancellation for directional lights by never adding the term it then subtracts.
#include <cmath>

#include "impls.h"

namespace shadowproof::impls {
namespace {

template <class T, bool fma>
void general(const double* in, double* out) {
  const inputs_as<T, 8> x(in);
  const T* p = x.v;
  const T* l = x.v + 4;
  T s;
  if constexpr (fma) s = std::fma(p[3], l[3], std::fma(p[2], l[2], std::fma(p[1], l[1], p[0] * l[0])));
  else s = p[0] * l[0] + p[1] * l[1] + p[2] * l[2] + p[3] * l[3];
  T m[16];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if (i != j) m[i * 4 + j] = -(l[i] * p[j]);
      else if constexpr (fma) m[i * 4 + j] = std::fma(-l[i], p[j], s);
      else m[i * 4 + j] = s - l[i] * p[j];
    }
  write_outputs(m, 16, out);
}

// Seed 000's closed form for a directional light (Lx, Ly, Lz, 0), entry by entry.
template <class T>
void closed_form(const double* in, double* out) {
  const inputs_as<T, 8> x(in);
  const T a = x[0], b = x[1], c = x[2], d = x[3];
  const T lx = x[4], ly = x[5], lz = x[6];
  const T m[16] = {b * ly + c * lz, -b * lx,         -c * lx,         -d * lx,
                   -a * ly,         a * lx + c * lz, -c * ly,         -d * ly,
                   -a * lz,         -b * lz,         a * lx + b * ly, -d * lz,
                   T(0),            T(0),            T(0),            a * lx + b * ly + c * lz};
  write_outputs(m, 16, out);
}

}  // namespace

void add_seed_shadow_matrix(std::vector<implementation>& out) {
  const conventions canonical{};
  out.push_back({"seed000-general-f32", operation::shadow_matrix, scalar_type::f32, canonical,
                 "(P·L) I − L Pᵀ in float, no FMA", general<float, false>});
  out.push_back({"seed000-general-f64", operation::shadow_matrix, scalar_type::f64, canonical,
                 "(P·L) I − L Pᵀ in double, no FMA", general<double, false>});
  out.push_back({"seed000-general-fma-f32", operation::shadow_matrix, scalar_type::f32, canonical,
                 "(P·L) I − L Pᵀ in float, dot product and diagonal with std::fma", general<float, true>});
  out.push_back({"seed000-general-fma-f64", operation::shadow_matrix, scalar_type::f64, canonical,
                 "(P·L) I − L Pᵀ in double, dot product and diagonal with std::fma", general<double, true>});
  conventions directional;
  directional.directional_only = true;
  out.push_back({"seed000-closed-form-f32", operation::shadow_matrix, scalar_type::f32, directional,
                 "seed 000's entry-by-entry matrix for a directional light, in float", closed_form<float>});
}

}  // namespace shadowproof::impls
