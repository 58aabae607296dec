#pragma once
/// A light L = (x, y, z, w) in homogeneous coordinates.
#include "shadowproof/core/error.h"
#include "shadowproof/core/homogeneous.h"

namespace shadowproof {

/// w ≠ 0: a point light at (x/w, y/w, z/w) (any non-zero w, including w < 0, names the same
/// point). w = 0: a directional light; (x, y, z) points *towards* the light, i.e. light travels
/// along −(x, y, z). (x, y, z, 0) and (−x, −y, −z, 0) give the same shadow matrix up to sign but
/// are opposite lights: they swap which points cast a real shadow.
template <class T>
struct light {
  vec4<T> l;

  bool is_directional() const { return l[3] == T(0); }
  bool is_point() const { return !is_directional(); }
};

/// Builds the light (x, y, z, w). Throws error "geometry.zero_light" for (0, 0, 0, 0), which is
/// no point and no direction.
template <class T>
light<T> make_light(const T& x, const T& y, const T& z, const T& w) {
  if (x == T(0) && y == T(0) && z == T(0) && w == T(0))
    throw zero_light_error();
  return light<T>{make_vec4<T>(x, y, z, w)};
}

template <class To, class From>
light<To> convert(const light<From>& L) {
  return light<To>{convert<To>(L.l)};
}

}  // namespace shadowproof
