#pragma once
/// Shadows and mirror images of CGAL points, computed exactly by shadowproof and returned as
/// CGAL objects of the same exact kernel K. Header-only; link shadowproof::cgal.
#include <optional>

#include "shadowproof/cgal/convert.h"
#include "shadowproof/constructions/classify.h"
#include "shadowproof/constructions/reflect.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof::cgal {

/// The shadow of a point: its class (classify.h) and its image under M = (P·L) I − L Pᵀ.
template <class K>
struct shadow_3 {
  point_class cls = point_class::shadow;
  /// The finite image (M V)/w. For line_in_plane, where M V is the zero vector, the point
  /// itself (on the receiver, it is its own shadow). Nothing for at_infinity, light_parallel
  /// and at_light.
  std::optional<typename K::Point_3> point;
  /// at_infinity and light_parallel: the (x, y, z) of the homogeneous image M V, a point at
  /// infinity. Nothing otherwise.
  std::optional<typename K::Vector_3> at_infinity;
};

/// The shadow of p from the light L on the receiver P (exact, whatever the configuration:
/// degenerate ones are classes, never errors).
template <class K>
shadow_3<K> shadow_of(const typename K::Plane_3& P, const light<rational>& L, const typename K::Point_3& p) {
  const plane<rational> receiver = to_plane<K>(P);
  const vec4<rational> V = to_vec4<K>(p);
  shadow_3<K> s;
  s.cls = classify_point(receiver, L, V);
  if (s.cls == point_class::line_in_plane) {
    s.point = p;
    return s;
  }
  const vec4<rational> image = shadow_image(receiver, L, V);
  s.point = to_point_3<K>(image);
  s.at_infinity = to_direction_3<K>(image);
  return s;
}

/// The shadow of p from the point light at `light` on P.
template <class K>
shadow_3<K> shadow_of(const typename K::Plane_3& P, const typename K::Point_3& light_position,
                      const typename K::Point_3& p) {
  return shadow_of<K>(P, to_light<K>(light_position), p);
}

/// The shadow of p from the directional light towards which `towards_light` points, on P.
/// Throws error "geometry.zero_light" for the zero vector.
template <class K>
shadow_3<K> shadow_of(const typename K::Plane_3& P, const typename K::Vector_3& towards_light,
                      const typename K::Point_3& p) {
  return shadow_of<K>(P, to_light<K>(towards_light), p);
}

/// The mirror image of p in the plane P: M V with M = reflection_matrix(P) (reflect.h), a
/// finite point always (M's last row is (0, 0, 0, 1)).
template <class K>
typename K::Point_3 reflection_of(const typename K::Plane_3& P, const typename K::Point_3& p) {
  return *to_point_3<K>(reflection_matrix(to_plane<K>(P)) * to_vec4<K>(p));
}

/// The mirror image of the direction v in P (the linear part of M: v − 2 (n·v) n / (n·n)).
template <class K>
typename K::Vector_3 reflection_of(const typename K::Plane_3& P, const typename K::Vector_3& v) {
  const vec4<rational> image = reflection_matrix(to_plane<K>(P)) * to_vec4<K>(v);
  using FT = typename K::FT;
  return typename K::Vector_3(from_rational<FT>(image[0]), from_rational<FT>(image[1]), from_rational<FT>(image[2]));
}

/// The reflection about P as CGAL's affine transformation: the rows of M above (0, 0, 0, 1),
/// exactly. t.transform(p) equals reflection_of(P, p).
template <class K>
typename K::Aff_transformation_3 reflection_transformation_3(const typename K::Plane_3& P) {
  const mat4<rational> M = reflection_matrix(to_plane<K>(P));
  using FT = typename K::FT;
  auto e = [&M](std::size_t r, std::size_t c) { return from_rational<FT>(M(r, c)); };
  return typename K::Aff_transformation_3(e(0, 0), e(0, 1), e(0, 2), e(0, 3), e(1, 0), e(1, 1), e(1, 2), e(1, 3),
                                          e(2, 0), e(2, 1), e(2, 2), e(2, 3));
}

}  // namespace shadowproof::cgal
