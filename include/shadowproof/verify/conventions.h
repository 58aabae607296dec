#pragma once
/// Conventions an implementation declares: storage, vector side, light sign, depth range, and
/// the input restrictions it needs. The grader maps each to the canonical form exactly, so a
/// convention is never reported as an error and never hides one.
#include <optional>
#include <string_view>

#include "shadowproof/constructions/project.h"

namespace shadowproof {

/// How the 16 numbers of a matrix are laid out in memory.
enum class storage_order { row_major, column_major };
/// Whether the matrix multiplies column vectors (M v) or row vectors (v M, i.e. the transpose).
enum class vector_side { column, row };
/// Sign of a directional light's (x, y, z): the library's canonical form points towards the
/// light; `along_rays` means the vector is the direction the light travels (the negation).
enum class light_sign { towards_light, along_rays };

/// What an implementation returns, by its documentation, when the problem has no answer (a
/// singular matrix, a flat view volume, a point whose shadow does not exist). NaN or ±Inf in
/// every output is always accepted as a rejection; a sentinel is accepted besides when declared.
///   zero: every output 0 (the zero matrix, the origin);
///   identity: the identity matrix (matrices only), as Qt's QMatrix4x4::inverted returns it.
enum class sentinel_kind { none, zero, identity };
/// "none", "zero", "identity".
std::string_view to_string(sentinel_kind s);
/// Inverse of to_string; nothing for an unknown name.
std::optional<sentinel_kind> sentinel_from_string(std::string_view name);

/// Declared conventions of an implementation (defaults are the library's canonical forms).
struct conventions {
  storage_order storage = storage_order::row_major;
  vector_side vectors = vector_side::column;
  light_sign light = light_sign::towards_light;
  /// The routine scales the plane to a unit normal first. For the shadow matrix this scales
  /// the result by 1/|n| (irrational in general), so it implies grading up to scale.
  bool normalises_plane = false;
  /// The result is a homogeneous matrix: any non-zero multiple of the exact one is correct.
  bool homogeneous = false;
  /// Only directional lights (w = 0) are accepted; cases are generated accordingly.
  bool directional_only = false;
  /// Only point lights (w = 1) are accepted; cases are generated accordingly.
  bool point_light_only = false;
  /// Only planes with a unit normal are accepted (exactly: ±1 on one axis, e.g. the ground
  /// y = h), as routines that assume a normalised plane require.
  bool unit_normal = false;
  /// shadow-point: points behind the receiver are deliberately left where they are (seed
  /// 001's clamping shader) instead of getting the matrix's false shadow.
  bool clamps_behind_receiver = false;
  /// ortho / frustum: NDC depth range of near and far (project.h).
  depth_convention depth = depth_convention::gl;
  /// ortho / frustum: only symmetric volumes (l = −r, b = −t), for builders taking a width
  /// and a height; cases are generated accordingly.
  bool symmetric_view = false;
  /// The documented answer for a problem without one, accepted besides NaN/±Inf.
  sentinel_kind sentinel = sentinel_kind::none;
};

}  // namespace shadowproof
