#pragma once
/// Implementations under test: what a float routine computes, in which conventions, and how
/// to call it. The grader (verify.h) maps every declared convention to the canonical form
/// exactly, so a convention is never reported as an error and never hides one.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/project.h"

namespace shadowproof {

/// The operations a float routine can be graded on. Inputs and outputs are flat arrays of
/// numbers; the canonical meaning of each is given by operation_signature().
enum class operation {
  shadow_matrix,      ///< plane[4], light[4] -> M = (P·L) I − L Pᵀ, 16 entries.
  shadow_point,       ///< plane[4], light[4], point[3] -> affine image of the point, 3 entries.
  reflection_matrix,  ///< plane[4] -> mirror matrix about P, 16 entries.
  ortho,              ///< box[6] = l, r, b, t, n, f -> orthographic(…, depth), 16 entries.
  frustum,            ///< box[6] = l, r, b, t, n, f -> frustum(…, depth), 16 entries.
  normal_matrix,      ///< matrix[9] (3x3, row by row) -> (A⁻¹)ᵀ, 9 entries; undefined if det A = 0.
};

/// Every operation, in a stable order.
const std::vector<operation>& all_operations();

/// Stable name used on the command line and in case files ("shadow-matrix", ...).
std::string_view to_string(operation op);
/// Inverse of to_string; nothing for an unknown name.
std::optional<operation> operation_from_string(std::string_view name);

/// One named group of inputs ("plane", 4 numbers).
struct input_group {
  std::string name;
  std::size_t size;
};

/// Inputs (in order, flattened) and the number of outputs of an operation.
struct operation_signature {
  std::vector<input_group> inputs;
  std::size_t input_count;
  std::size_t output_count;
  std::size_t matrix_size;  ///< 4 or 3 when the outputs form a square matrix (storage
                            ///< conventions apply), 0 otherwise
};
/// The signature of op (a static object).
const operation_signature& signature(operation op);

/// Floating-point format of an implementation's inputs and outputs.
enum class scalar_type { f32, f64 };
/// "f32" or "f64".
std::string_view to_string(scalar_type t);
/// Inverse of to_string; nothing for an unknown name.
std::optional<scalar_type> scalar_type_from_string(std::string_view name);

/// How the 16 numbers of a matrix are laid out in memory.
enum class storage_order { row_major, column_major };
/// Whether the matrix multiplies column vectors (M v) or row vectors (v M, i.e. the transpose).
enum class vector_side { column, row };
/// Sign of a directional light's (x, y, z): the library's canonical form points towards the
/// light; `along_rays` means the vector is the direction the light travels (the negation).
enum class light_sign { towards_light, along_rays };

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
};

/// Calls the routine: `inputs` holds signature(op).input_count numbers, each exactly
/// representable in the implementation's scalar_type; it writes output_count numbers (a float
/// routine's results widened to double, which is exact).
using implementation_function = std::function<void(const double* inputs, double* outputs)>;

/// A routine under test.
struct implementation {
  std::string name;         ///< unique, e.g. "glm-reflect3d-f32"
  operation op;
  scalar_type type;
  conventions conv;
  std::string origin;       ///< what it is, e.g. "GLM 0.9.9.8 glm::reflect3D (gtx/transform2)"
  implementation_function run;
};

/// The built-in implementations (src/impls/, library shadowproof_impls): seed formulas written
/// as shaders and engines write them, and engine code from Debian packages. Sorted by name.
const std::vector<implementation>& builtin_implementations();

/// The built-in implementation called `name`; throws error "verify.unknown_impl" naming it.
const implementation& find_builtin_implementation(std::string_view name);

}  // namespace shadowproof
