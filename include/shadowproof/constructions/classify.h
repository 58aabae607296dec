#pragma once
/// Exact classification of a finite point V under a receiver plane P and a light L.
#include <string_view>

#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/plane.h"

namespace shadowproof {

/// What the shadow matrix M = (P·L) I − L Pᵀ does to a finite point V, with s = P·L, t = P·V.
enum class point_class {
  on_receiver,      ///< s ≠ 0, t = 0: V lies on the receiver; its image is V itself.
  shadow,           ///< V strictly between the light and the receiver: a real shadow.
  behind_receiver,  ///< V on the far side of the receiver: the matrix gives a false shadow.
  beyond_light,     ///< point light; V farther from the receiver than the light, same side: anti-shadow.
  at_infinity,      ///< point light; V as far from the receiver as the light (not the light): image w = 0.
  at_light,         ///< point light; V is the light: the image is the zero vector.
  light_on_plane,   ///< point light with s = 0, t ≠ 0: every such V maps to the light itself.
  light_parallel,   ///< directional light with s = 0, t ≠ 0: every such V maps to the light's direction.
  line_in_plane,    ///< s = 0 and t = 0: the line from V to the light lies in P; M V is the zero vector
                    ///< (V, on the receiver, is its own shadow: the grader in verify.h expects V).
};

/// Stable name of a class, as printed by the CLI ("on_receiver", "shadow", ...).
constexpr std::string_view to_string(point_class c) {
  switch (c) {
    case point_class::on_receiver: return "on_receiver";
    case point_class::shadow: return "shadow";
    case point_class::behind_receiver: return "behind_receiver";
    case point_class::beyond_light: return "beyond_light";
    case point_class::at_infinity: return "at_infinity";
    case point_class::at_light: return "at_light";
    case point_class::light_on_plane: return "light_on_plane";
    case point_class::light_parallel: return "light_parallel";
    case point_class::line_in_plane: return "line_in_plane";
  }
  return "unknown";
}

/// Sign of x: −1, 0 or +1 (exact for rationals).
template <class T>
int sign_of(const T& x) {
  return x > T(0) ? 1 : (x < T(0) ? -1 : 0);
}

/// Classifies the finite point V = (x, y, z, 1) (V[3] must be 1).
/// For a point light scale-invariance is kept by multiplying with w instead of dividing:
/// with s = P·L and t = P·V, the light's own plane value is s/w, so
///   on_receiver: t = 0;  at_light: V = L/w;  at_infinity: w t = s;
///   shadow: 0 < w t / s < 1, i.e. sign(t) = sign(s w) and |w t| < |s|;
///   beyond_light: same sign with |w t| > |s|;  behind_receiver: sign(t) = −sign(s w).
/// For a directional light (w = 0, pointing towards the light): shadow when sign(t) = sign(s).
/// Exact for rationals; for float and double it is the naive evaluation of the same formula.
template <class T>
point_class classify_point(const plane<T>& P, const light<T>& L, const vec4<T>& V) {
  const T s = dot(P.p, L.l);
  const T t = dot(P.p, V);
  const T& w = L.l[3];
  if (s == T(0)) {
    if (t == T(0)) return point_class::line_in_plane;
    return L.is_directional() ? point_class::light_parallel : point_class::light_on_plane;
  }
  if (t == T(0)) return point_class::on_receiver;
  if (L.is_directional())
    return sign_of(t) == sign_of(s) ? point_class::shadow : point_class::behind_receiver;
  // Point light: compare t with the light's own value s/w, scaled by w to stay division-free.
  const T wt = w * t;
  if (V[0] * w == L.l[0] && V[1] * w == L.l[1] && V[2] * w == L.l[2]) return point_class::at_light;
  if (wt == s) return point_class::at_infinity;
  if (sign_of(wt) != sign_of(s)) return point_class::behind_receiver;
  const bool nearer_than_light = (s > T(0)) ? (wt < s) : (wt > s);
  return nearer_than_light ? point_class::shadow : point_class::beyond_light;
}

}  // namespace shadowproof
