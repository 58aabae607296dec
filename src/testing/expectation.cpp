// Expectations: one case of the grader, the declared conventions and a failure policy.
#include "shadowproof/testing/expectation.h"

#include <cmath>

#include "failure_text.h"
#include "judgement.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/ulp.h"
#include "shadowproof/verify/grade.h"

namespace shadowproof {

namespace detail {

void check_group(scalar_type& type, bool& typed, scalar_type group_type, const char* name, std::size_t expected,
                 std::size_t given) {
  if (given != expected)
    throw error(errc::testing_input, std::string(name) + " has " + std::to_string(given) + " numbers, expected " +
                                         std::to_string(expected));
  if (typed && group_type != type)
    throw error(errc::testing_input, std::string(name) + " is " + std::string(to_string(group_type)) +
                                         " but the inputs before it are " + std::string(to_string(type)) +
                                         ": give every input in the format the routine computes in");
  type = group_type;
  typed = true;
}

}  // namespace detail

std::ostream& operator<<(std::ostream& out, const output_values& v) {
  out << '{';
  for (std::size_t i = 0; i < v.size(); ++i) out << (i ? ", " : "") << hex_string(v.values()[i]);
  return out << "} (" << to_string(v.type()) << ')';
}

output_values::output_values(const float* p, std::size_t n) : values_(p, p + n), type_(scalar_type::f32) {}
output_values::output_values(const double* p, std::size_t n) : values_(p, p + n), type_(scalar_type::f64) {}

expectation::expectation(operation op, scalar_type type, std::vector<double> inputs) {
  const auto& sig = signature(op);
  if (inputs.size() != sig.input_count)
    throw error(errc::testing_input, std::string(to_string(op)) + " takes " + std::to_string(sig.input_count) +
                                         " inputs, given " + std::to_string(inputs.size()));
  case_.op = op;
  case_.type = type;
  std::size_t k = 0;
  for (const auto& g : sig.inputs)
    for (std::size_t i = 0; i < g.size; ++i, ++k)
      if (!representable(inputs[k], type))
        throw error(errc::testing_input, g.name + "[" + std::to_string(i) + "] = " + hex_string(inputs[k]) +
                                             (std::isfinite(inputs[k]) ? " is not a " : " is not a finite ") +
                                             std::string(type == scalar_type::f32 ? "float" : "double"));
  case_.inputs = std::move(inputs);
  for (double& x : case_.inputs)
    if (x == 0) x = 0.0;  // −0 and +0 are the same exact input
  const std::string why = invalid_inputs_reason(case_);
  if (!why.empty()) throw error(errc::testing_input, std::string(to_string(op)) + ": " + why);
}

expectation expectation::within_ulps(std::uint64_t n) const { return failing_on(failure_policy::ulps_above(n)); }

expectation expectation::failing_on(const failure_policy& policy) const {
  expectation e = *this;
  e.policy_ = policy;
  return e;
}

expectation expectation::up_to_scale() const {
  expectation e = *this;
  e.conv_.homogeneous = true;
  return e;
}

expectation expectation::column_major() const {
  expectation e = *this;
  e.conv_.storage = storage_order::column_major;
  return e;
}

expectation expectation::row_vectors() const {
  expectation e = *this;
  e.conv_.vectors = vector_side::row;
  return e;
}

expectation expectation::light_along_rays() const {
  expectation e = *this;
  e.conv_.light = light_sign::along_rays;
  return e;
}

expectation expectation::depth(depth_convention c) const {
  expectation e = *this;
  e.conv_.depth = c;
  return e;
}

expectation expectation::with_conventions(const conventions& c) const {
  expectation e = *this;
  e.conv_ = c;
  return e;
}

std::string expectation::describe() const {
  std::string s = "is the correctly rounded " + std::string(to_string(case_.op)) + " of " +
                  detail::inputs_text(case_) + " in " + std::string(to_string(case_.type));
  const auto& ulps = policy_.ulps_threshold();
  if (ulps && *ulps > 0) s += ", within " + std::to_string(*ulps) + (*ulps == 1 ? " ulp" : " ulps");
  if (!policy_.verdict_names().empty()) s += ", failing on " + policy_.to_string();
  const std::string conv = detail::conventions_text(conv_, case_.op);
  if (!conv.empty()) s += ", " + conv;
  return s;
}

match_result expectation::match(const output_values& got) const {
  const auto& sig = signature(case_.op);
  const std::string op = std::string(to_string(case_.op));
  if (got.size() != sig.output_count)
    return {false, "  " + op + " has " + std::to_string(sig.output_count) + " outputs, given " +
                       std::to_string(got.size()) + "\n"};
  if (got.type() != case_.type)
    return {false, "  the outputs are " + std::string(to_string(got.type())) + " but the inputs are " +
                       std::string(to_string(case_.type)) + ": grade a routine in the format it computes in\n"};
  const case_grade g = grade_case(case_, conv_, got.data());
  const detail::case_judgement j = detail::judge(g, policy_);
  if (!j.fails) return {true, ""};
  const std::size_t failing = j.entries.size();
  std::string head = "  " + std::to_string(failing) + " of " + std::to_string(sig.output_count) + " outputs fail (" +
                     policy_.to_string() + ")";
  if (j.exact_class) head += "; the image is on the wrong side";
  return {false, head + ":\n" + detail::failure_text(case_, conv_, got.data(), j)};
}

}  // namespace shadowproof
