#pragma once
// The operation table: everything the grader, the case generator, the command line and the
// fuzzer know about one graded operation. Each src/verify/operations/<op>.cpp fills one
// operation_spec; operation_table.cpp lists them in the order of operations.def. Code that
// needs to know an operation asks its spec, never switches on the enumerator.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "case_generation.h"
#include "exact_outputs.h"
#include "oracle_fast.h"
#include "sensitivity.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof::detail {

template <class N>
using exact_function = exact_outputs<N> (*)(const double* inputs, const conventions& conv);

/// Fills every instance of an operation's exact<N> template into `spec`: the values over
/// rationals and intervals, and the values with their partial derivatives (dual.h) that the
/// verdicts need. Every operation file ends its make() with it.
#define SHADOWPROOF_EXACT_TEMPLATE(spec, fn)                 \
  do {                                                       \
    (spec).exact_rational = fn<rational>;                    \
    (spec).exact_ival32 = fn<ival32>;                        \
    (spec).exact_ival64 = fn<ival64>;                        \
    (spec).derivatives_ival32 = fn<dual<ival32>>;            \
    (spec).derivatives_ival64 = fn<dual<ival64>>;            \
    (spec).derivatives_rational = fn<dual<rational>>;        \
  } while (false)

struct operation_spec {
  operation op;
  std::string_view name;     ///< command-line and case-file name, "shadow-matrix"
  std::string_view summary;  ///< one line: what it computes from what
  operation_signature signature;

  /// Fills signature.input_count inputs of class `cls`, exactly representable in r's type and
  /// within the declared input restrictions of `requirements`. near_degenerate: within a relative
  /// 2^-4 … 2^-(p−1) of the degeneracy (generate_cases redraws a case beyond that or exactly on
  /// it); degenerate: exactly on it; range: a regular configuration scaled by powers of two so
  /// that a straightforward evaluation over- or underflows (tests/test_verdicts.cpp checks it).
  void (*generate)(case_rng& r, input_class cls, const conventions& requirements, double* inputs);
  /// log2 of the relative distance to the degeneracy, −inf exactly when the inputs are exactly
  /// degenerate (decided exactly; the finite value is rounded, for plots and the case files).
  double (*closeness)(const double* inputs);

  /// The canonical exact outputs, once per number type of the oracle (the same template).
  exact_function<rational> exact_rational;
  exact_function<ival32> exact_ival32;
  exact_function<ival64> exact_ival64;
  /// The same template over dual numbers: the outputs with ∂f_i/∂x_j (SHADOWPROOF_EXACT_TEMPLATE
  /// fills all six).
  exact_function<dual<ival32>> derivatives_ival32 = nullptr;
  exact_function<dual<ival64>> derivatives_ival64 = nullptr;
  exact_function<dual<rational>> derivatives_rational = nullptr;
  /// c of the `stable` verdict: an output whose mixed backward error is at most c·u is stable
  /// (docs/verdicts.md). Twice the number of roundings on the longest path of a straightforward
  /// evaluation of an output (a product of two computed factors adds both their errors), so that
  /// such evaluations come out stable.
  int stable_constant = 0;
  /// A dedicated kernel bounding D_i = Σ_j |∂f_i/∂x_j| |x_j| in closed form (sensitivity.h), which
  /// spares most verdicts the generic derivatives; null when the operation has none.
  sensitivity_kernel sensitivity = nullptr;
  /// The outputs of a documented sentinel (zero, identity) in canonical order, or false when
  /// the sentinel means nothing for this operation.
  bool (*sentinel_outputs)(sentinel_kind kind, double* outputs) = nullptr;
  /// Dedicated error-free kernels (oracle_fast.h) for f32 / f64 cases: the canonical outputs
  /// correctly rounded, or false when they cannot decide. Null when the operation has none.
  bool (*fast_f32)(const double* inputs, const conventions& conv, fast_reference& out) = nullptr;
  bool (*fast_f64)(const double* inputs, const conventions& conv, fast_reference& out) = nullptr;
  /// The kernels compute the matrix of either handedness themselves (the camera builders with
  /// irrational values); otherwise a left-handed case goes to the generic oracle.
  bool fast_kernels_read_handedness = false;
  /// Grades what the outputs mean beyond their values (shadow-point: the class of the float
  /// image); g.exact_class is set already, `exact_defined` says whether the exact outputs exist.
  /// Null when there is nothing more to grade.
  void (*grade_meaning)(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                        bool exact_defined, oracle_mode mode) = nullptr;

