// perspective: camera[4] = c, aspect, n, f -> perspective(c, aspect, n, f, depth), 16 entries:
// gluPerspective from the focal scale c = cot(fovy/2), the aspect width/height and the near
// and far distances, onto the canonical volume of the declared depth convention:
//   [ c/aspect 0 0 0; 0 c 0 0; 0 0 A B; 0 0 −1 0 ], A, B as in frustum (project.h).
// Classes: near-degenerate = far within a relative 2^-4 … 2^-(p−1) of near, or far ≫ near;
// degenerate = n = f (A and B undefined, the rest defined); range = n and f scaled so that n f
// over- or underflows. c, aspect, n or f ≤ 0 admits no projection: every output is undefined.
// Stable: c/aspect takes one rounding, A and B two or three (B = 2 f n r with r = 1/(n − f) takes
// three): c = 2 × 3 = 6.
#include <cmath>
#include <limits>

#include "view_volume.h"

namespace shadowproof::detail {
namespace {

template <class N>
exact_outputs<N> exact(const double* in, const conventions& conv) {
  exact_outputs<N> r;
  const N c = from_double<N>(in[0]), aspect = from_double<N>(in[1]), n = from_double<N>(in[2]);
  N f = from_double<N>(in[3]);
  if (sign_n(c) <= 0 || sign_n(aspect) <= 0 || sign_n(n) <= 0 || sign_n(f) <= 0) {
    r.set_undefined(16);
    return r;
  }
  r.entry_undefined.assign(16, false);
  if (sign_n(N(f - n)) == 0) {  // zero depth extent: only the depth row divides by f − n
    r.entry_undefined[2 * 4 + 2] = r.entry_undefined[2 * 4 + 3] = true;
    f = n + N(1);
  }
  r.set_matrix(with_handedness(perspective(c, aspect, n, f, conv.depth, false), conv.hand));
  return r;
}

double positive(case_rng& r, int emin, int emax) {
  double v = 0;
  while (v == 0) v = std::fabs(r.value(emin, emax));
  return v;
}

void generate(case_rng& r, input_class cls, const conventions&, double* x) {
  x[0] = positive(r, -2, 3);   // cot(fovy/2): fields of view from about 1° to 170°
  x[1] = positive(r, -1, 2);   // aspect
  x[2] = positive(r, -4, 0);   // near
  x[3] = x[2] + positive(r, 0, 6);
  if (cls == input_class::near_degenerate) {
    if (r.raw() & 1) {
      x[3] = x[2] * std::ldexp(1.0, static_cast<int>(r.integer(4, r.bits() - 1)));  // far ≫ near
    } else {
      const int k = static_cast<int>(r.integer(4, r.bits() - 1));
      x[3] = x[2] + std::ldexp(x[2], -k);  // far a relative 2^-k beyond near
    }
  } else if (cls == input_class::degenerate) {
    x[3] = x[2];
  }
  for (int i = 0; i < 4; ++i) x[i] = r.fit(x[i]);
  if (cls == input_class::range) {
    // n and f scaled so that 2 f n overflows, or underflows; A does not change, B scales.
    const int top = top_exponent(x + 2, 2);
    const int e = (r.raw() & 1) ? max_exponent(r) / 2 - top + static_cast<int>(r.integer(0, 2))
                                : min_normal_exponent(r) / 2 - top - 2 - static_cast<int>(r.integer(0, 2));
    if (!scale_exactly(r, x + 2, 2, e)) generate(r, cls, conventions{}, x);  // draw again
  }
}

// log2(|f − n| / (|f| + |n|)): the relative depth extent (−inf exactly when f = n).
double closeness(const double* x) {
  if (x[3] == x[2]) return -std::numeric_limits<double>::infinity();
  const long double extent = std::fabs(static_cast<long double>(x[3]) - x[2]);
  return static_cast<double>(std::log2(extent / (std::fabs(static_cast<long double>(x[2])) + std::fabs(static_cast<long double>(x[3])))));
}

std::string reproducer(const test_case& c, const conventions& conv) {
  const double* x = c.inputs.data();
  if (!(x[0] > 0 && x[1] > 0 && x[2] > 0 && x[3] > 0) || x[2] == x[3]) return exact_command(c, conv);
  return "shadowproof project perspective --cot-half-fovy " + hex_string(c.inputs[0]) + " --aspect " +
         hex_string(c.inputs[1]) + " --near " + hex_string(c.inputs[2]) + " --far " + hex_string(c.inputs[3]) +
         " --convention " + std::string(to_string(conv.depth)) + handedness_flag(conv);
}

operation_spec make() {
  operation_spec s{};
  s.op = operation::perspective;
  s.name = "perspective";
  s.summary = "camera[4] = cot(fovy/2), aspect, n, f -> symmetric perspective in the declared depth convention, 16 entries";
  s.signature = make_signature({{"camera", 4}}, 16, 4);
  s.generate = generate;
  s.closeness = closeness;
  SHADOWPROOF_EXACT_TEMPLATE(s, exact);
  s.stable_constant = 6;
  s.sentinel_outputs = matrix_sentinels;
  s.fast_f32 = fast_perspective_f32;
  s.fast_f64 = fast_perspective_f64;
  s.reproducer = reproducer;
  s.invalid = never_invalid;
  return s;
}

}  // namespace

const operation_spec& perspective_spec() {
  static const operation_spec s = make();
  return s;
}

}  // namespace shadowproof::detail
