// The exact answer of a case, straight from the operation's entry in the table.
#include "shadowproof/verify/exact_answer.h"

#include "operation_table.h"

namespace shadowproof {

std::vector<std::optional<rational>> exact_answer(const test_case& c, const conventions& conv) {
  const detail::exact_outputs<rational> e = detail::spec_of(c.op).exact_rational(c.inputs.data(), conv);
  const std::size_t n = signature(c.op).output_count;
  std::vector<std::optional<rational>> values(n);
  if (!e.defined) return values;
  for (std::size_t i = 0; i < n; ++i)
    if (e.entry_undefined.empty() || !e.entry_undefined[i]) values[i] = e.values[i];
  return values;
}

}  // namespace shadowproof
