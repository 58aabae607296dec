// Deterministic test cases for the grader, in three classes of closeness to degeneracy; each
// operation's generator and closeness measure come from its entry in the operation table.
#include <cmath>

#include "conditioning.h"
#include "operation_table.h"
#include "shadowproof/core/error.h"
#include "shadowproof/verify/cases.h"

namespace shadowproof {

std::string_view to_string(input_class c) {
  switch (c) {
    case input_class::regular: return "regular";
    case input_class::near_degenerate: return "near-degenerate";
    case input_class::degenerate: return "degenerate";
    case input_class::range: return "range";
  }
  return "unknown";
}

const std::vector<input_class>& all_input_classes() {
  static const std::vector<input_class> classes{input_class::regular, input_class::near_degenerate,
                                                input_class::degenerate, input_class::range};
  return classes;
}

std::optional<input_class> input_class_from_string(std::string_view name) {
  for (input_class c : all_input_classes())
    if (to_string(c) == name) return c;
  return std::nullopt;
}

struct case_stream::state {
  const detail::operation_spec& spec;
  scalar_type type;
  std::optional<input_class> cls;
  conventions requirements;
  detail::case_rng rng;
  std::uint64_t next_id = 0;
};

case_stream::case_stream(operation op, scalar_type type, std::uint64_t seed, std::optional<input_class> cls,
                         const conventions& requirements)
    : state_(new state{detail::spec_of(op), type, cls, requirements, detail::case_rng(seed, type)}) {
  state_->rng.unit_normal = requirements.unit_normal;
}

case_stream::~case_stream() = default;
case_stream::case_stream(case_stream&&) noexcept = default;
case_stream& case_stream::operator=(case_stream&&) noexcept = default;

std::vector<test_case> case_stream::next(std::size_t count) {
  state& st = *state_;
  const operation op = st.spec.op;
  std::vector<test_case> cases;
  cases.reserve(count);
  const std::vector<input_class>& cycle = all_input_classes();
  // Near-degenerate means within the type's resolution and not on the degeneracy: closer than
  // 2^-(p−1), the inputs' rounding decides the answer; exactly on it is the degenerate class.
  const double resolution = -(st.type == scalar_type::f32 ? 24.0 : 53.0) + 1;
  for (std::size_t i = 0; i < count; ++i, ++st.next_id) {
    test_case c;
    c.id = st.next_id;
    c.op = op;
    c.type = st.type;
    c.cls = st.cls ? *st.cls : cycle[st.next_id % cycle.size()];
    c.inputs.assign(st.spec.signature.input_count, 0.0);
    for (int attempt = 0;; ++attempt) {
      st.spec.generate(st.rng, c.cls, st.requirements, c.inputs.data());
      for (double& x : c.inputs)
        if (x == 0) x = 0.0;  // no −0: the case file's exact decimals could not tell them apart
      c.closeness = st.spec.closeness(c.inputs.data());
      if (c.cls == input_class::near_degenerate) {
        if (std::isfinite(c.closeness) && c.closeness >= resolution) break;
      } else if (c.cls == input_class::range) {
        if (detail::leaves_range(c, st.requirements)) break;
      } else {
        break;
      }
      if (attempt == 1000)
        throw internal_error("the " + std::string(to_string(c.cls)) + " generator of " + std::string(st.spec.name) +
                             " keeps missing its class");
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

std::vector<test_case> generate_cases(operation op, scalar_type type, std::size_t count,
                                      std::uint64_t seed, std::optional<input_class> cls,
                                      const conventions& requirements, std::uint64_t first_id) {
  std::vector<test_case> cases = case_stream(op, type, seed, cls, requirements).next(count);
  for (test_case& c : cases) c.id += first_id;
  return cases;
}

std::string reproducer_command(const test_case& c, const conventions& conv) {
  return detail::spec_of(c.op).reproducer(c, conv);
}

std::string invalid_inputs_reason(const test_case& c) { return detail::spec_of(c.op).invalid(c.inputs.data()); }

double closeness_to_degeneracy(const test_case& c) { return detail::spec_of(c.op).closeness(c.inputs.data()); }

}  // namespace shadowproof
