#pragma once
/// The library's own templates instantiated with recorded terms: conversions between the
/// library's vec4/mat4/plane/light of `term` and the proofs' matrices. A matrix the library
/// computes prints under the call that computed it, e.g. "\texttt{shadow\_matrix}(P, L)".
#include <array>
#include <string>

#include "mat.h"
#include "shadowproof/core/homogeneous.h"
#include "shadowproof/core/light.h"
#include "shadowproof/core/plane.h"

namespace shadowproof::proofs {

/// A column 4-vector as the library's vec4.
inline vec4<term> to_vec4(const mat& v) { return make_vec4<term>(v[0], v[1], v[2], v[3]); }

/// A 4x4 matrix as the library's mat4.
inline mat4<term> to_mat4(const mat& m) {
  mat4<term> r;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) r(i, j) = m(static_cast<unsigned>(i), static_cast<unsigned>(j));
  return r;
}

/// The plane P = (a, b, c, d) without make_plane's check (the proofs decide nothing about it).
inline plane<term> to_plane(const mat& P) { return plane<term>{to_vec4(P)}; }
inline light<term> to_light(const mat& L) { return light<term>{to_vec4(L)}; }

/// A 3-vector as the library's std::array.
inline std::array<term, 3> to_array(const mat& v) { return {v[0], v[1], v[2]}; }

/// "\texttt{name}" for a C++ identifier (underscores escaped).
inline std::string code_tex(const std::string& name) {
  std::string s;
  for (char ch : name) s += ch == '_' ? std::string("\\_") : std::string(1, ch);
  return "\\texttt{" + s + "}";
}

/// The library's result, printed as `call` (LaTeX).
inline mat from_library(const mat4<term>& m, const std::string& call) {
  std::vector<term> e;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) e.push_back(m(i, j));
  return mat(4, 4, std::move(e), call, tex_precedence::atom);
}

inline mat from_library(const vec4<term>& v, const std::string& call) {
  return mat(4, 1, {v[0], v[1], v[2], v[3]}, call, tex_precedence::atom);
}

inline mat from_library(const std::array<term, 3>& v, const std::string& call) {
  return mat(3, 1, {v[0], v[1], v[2]}, call, tex_precedence::atom);
}

}  // namespace shadowproof::proofs
