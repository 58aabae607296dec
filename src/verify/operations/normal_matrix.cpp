// normal-matrix: matrix[9] (a 3x3 linear map A, row by row) -> the normal matrix (A⁻¹)ᵀ,
// 9 entries (row-major). Undefined when det A = 0 (no inverse exists).
// Classes: near-degenerate = nearly singular (third row = first + second, rounded, plus a
// relative 2^-k); degenerate = exactly singular (third row = 2 × first row).
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
    const int k = static_cast<int>(r.integer(4, r.bits() + 4));
    for (int j = 0; j < 3; ++j) m[6 + j] = r.fit(m[j] + m[3 + j] + std::ldexp(r.value(), -k));
  } else if (cls == input_class::degenerate) {
    for (int j = 0; j < 3; ++j) m[6 + j] = 2 * m[j];
  }
}

// log2(|det A| / (|row 0| |row 1| |row 2|)): 0 for orthogonal rows, −inf for singular A.
double closeness(const double* in) {
  auto l = [&](int i) { return static_cast<long double>(in[i]); };
  const long double det = l(0) * (l(4) * l(8) - l(5) * l(7)) - l(1) * (l(3) * l(8) - l(5) * l(6)) +
                          l(2) * (l(3) * l(7) - l(4) * l(6));
  if (det == 0) return -std::numeric_limits<double>::infinity();
  auto row = [&](int i) { return std::sqrt(l(3 * i) * l(3 * i) + l(3 * i + 1) * l(3 * i + 1) + l(3 * i + 2) * l(3 * i + 2)); };
  return static_cast<double>(std::log2(std::fabs(det) / (row(0) * row(1) * row(2))));
}

std::string reproducer(const test_case& c, const conventions&) {
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
  s.exact_rational = exact<rational>;
  s.exact_ival32 = exact<ival32>;
  s.exact_ival64 = exact<ival64>;
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
