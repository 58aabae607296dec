// reflection-matrix: plane P[4] -> the mirror matrix about P,
// [I − 2nnᵀ/(n·n), −2d n/(n·n); 0 0 0 1], 16 entries (row-major, column vectors).
// Classes: near-degenerate = a mirror far from the origin compared with its normal
// (|d| ≫ |n|); degenerate = a normal whose |n|² over- or underflows the type (the mirror itself
// is an ordinary plane; only formulas that square n fail there).
#include "shadowproof/constructions/reflect.h"

#include <cmath>

#include "../operation_table.h"

namespace shadowproof::detail {
namespace {

template <class N>
exact_outputs<N> exact(const double* in, const conventions&) {
  exact_outputs<N> r;
  r.set_matrix(reflection_matrix(plane_from<N>(in)));
  return r;
}

void generate(case_rng& r, input_class cls, const conventions&, double* p) {
  random_plane(r, p);
  if (cls == input_class::near_degenerate) {
    // The mirror far from the origin compared with its normal: the translation column is
    // a large multiple of n and the linear block must still be exact to within an ulp.
    p[3] = std::ldexp(p[3] == 0 ? 1.0 : p[3], static_cast<int>(r.integer(8, 40)));
  } else if (cls == input_class::degenerate) {
    // |n|² under- or overflows the type while the mirror itself is an ordinary plane.
    const int e = r.bits() == 24 ? 70 : 540;
    const int s = (r.raw() & 1) ? e : -e;
    for (int i = 0; i < 4; ++i) p[i] = std::ldexp(p[i], s);
  }
}

// log2(|n| / |P|).
double closeness(const double* in) {
  long double nn = 0, pp = 0;
  for (int i = 0; i < 4; ++i) {
    const long double sq = static_cast<long double>(in[i]) * in[i];
    if (i < 3) nn += sq;
    pp += sq;
  }
  return static_cast<double>(std::log2(std::sqrt(nn) / std::sqrt(pp)));
}

std::string reproducer(const test_case& c, const conventions&) {
  return "shadowproof reflect --plane " + hex_list(c, 0, 4);
}

void from_configuration(const double* plane, const double*, const double*, double* in) {
  std::copy(plane, plane + 4, in);
}

operation_spec make() {
  operation_spec s{};
  s.op = operation::reflection_matrix;
  s.name = "reflection-matrix";
  s.summary = "plane[4] -> mirror matrix about P, 16 entries";
  s.signature = make_signature({{"plane", 4}}, 16, 4);
  s.generate = generate;
  s.closeness = closeness;
  s.exact_rational = exact<rational>;
  s.exact_ival32 = exact<ival32>;
  s.exact_ival64 = exact<ival64>;
  s.fast_f32 = fast_reflection_matrix_f32;
  s.fast_f64 = fast_reflection_matrix_f64;
  s.reproducer = reproducer;
  s.invalid = invalid_plane;
  s.from_configuration = from_configuration;
  s.symmetries.plane_degree = 0;  // the mirror does not depend on the scale of P
  s.symmetries.swap_xy = true;
  return s;
}

}  // namespace

const operation_spec& reflection_matrix_spec() {
  static const operation_spec s = make();
  return s;
}

}  // namespace shadowproof::detail