  /// The shadowproof command that prints the exact answer for these very inputs.
  std::string (*reproducer)(const test_case& c, const conventions& conv);
  /// Why the inputs name no instance of the problem at all (a zero plane normal, an all-zero
  /// light), or empty when they do. Such inputs are rejected by the case-file reader.
  std::string (*invalid)(const double* inputs);

  /// Fuzzing from a shadow configuration (plane, light, point; fuzz/generate.h): fills the
  /// operation's inputs, or null when the operation is not fuzzed.
  void (*from_configuration)(const double* plane, const double* light, const double* point,
                             double* inputs) = nullptr;
  /// Facts the fuzzer checks without an oracle (operation.h).
  operation_symmetries symmetries;
};

/// The spec of op.
const operation_spec& spec_of(operation op);

/// Canonical row-major index of output j of an implementation whose outputs are a k x k matrix
/// (k = 0: not a matrix, j itself) under its storage conventions: column-major storage and row
/// vectors each transpose, both together cancel.
inline std::size_t canonical_index(std::size_t j, std::size_t k, const conventions& conv) {
  if (k == 0) return j;
  const bool transposed = (conv.storage == storage_order::column_major) != (conv.vectors == vector_side::row);
  if (!transposed) return j;
  if (k == 4) return ((j & 3) << 2) | (j >> 2);  // the common case without a division
  return (j % k) * k + j / k;
}

/// A homogeneous result, and a routine that normalises the plane first when the outputs are
/// not invariant under scaling P (normalising multiplies them by the irrational |n|^-degree),
/// is graded up to scale.
inline bool graded_up_to_scale(const operation_spec& spec, const conventions& conv) {
  return spec.signature.matrix_size &&
         (conv.homogeneous || (conv.normalises_plane && spec.symmetries.plane_degree > 0));
}

// One function per operations.def entry, defined in operations/<code>.cpp.
#define SHADOWPROOF_OPERATION(code) const operation_spec& code##_spec();
#include "shadowproof/verify/operations.def"
#undef SHADOWPROOF_OPERATION

/// `shadowproof exact --op … --type … --inputs …` with the conventions that change the exact
/// values: the reproducer of any case, and the only one for inputs the geometric commands reject.
std::string exact_command(const test_case& c, const conventions& conv);

/// Inputs [first, first + n) as comma-separated hex floats (the reproducer's argument syntax).
std::string hex_list(const test_case& c, std::size_t first, std::size_t n);

/// The signature with its running input count, from named groups.
operation_signature make_signature(std::vector<input_group> inputs, std::size_t output_count,
                                   std::size_t matrix_size);

/// log2(|a·b| / (|a| |b|)) for a plane a and a homogeneous b (nb = 4) or a finite point b
/// (nb = 3, w = 1); −inf when a·b = 0. Long double, for plots.
double log2_relative_dot(const double* a, const double* b, std::size_t nb);

/// The `invalid` checks shared by several operations: a plane at inputs[0..3] with a zero normal
/// (and, for the second, a light at inputs[4..7] that is all zeros).
std::string invalid_plane(const double* inputs);
std::string invalid_plane_and_light(const double* inputs);
/// No inputs are invalid.
std::string never_invalid(const double* inputs);

/// Sentinels of a k x k matrix (zero matrix, identity), of a point (zero only).
bool matrix_sentinels(sentinel_kind kind, double* outputs);
bool matrix3_sentinels(sentinel_kind kind, double* outputs);
bool point_sentinels(sentinel_kind kind, double* outputs);

/// Whether the n outputs `got` (in the implementation's layout) equal the sentinel the
/// conventions declare for this operation (zero and identity read the same in every order).
bool is_sentinel(const operation_spec& spec, const conventions& conv, const double* got, std::size_t n);

/// Box inputs (l, r, b, t, n, f): the flattest relative extent |hi − lo| / (|lo| + |hi|) in log2.
double box_closeness(const double* x);

}  // namespace shadowproof::detail
