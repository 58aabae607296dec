// The correctly rounded references "correctly-rounded-<op>-<type>": the exact answer computed
// with rationals by the operation table and rounded with MPFR, NaN where it does not exist.
#include "shadowproof/impls/reference.h"

#include <cmath>
#include <limits>

#include "impls.h"
#include "shadowproof/verify/exact.h"

namespace shadowproof {

implementation correctly_rounded_implementation(operation op, scalar_type type, const conventions& conv,
                                                const rational& scale, bool use_sentinel) {
  implementation impl;
  impl.name = "correctly-rounded-" + std::string(to_string(op)) + "-" + std::string(to_string(type));
  impl.op = op;
  impl.type = type;
  impl.conv = conv;
  impl.origin = "the exact answer correctly rounded to " + std::string(to_string(type)) +
                " (rationals, MPFR round to nearest), NaN where it does not exist";
  impl.run = [op, type, conv, scale, use_sentinel](const double* inputs, double* outputs) {
    test_case c;
    c.op = op;
    c.type = type;
    c.inputs.assign(inputs, inputs + signature(op).input_count);
    const std::vector<double> rounded = correctly_rounded_outputs(c, conv, scale);
    bool undefined = false;
    for (double x : rounded) undefined = undefined || std::isnan(x);
    const std::size_t k = signature(op).matrix_size;
    for (std::size_t j = 0; j < rounded.size(); ++j) {
      if (undefined && use_sentinel && conv.sentinel != sentinel_kind::none)
        outputs[j] = conv.sentinel == sentinel_kind::identity && k && j % (k + 1) == 0 ? 1.0 : 0.0;
      else outputs[j] = rounded[j];
    }
  };
  return impl;
}

namespace impls {

void add_reference(std::vector<implementation>& out) {
  for (operation op : all_operations())
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) out.push_back(correctly_rounded_implementation(op, type));
}

}  // namespace impls
}  // namespace shadowproof
