#pragma once
/// What can be graded: the operations, their inputs and outputs as flat arrays of numbers, and
/// the floating-point formats of an implementation. Every operation is one entry of the table
/// in operations.def; the functions below read that table.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowproof {

/// The operations a float routine can be graded on (operations.def, in its order):
///   shadow-matrix      plane[4], light[4] -> M = (P·L) I − L Pᵀ, 16 entries;
///   shadow-point       plane[4], light[4], point[3] -> affine image of the point, 3 entries;
///   reflection-matrix  plane[4] -> mirror matrix about P, 16 entries;
///   ortho, frustum     box[6] = l, r, b, t, n, f -> orthographic / frustum(…, depth), 16 entries;
///   normal-matrix      matrix[9] (3x3, row by row) -> (A⁻¹)ᵀ, 9 entries;
///   perspective        camera[4] = cot(fovy/2), aspect, n, f -> perspective(…, depth), 16 entries;
///   perspective-fov    camera[4] = fovy, aspect, n, f -> the same from the angle (irrational);
///   perspective-fov-infinite  camera[3] = fovy, aspect, n -> far plane at infinity;
///   look-at, target-to eye[3], target[3], up[3] -> view matrix / its inverse (irrational);
///   ortho-size, perspective-size  size[4] = width, height, n, f -> symmetric volumes.
/// summary(op) says the same for each one.
enum class operation {
#define SHADOWPROOF_OPERATION(code) code,
#include "shadowproof/verify/operations.def"
#undef SHADOWPROOF_OPERATION
};

/// Every operation, in a stable order.
const std::vector<operation>& all_operations();

/// Stable name used on the command line and in case files ("shadow-matrix", ...).
std::string_view to_string(operation op);
/// Inverse of to_string; nothing for an unknown name.
std::optional<operation> operation_from_string(std::string_view name);
/// Every name joined by `separator`, in table order: "shadow-matrix|shadow-point|…".
std::string operation_names(std::string_view separator = "|");
/// One line saying what the operation computes from what, for help texts and reports.
std::string_view summary(operation op);

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

/// The canonical name of output j: "(row,col)" of a matrix (row-major, zero-based) or the
/// coordinate ("x", "y", "z") of a point.
std::string output_name(operation op, std::size_t j);

/// Facts about an operation that need no oracle, which the fuzzer checks metamorphically: the
/// outputs scale by 2^degree when the plane (light) input is doubled (−1: no such input or no
/// such relation); swapping x and y in every input swaps them in the outputs; translating the
/// whole configuration translates the output point.
struct operation_symmetries {
  int plane_degree = -1;
  int light_degree = -1;
  bool swap_xy = false;
  bool translation = false;
};
/// The symmetries of op (a static object).
const operation_symmetries& symmetries(operation op);

/// The operation's inputs for a shadow configuration (plane[4], light[4], point[3]), as the
/// fuzzer's degeneracy-biased generator makes them; nothing when op takes other inputs.
std::optional<std::vector<double>> inputs_from_shadow_configuration(operation op, const double* plane,
                                                                    const double* light, const double* point);

/// Floating-point format of an implementation's inputs and outputs.
enum class scalar_type { f32, f64 };
/// "f32" or "f64".
std::string_view to_string(scalar_type t);
/// Inverse of to_string; nothing for an unknown name.
std::optional<scalar_type> scalar_type_from_string(std::string_view name);
/// True when x is finite and exactly a value of type t.
bool representable(double x, scalar_type t);

}  // namespace shadowproof
