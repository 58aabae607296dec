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
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof::detail {

template <class N>
using exact_function = exact_outputs<N> (*)(const double* inputs, const conventions& conv);

struct operation_spec {
  operation op;
  std::string_view name;     ///< command-line and case-file name, "shadow-matrix"
  std::string_view summary;  ///< one line: what it computes from what
  operation_signature signature;

  /// Fills signature.input_count inputs of class `cls`, exactly representable in r's type and
  /// within the declared input restrictions of `requirements`.
  void (*generate)(case_rng& r, input_class cls, const conventions& requirements, double* inputs);
  /// log2 of the relative distance to the degeneracy (−inf when exactly degenerate); a plot
  /// value computed in long double, never graded.
  double (*closeness)(const double* inputs);

  /// The canonical exact outputs, once per number type of the oracle (the same template).
  exact_function<rational> exact_rational;
  exact_function<ival32> exact_ival32;
  exact_function<ival64> exact_ival64;
  /// Dedicated error-free kernels (oracle_fast.h) for f32 / f64 cases: the canonical outputs
  /// correctly rounded, or false when they cannot decide. Null when the operation has none.
  bool (*fast_f32)(const double* inputs, const conventions& conv, fast_reference& out) = nullptr;
  bool (*fast_f64)(const double* inputs, const conventions& conv, fast_reference& out) = nullptr;
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

// One function per operations.def entry, defined in operations/<code>.cpp.
#define SHADOWPROOF_OPERATION(code) const operation_spec& code##_spec();
#include "shadowproof/verify/operations.def"
#undef SHADOWPROOF_OPERATION

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

/// Box inputs (l, r, b, t, n, f): the flattest relative extent |hi − lo| / (|lo| + |hi|) in log2.
double box_closeness(const double* x);

}  // namespace shadowproof::detail
