#pragma once
/// Handedness of eye space: which way the camera looks along z.
///   right: OpenGL's eye space, the camera looks down −z (every matrix in project.h);
///   left : Direct3D's (and Babylon's, Unity's) eye space, the camera looks down +z.
/// A left-handed projection is the right-handed one applied to (x, y, −z):
///   M_left = M_right · diag(1, 1, −1, 1), i.e. column 2 negated, exactly.
#include <string>
#include <string_view>

#include "shadowproof/core/error.h"
#include "shadowproof/core/homogeneous.h"

namespace shadowproof {

/// Right-handed (looking down −z) or left-handed (looking down +z) eye space.
enum class handedness { right, left };

/// "right" or "left" (the command-line spelling).
inline std::string_view to_string(handedness h) { return h == handedness::left ? "left" : "right"; }

/// Parses "right" or "left"; throws error "project.handedness" for anything else.
inline handedness parse_handedness(std::string_view text) {
  if (text == "right") return handedness::right;
  if (text == "left") return handedness::left;
  throw error(errc::project_handedness, "unknown handedness '" + std::string(text) + "': expected right or left");
}

/// M · diag(1, 1, −1, 1) for a left-handed eye space, M itself for a right-handed one: the
/// projection of the mirrored eye point (x, y, −z). Exact in every number type (negation).
template <class T>
mat4<T> with_handedness(mat4<T> M, handedness h) {
  if (h == handedness::left)
    for (std::size_t i = 0; i < 4; ++i) M(i, 2) = -M(i, 2);
  return M;
}

}  // namespace shadowproof
