// Fuzz target: the graded comparison of a registered implementation against the exact answer.
// The case and the implementation are decoded from the input (coordinates from small-integer
// grids, raw float bits and perturbed degenerate configurations). Invariants: grading never
// crashes, and the interval-filtered oracle gives exactly the grade of the all-rational one.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "shadowproof/fuzz/differential.h"
#include "shadowproof/core/error.h"
#include "byte_source.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/impls/builtin.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"

namespace {

using namespace shadowproof;

bool fuzzed_from_shadow_configurations(operation op) {
  const double zeros[4] = {0, 0, 0, 0};
  return inputs_from_shadow_configuration(op, zeros, zeros, zeros).has_value();
}

const std::vector<const implementation*>& shadow_implementations() {
  static const std::vector<const implementation*> list = [] {
    std::vector<const implementation*> v;
    for (const auto& i : builtin_implementations())
      if (fuzzed_from_shadow_configurations(i.op)) v.push_back(&i);
    return v;
  }();
  return list;
}

bool same_grade(const case_grade& a, const case_grade& b) {
  if (a.outputs.size() != b.outputs.size()) return false;
  for (std::size_t i = 0; i < a.outputs.size(); ++i) {
    const auto &x = a.outputs[i], &y = b.outputs[i];
    if (x.exact_defined != y.exact_defined || x.ulps != y.ulps || x.nonfinite != y.nonfinite || x.garbage != y.garbage)
      return false;
    if (x.exact_defined && !(x.reference == y.reference || (std::isnan(x.reference) && std::isnan(y.reference))))
      return false;
  }
  return a.max_ulps == b.max_ulps && a.exact_class == b.exact_class && a.got_class == b.got_class &&
         a.misclassified == b.misclassified;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& impls = shadow_implementations();
  if (impls.empty()) return 0;
  byte_source src(data, size);
  const implementation& impl = *impls[src.below(impls.size())];
  generated_case<double> g;
  if (impl.type == scalar_type::f32) {
    const auto f = decode_shadow_case<float>(src);
    std::copy(f.plane.begin(), f.plane.end(), g.plane.begin());
    std::copy(f.light.begin(), f.light.end(), g.light.begin());
    std::copy(f.point.begin(), f.point.end(), g.point.begin());
    g.family = f.family;
  } else {
    g = decode_shadow_case<double>(src);
  }
  for (double x : g.plane) if (!std::isfinite(x)) return 0;
  for (double x : g.light) if (!std::isfinite(x)) return 0;
  for (double x : g.point) if (!std::isfinite(x)) return 0;
  if (g.plane[0] == 0 && g.plane[1] == 0 && g.plane[2] == 0) return 0;
  if (g.light[0] == 0 && g.light[1] == 0 && g.light[2] == 0 && g.light[3] == 0) return 0;
  const test_case c = make_fuzz_case(g, impl, 0);
  std::vector<double> out(signature(c.op).output_count);
  impl.run(c.inputs.data(), out.data());
  const case_grade filtered = grade_case(c, impl.conv, out.data(), oracle_mode::filtered);
  const case_grade naive = grade_case(c, impl.conv, out.data(), oracle_mode::naive);
  if (!same_grade(filtered, naive)) std::abort();
  return 0;
}
