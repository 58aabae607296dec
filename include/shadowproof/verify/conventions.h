#pragma once
/// Conventions an implementation declares: storage, vector side, light sign, depth range, and
/// the input restrictions it needs. The grader maps each to the canonical form exactly, so a
/// convention is never reported as an error and never hides one.
#include <optional>
#include <string_view>

#include "shadowproof/constructions/handedness.h"
#include "shadowproof/constructions/irrational.h"
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

/// How a plane's fourth number is meant: (a, b, c, d) is a x + b y + c z + d = 0 (`plus_d`, the
/// canonical form) or a x + b y + c z = d (`equals_d`, e.g. three.js ShadowMesh's reading).
/// A protocol convention: case files write planes in the declared form and the reader maps
/// them back exactly (d ↦ −d), so a test_case always holds the canonical form.
enum class plane_form { plus_d, equals_d };
/// How a 3x3 matrix (the normal matrix's input and output) is laid out: 9 numbers (`packed`),
/// 12 (`padded`: three groups of 4, each row or column followed by one unused number, as
/// WGSL's mat3x3<f32> and wgpu-matrix's mat3 store it), or 16 (`mat4`: embedded as
/// [A 0; 0 1], as libraries that only have 4x4 matrices use it). A protocol convention: the
/// reader maps the line to the 9 canonical numbers; padding is ignored, and the embedding's
/// own entries must be exactly 0 and 1.
enum class matrix3_layout { packed, padded, mat4 };

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
  /// Projections and look-at cameras: eye space looking down −z (right) or +z (left);
  /// left-handed projections are M · diag(1, 1, −1, 1) (constructions/handedness.h).
  handedness hand = handedness::right;
  /// perspective-fov: unit of the field-of-view angle.
  angle_unit angle = angle_unit::radians;
  /// Protocol only (case files): how planes are written, see plane_form.
  plane_form plane = plane_form::plus_d;
  /// Protocol only (case files): how 3x3 matrix outputs are laid out, see matrix3_layout.
  matrix3_layout matrix3 = matrix3_layout::packed;
  /// Protocol only (case files): how 3x3 matrix inputs are laid out (a library may take a
  /// mat4 and return a mat3, as gl-matrix's normalFromMat4 and three.js's getNormalMatrix do).
  matrix3_layout matrix3_input = matrix3_layout::packed;
};

}  // namespace shadowproof
