// reflection-matrix: plane P[4] -> the mirror matrix about P,
// [I − 2nnᵀ/(n·n), −2d n/(n·n); 0 0 0 1], 16 entries (row-major, column vectors).
// Classes: near-degenerate = a mirror far from the origin compared with its normal
// (|n| / |P| within 2^-4 … 2^-(p−1): P tends to the plane at infinity, the translation column
// grows like |d| / |n|); degenerate = no valid plane is exactly on that degeneracy (n = 0 names
// no plane), so this class holds the exactly structured mirrors instead: axis-aligned and
// diagonal normals of powers of two, whose entries are exactly 0, ±1 and −2d/n_i; range = a
// normal whose |n|² over- or underflows the type (the mirror itself is an ordinary plane; only
// formulas that square n fail there).
// Stable: n·n takes three products and two sums (three roundings on its longest path), then
// 2 n_i n_j (one), the quotient (one) and 1 − q (one): six; normalising first with a square root
// adds one: seven roundings, c = 2 × 7 = 14.
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
    p[3] = std::ldexp(p[3] == 0 ? 1.0 : p[3], static_cast<int>(r.integer(4, r.bits() - 1)));
  } else if (cls == input_class::degenerate) {
    // n = ±2^k e_i (an axis) or ±2^k (e_i ± e_j) (a diagonal), any d: every entry is exact.
    const double size = std::ldexp(1.0, static_cast<int>(r.integer(-3, 3)));
    const int i = static_cast<int>(r.integer(0, 2));
    p[0] = p[1] = p[2] = 0;
    p[i] = (r.raw() & 1) ? size : -size;
    if (r.raw() & 1) p[(i + 1) % 3] = (r.raw() & 1) ? size : -size;
  } else if (cls == input_class::range) {
    // |n|² under- or overflows the type while the mirror itself is an ordinary plane.
    const int e = r.bits() == 24 ? 70 : 540;
    const int s = (r.raw() & 1) ? e : -e;
    for (int i = 0; i < 4; ++i) p[i] = std::ldexp(p[i], s);
  }
}

// log2(|n| / |P|): never −inf, a valid plane has n ≠ 0.
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
  SHADOWPROOF_EXACT_TEMPLATE(s, exact);
  s.sensitivity = reflection_matrix_sensitivity;
  s.stable_constant = 14;
  s.sentinel_outputs = matrix_sentinels;
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
