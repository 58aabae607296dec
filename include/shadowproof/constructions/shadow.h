#pragma once
/// The planar shadow matrix and the closed forms the reference derivations give for it.
#include <array>

#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/plane.h"

namespace shadowproof {

// ===========================================================================================
// General form

/// M = (P·L) I − L Pᵀ (column vectors: the shadow of V is M V).
/// Every V maps onto P: P·(M V) = (P·L)(P·V) − (P·L)(P·V) = 0. Valid for every homogeneous
/// light, point (w ≠ 0) or directional (w = 0). Degenerate cases are *results*, see
/// classify.h: P·L = 0 gives M = −L Pᵀ (rank 1: everything off the plane maps to L itself).
template <class T>
mat4<T> shadow_matrix(const plane<T>& P, const light<T>& L) {
  const T s = dot(P.p, L.l);
  return s * identity4<T>() - outer(L.l, P.p);
}

/// Image of V under the shadow matrix without forming it: M V = (P·L) V − (P·V) L.
template <class T>
vec4<T> shadow_image(const plane<T>& P, const light<T>& L, const vec4<T>& V) {
  const T s = dot(P.p, L.l);
  const T t = dot(P.p, V);
  return s * V - t * L.l;
}

// ===========================================================================================
// Closed forms from the reference derivations, each with its own conventions.

/// Seed 000: directional light with direction (Lx, Ly, Lz) onto a x + b y + c z + d = 0,
/// written out entry by entry:
///   [bLy+cLz, −bLx, −cLx, −dLx; −aLy, aLx+cLz, −cLy, −dLy; −aLz, −bLz, aLx+bLy, −dLz; 0,0,0, aLx+bLy+cLz].
/// Equals shadow_matrix(P, (Lx, Ly, Lz, 0)) exactly. The sign of (Lx, Ly, Lz) only scales M by −1.
template <class T>
mat4<T> shadow_matrix_directional_closed_form(const plane<T>& P, const T& lx, const T& ly,
                                              const T& lz) {
  const T &a = P.a(), &b = P.b(), &c = P.c(), &d = P.d();
  return make_mat4<T>({b * ly + c * lz, -b * lx,          -c * lx,          -d * lx,
                       -a * ly,         a * lx + c * lz,  -c * ly,          -d * ly,
                       -a * lz,         -b * lz,          a * lx + b * ly,  -d * lz,
                       T(0),            T(0),             T(0),             a * lx + b * ly + c * lz});
}

/// Seed 001, method 1 (ray/plane intersection) onto the ground plane y = h, for a directional
/// light whose direction `dir` points towards the light:
///   k = ((p0 − X)·n) / (dir·n) with p0 = (0, h, 0), n = (0, 1, 0);  image = X + k dir.
/// The shader normalises dir first; that changes k, not the image, so it is omitted here.
/// Precondition dir.y ≠ 0 (the formula divides by it; a parallel light has no image).
template <class T>
std::array<T, 3> ground_shadow_by_intersection(const std::array<T, 3>& X, const std::array<T, 3>& dir,
                                               const T& h) {
  const T k = (h - X[1]) / dir[1];
  return {X[0] + k * dir[0], X[1] + k * dir[1], X[2] + k * dir[2]};
}

/// Seed 001, method 2 (similar triangles) with the shader's clamping, ground plane y = h:
///   G.xz = X.xz − dir.xz · max(0, X.y − h) / dir.y,  G.y = min(X.y, h).
/// Points above the ground agree with the shadow matrix; points below the ground are left
/// where they are (the matrix instead gives a false shadow). Precondition dir.y ≠ 0.
template <class T>
std::array<T, 3> ground_shadow_by_similar_triangles(const std::array<T, 3>& X,
                                                    const std::array<T, 3>& dir, const T& h) {
  const T height = X[1] > h ? T(X[1] - h) : T(0);
  const T k = height / dir[1];
  return {X[0] - dir[0] * k, X[1] < h ? X[1] : h, X[2] - dir[2] * k};
}

/// Seed 002: point light l = (xl, yl, zl) onto y = 0 as T(l) · N · T(−l), with
///   N = [1,0,0,0; 0,1,0,0; 0,0,1,0; 0, −1/yl, 0, 0] (projection from the origin onto y = −yl).
/// Equals (1/yl) · shadow_matrix((0,1,0,0), (xl,yl,zl,1)): the same projective map.
/// Precondition yl ≠ 0 (the light on the ground has no such matrix).
template <class T>
mat4<T> ground_shadow_matrix_by_translation(const T& xl, const T& yl, const T& zl) {
  mat4<T> N = identity4<T>();
  N(3, 3) = T(0);
  N(3, 1) = T(-1) / yl;
  return translation<T>(xl, yl, zl) * N * translation<T>(-xl, -yl, -zl);
}

/// Seed 003: shadow of the point V from the point light L onto ⟨N, Q⟩ + d = 0 along the ray
/// r(t) = L + (V − L) t:   Q = L − (V − L)(⟨N, L⟩ + d) / ⟨N, V − L⟩.
/// Precondition ⟨N, V − L⟩ ≠ 0 (the ray is not parallel to the plane).
template <class T>
std::array<T, 3> shadow_point_by_ray(const plane<T>& P, const std::array<T, 3>& L,
                                     const std::array<T, 3>& V) {
  const std::array<T, 3> dir{V[0] - L[0], V[1] - L[1], V[2] - L[2]};
  const T num = P.a() * L[0] + P.b() * L[1] + P.c() * L[2] + P.d();
  const T den = P.a() * dir[0] + P.b() * dir[1] + P.c() * dir[2];
  const T k = num / den;
  return {L[0] - dir[0] * k, L[1] - dir[1] * k, L[2] - dir[2] * k};
}

}  // namespace shadowproof
