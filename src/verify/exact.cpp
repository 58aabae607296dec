// The exact answer and its correct rounding, from the operation table.
#include "shadowproof/verify/exact.h"

#include <limits>

#include "operation_table.h"

namespace shadowproof {

exact_result exact_result_of(const test_case& c, const conventions& conv) {
  const detail::operation_spec& spec = detail::spec_of(c.op);
  const detail::exact_outputs<rational> e = spec.exact_rational(c.inputs.data(), conv);
  exact_result a;
  a.cls = e.cls;
  for (std::size_t i = 0; i < spec.signature.output_count; ++i) {
    const bool defined = e.defined && (e.entry_undefined.empty() || !e.entry_undefined[i]);
    a.defined.push_back(defined);
    a.values.push_back(defined ? e.values[i] : rational(0));
  }
  return a;
}

std::vector<double> correctly_rounded_outputs(const test_case& c, const conventions& conv, const rational& scale) {
  const exact_result a = exact_result_of(c, conv);
  const std::size_t k = signature(c.op).matrix_size;
  std::vector<double> out(a.values.size());
  for (std::size_t j = 0; j < out.size(); ++j) {
    const std::size_t i = detail::canonical_index(j, k, conv);
    if (!a.defined[i]) {
      out[j] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    const rational v = scale * a.values[i];
    out[j] = c.type == scalar_type::f32 ? static_cast<double>(detail::round_exact<float>(v))
                                        : detail::round_exact<double>(v);
  }
  return out;
}

}  // namespace shadowproof
