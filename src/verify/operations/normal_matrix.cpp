// normal-matrix: matrix[9] (a 3x3 linear map A, row by row) -> the normal matrix (A⁻¹)ᵀ,
// 9 entries (row-major). Undefined when det A = 0 (no inverse exists).
// Classes: near-degenerate = nearly singular (third row = first + second, rounded, plus a
// relative 2^-k, k = 4 … p−1, never exactly singular); degenerate = exactly singular (third row =
// 2 × first row); range = A scaled so that det A (a product of three entries) over- or underflows.
// Stable: a cofactor takes two roundings, det A = Σ a_0j C_0j three more, the quotient C_ij/det A
// one, and 1/det A then a product one more: seven, c = 2 × 7 = 14.
#include "shadowproof/constructions/normal_matrix.h"

#include <cmath>
#include <limits>

#include "../operation_table.h"
#include "shadowproof/core/error.h"

namespace shadowproof::detail {
namespace {

template <class N>
exact_outputs<N> exact(const double* in, const conventions&) {
  exact_outputs<N> r;
  mat4<N> A = identity4<N>();
  for (std::size_t i = 0; i < 9; ++i) A(i / 3, i % 3) = from_double<N>(in[i]);
  try {
    const mat4<N> G = normal_matrix3(A);
    for (std::size_t i = 0; i < 9; ++i) r.values.push_back(G(i / 3, i % 3));
  } catch (const error&) {  // det A = 0: no inverse, no normal matrix
    r.set_undefined(9);
  }
  return r;
}

void generate(case_rng& r, input_class cls, const conventions&, double* m) {
  for (int i = 0; i < 9; ++i) m[i] = r.value();
  if (cls == input_class::near_degenerate) {
    const int k = static_cast<int>(r.integer(4, r.bits() - 1));
    for (int j = 0; j < 3; ++j) m[6 + j] = r.fit(m[j] + m[3 + j] + std::ldexp(r.value(), -k));
  } else if (cls == input_class::degenerate) {
    for (int j = 0; j < 3; ++j) m[6 + j] = 2 * m[j];
  } else if (cls == input_class::range) {
    // det A, a sum of products of three entries, over- or underflows; (A⁻¹)ᵀ scales by 2^-e.
    const int top = top_exponent(m, 9);
    const int e = (r.raw() & 1) ? max_exponent(r) / 3 - top + 1 + static_cast<int>(r.integer(0, 2))
                                : min_normal_exponent(r) / 3 - top - 2 - static_cast<int>(r.integer(0, 2));
    if (!scale_exactly(r, m, 9, e)) generate(r, cls, conventions{}, m);  // draw again
  }
}

// det A, exactly.
rational exact_determinant(const double* in) {
  auto q = [&](int i) { return exact_value(in[i]); };
  return rational(q(0) * (q(4) * q(8) - q(5) * q(7)) - q(1) * (q(3) * q(8) - q(5) * q(6)) +
                  q(2) * (q(3) * q(7) - q(4) * q(6)));
}

// log2(|det A| / (|row 0| |row 1| |row 2|)): 0 for orthogonal rows, −inf exactly for singular A.
double closeness(const double* in) {
  auto l = [&](int i) { return static_cast<long double>(in[i]); };
  long double det = l(0) * (l(4) * l(8) - l(5) * l(7)) - l(1) * (l(3) * l(8) - l(5) * l(6)) +
                    l(2) * (l(3) * l(7) - l(4) * l(6));
  auto row = [&](int i) { return std::sqrt(l(3 * i) * l(3 * i) + l(3 * i + 1) * l(3 * i + 1) + l(3 * i + 2) * l(3 * i + 2)); };
  const long double rows = row(0) * row(1) * row(2);
  if (rows == 0) return -std::numeric_limits<double>::infinity();
  if (!(std::fabs(det) >= 0x1p-40L * rows)) {  // near 0 (or out of long double's range): exactly
    const rational exact = exact_determinant(in);
    if (sgn(exact) == 0) return -std::numeric_limits<double>::infinity();
    det = static_cast<long double>(to_nearest_double(exact));
  }
  return static_cast<double>(std::log2(std::fabs(det) / rows));
}

std::string reproducer(const test_case& c, const conventions& conv) {
  if (sgn(exact_determinant(c.inputs.data())) == 0) return exact_command(c, conv);  // normal-matrix rejects it
  std::string s = "shadowproof normal-matrix --matrix ";
  for (std::size_t i = 0; i < 3; ++i) s += hex_list(c, 3 * i, 3) + ",0,";
  return s + "0,0,0,1";
}

operation_spec make() {
  operation_spec s{};
  s.op = operation::normal_matrix;
  s.name = "normal-matrix";
  s.summary = "matrix[9] (3x3, row by row) -> (A⁻¹)ᵀ, 9 entries; undefined if det A = 0";
  s.signature = make_signature({{"matrix", 9}}, 9, 3);
  s.generate = generate;
  s.closeness = closeness;
  SHADOWPROOF_EXACT_TEMPLATE(s, exact);
  s.sensitivity = normal_matrix_sensitivity;
  s.stable_constant = 14;
  s.sentinel_outputs = matrix3_sentinels;
  s.fast_f32 = fast_normal_matrix_f32;
  s.fast_f64 = fast_normal_matrix_f64;
  s.reproducer = reproducer;
  s.invalid = never_invalid;
  return s;
}

}  // namespace

const operation_spec& normal_matrix_spec() {
  static const operation_spec s = make();
  return s;
}

}  // namespace shadowproof::detail
