// Names and signatures of the operations an implementation can be graded on.
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"

namespace shadowproof {

const std::vector<operation>& all_operations() {
  static const std::vector<operation> ops{operation::shadow_matrix, operation::shadow_point,
                                          operation::reflection_matrix, operation::ortho,
                                          operation::frustum, operation::normal_matrix};
  return ops;
}

std::string_view to_string(operation op) {
  switch (op) {
    case operation::shadow_matrix: return "shadow-matrix";
    case operation::shadow_point: return "shadow-point";
    case operation::reflection_matrix: return "reflection-matrix";
    case operation::ortho: return "ortho";
    case operation::frustum: return "frustum";
    case operation::normal_matrix: return "normal-matrix";
  }
  return "unknown";
}

std::optional<operation> operation_from_string(std::string_view name) {
  for (operation op : all_operations())
    if (to_string(op) == name) return op;
  return std::nullopt;
}

const operation_signature& signature(operation op) {
  static const operation_signature shadow_matrix{{{"plane", 4}, {"light", 4}}, 8, 16, 4};
  static const operation_signature shadow_point{{{"plane", 4}, {"light", 4}, {"point", 3}}, 11, 3, 0};
  static const operation_signature reflection_matrix{{{"plane", 4}}, 4, 16, 4};
  static const operation_signature box{{{"box", 6}}, 6, 16, 4};
  static const operation_signature normal{{{"matrix", 9}}, 9, 9, 3};
  switch (op) {
    case operation::shadow_matrix: return shadow_matrix;
    case operation::shadow_point: return shadow_point;
    case operation::reflection_matrix: return reflection_matrix;
    case operation::ortho:
    case operation::frustum: return box;
    case operation::normal_matrix: return normal;
  }
  return shadow_matrix;
}

std::string_view to_string(scalar_type t) { return t == scalar_type::f32 ? "f32" : "f64"; }

std::optional<scalar_type> scalar_type_from_string(std::string_view name) {
  if (name == "f32") return scalar_type::f32;
  if (name == "f64") return scalar_type::f64;
  return std::nullopt;
}

std::string_view to_string(input_class c) {
  switch (c) {
    case input_class::regular: return "regular";
    case input_class::near_degenerate: return "near-degenerate";
    case input_class::degenerate: return "degenerate";
  }
  return "unknown";
}

std::optional<input_class> input_class_from_string(std::string_view name) {
  for (input_class c : {input_class::regular, input_class::near_degenerate, input_class::degenerate})
    if (to_string(c) == name) return c;
  return std::nullopt;
}

std::string_view to_string(image_class c) {
  switch (c) {
    case image_class::on_receiver: return "on_receiver";
    case image_class::shadow: return "shadow";
    case image_class::behind_receiver: return "behind_receiver";
    case image_class::beyond_light: return "beyond_light";
    case image_class::nonfinite: return "nonfinite";
    case image_class::other: return "other";
  }
  return "unknown";
}

}  // namespace shadowproof
