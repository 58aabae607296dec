// Deterministic test cases for the grader, in three classes of closeness to degeneracy; each
// operation's generator and closeness measure come from its entry in the operation table.
#include <cmath>

#include "operation_table.h"
#include "shadowproof/verify/cases.h"

namespace shadowproof {

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

std::vector<test_case> generate_cases(operation op, scalar_type type, std::size_t count,
                                      std::uint64_t seed, std::optional<input_class> cls,
                                      const conventions& requirements, std::uint64_t first_id) {
  const detail::operation_spec& spec = detail::spec_of(op);
  detail::case_rng r(seed, type);
  r.unit_normal = requirements.unit_normal;
  std::vector<test_case> cases;
  cases.reserve(count);
  const input_class cycle[3] = {input_class::regular, input_class::near_degenerate, input_class::degenerate};
  for (std::size_t i = 0; i < count; ++i) {
    test_case c;
    c.id = first_id + i;
    c.op = op;
    c.type = type;
    c.cls = cls ? *cls : cycle[i % 3];
    c.inputs.assign(spec.signature.input_count, 0.0);
    spec.generate(r, c.cls, requirements, c.inputs.data());
    for (double& x : c.inputs)
      if (x == 0) x = 0.0;  // no −0: the case file's exact decimals could not tell them apart
    cases.push_back(std::move(c));
  }
  return cases;
}

std::string reproducer_command(const test_case& c, const conventions& conv) {
  return detail::spec_of(c.op).reproducer(c, conv);
}

std::string invalid_inputs_reason(const test_case& c) { return detail::spec_of(c.op).invalid(c.inputs.data()); }

double closeness_to_degeneracy(const test_case& c) { return detail::spec_of(c.op).closeness(c.inputs.data()); }

}  // namespace shadowproof
