#pragma once
/// What can be graded: the operations, their inputs and outputs as flat arrays of numbers, and
/// the floating-point formats of an implementation.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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

}  // namespace shadowproof
