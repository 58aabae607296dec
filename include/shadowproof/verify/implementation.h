#pragma once
/// A float routine under test: what it computes, in which format and conventions, and how to
/// call it.
#include <functional>
#include <string>

#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof {

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

}  // namespace shadowproof
