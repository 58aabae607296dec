#pragma once
/// CGAL's Plane_3, Point_3 and Vector_3 of an exact kernel K (Epeck, Simple_cartesian<Gmpq>,
/// Cartesian<mpq_class>, ...) to and from shadowproof's planes, lights and homogeneous vectors,
/// exactly. Header-only; link shadowproof::cgal.
///
/// The conventions agree: CGAL's Plane_3(a, b, c, d) is the set a x + b y + c z + d = 0 with the
/// positive side where a x + b y + c z + d > 0, as shadowproof's plane (a, b, c, d). A point is
/// the homogeneous (x, y, z, 1); a vector is the point at infinity (x, y, z, 0). A point light
/// is a Point_3; a directional light is the Vector_3 pointing *towards* the light.
#include <optional>

#include "shadowproof/cgal/number.h"
#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/plane.h"

namespace shadowproof::cgal {

// ===========================================================================================
// CGAL -> shadowproof

/// The plane (a, b, c, d) of P. CGAL's precondition (a, b, c) ≠ 0 makes it a valid plane.
template <class K>
plane<rational> to_plane(const typename K::Plane_3& P) {
  return make_plane(to_rational(P.a()), to_rational(P.b()), to_rational(P.c()), to_rational(P.d()));
}

/// The homogeneous point (x, y, z, 1).
template <class K>
vec4<rational> to_vec4(const typename K::Point_3& p) {
  return make_point(to_rational(p.x()), to_rational(p.y()), to_rational(p.z()));
}

/// The point at infinity in the direction v: (x, y, z, 0).
template <class K>
vec4<rational> to_vec4(const typename K::Vector_3& v) {
  return make_vec4(to_rational(v.x()), to_rational(v.y()), to_rational(v.z()), rational(0));
}

/// The point light at p: L = (x, y, z, 1).
template <class K>
light<rational> to_light(const typename K::Point_3& p) {
  return light<rational>{to_vec4<K>(p)};
}

/// The directional light towards which v points: L = (x, y, z, 0). Throws error
/// "geometry.zero_light" for the zero vector, which is no direction.
template <class K>
light<rational> to_light(const typename K::Vector_3& towards_light) {
  const vec4<rational> l = to_vec4<K>(towards_light);
  return make_light(l[0], l[1], l[2], l[3]);
}

// ===========================================================================================
// shadowproof -> CGAL

/// The Plane_3 a x + b y + c z + d = 0.
template <class K>
typename K::Plane_3 to_plane_3(const plane<rational>& P) {
  using FT = typename K::FT;
  return typename K::Plane_3(from_rational<FT>(P.a()), from_rational<FT>(P.b()), from_rational<FT>(P.c()),
                             from_rational<FT>(P.d()));
}

/// The finite point (x/w, y/w, z/w) of the homogeneous v; nothing when w = 0 (a point at
/// infinity, or the zero vector, has no Point_3). Any w ≠ 0, negative included, names the
/// same point.
template <class K>
std::optional<typename K::Point_3> to_point_3(const vec4<rational>& v) {
  if (v[3] == 0) return std::nullopt;
  using FT = typename K::FT;
  return typename K::Point_3(from_rational<FT>(v[0] / v[3]), from_rational<FT>(v[1] / v[3]),
                             from_rational<FT>(v[2] / v[3]));
}

/// The direction (x, y, z) of the point at infinity v; nothing when v is finite (w ≠ 0) or the
/// zero vector.
template <class K>
std::optional<typename K::Vector_3> to_direction_3(const vec4<rational>& v) {
  if (v[3] != 0 || (v[0] == 0 && v[1] == 0 && v[2] == 0)) return std::nullopt;
  using FT = typename K::FT;
  return typename K::Vector_3(from_rational<FT>(v[0]), from_rational<FT>(v[1]), from_rational<FT>(v[2]));
}

}  // namespace shadowproof::cgal
