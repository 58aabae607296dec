// perspective kernels: perspective(c, aspect, n, f, depth) with c = cot(fovy/2) (project.h):
//   [ c/aspect 0 0 0; 0 c 0 0; 0 0 A B; 0 0 −1 0 ], A and B as in frustum over f − n.
// c, aspect, n or f ≤ 0 admits no projection (every output undefined); n = f undefines A and B.
#include "view_volume.h"

namespace shadowproof::detail {
namespace {

struct perspective_form {
  static constexpr int inputs = 4, entries = 16, denominators = 2;
  static constexpr int degree = 2;

  static void prepare(const double* in, const conventions&, double* x) { copy_inputs(in, 4, x); }
  static bool undefined_case(const double* x, const conventions&) {
    return !(x[0] > 0) || !(x[1] > 0) || !(x[2] > 0) || !(x[3] > 0);
  }
  static fraction_layout layout(const conventions&) {
    fraction_layout l;
    l.denominator[0] = 0;  // c / aspect; aspect > 0 here
    l.on_zero[0] = zero_denominator::impossible;
    l.denominator[10] = l.denominator[11] = 1;
    l.on_zero[1] = zero_denominator::undefines_entries;
    return l;
  }

  template <class N>
  static void evaluate(const N* x, const conventions& conv, N* num, N* den) {
    for (int j = 0; j < 16; ++j) num[j] = N(0.0);
    const N& n = x[2];
    const N& f = x[3];
    den[0] = x[1];
    num[0] = x[0];
    num[5] = x[0];
    den[1] = f - n;
    perspective_depth_numerators(n, f, conv, num[10], num[11]);
    num[14] = N(-1.0);
  }
};

}  // namespace

bool fast_perspective_f32(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<perspective_form, float>(in, conv, out);
}

bool fast_perspective_f64(const double* in, const conventions& conv, fast_reference& out) {
  return fraction_kernel<perspective_form, double>(in, conv, out);
}

}  // namespace shadowproof::detail
