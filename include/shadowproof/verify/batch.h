#pragma once
/// Grading many cases of one operation at once. Inputs, outputs, references and grades are
/// stored as structure of arrays (one contiguous column per number, e.g. every case's input 3),
/// written into storage allocated once per batch, never per case. The exact references come
/// from the same oracle as grade_case (dedicated kernels, then intervals, then rationals), their
/// filter stage run over whole columns (vectorised, with AVX2 where the processor has it), and
/// every grade equals grade_case's for the same case.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof {

/// `count` cases of one operation and type, column by column: input k of case i is
/// inputs[k * count + i], output j of case i is outputs[j * count + i] (the implementation's
/// outputs in its own layout, as implementation_function writes them).
struct case_batch {
  operation op = operation::shadow_matrix;
  scalar_type type = scalar_type::f32;
  std::size_t count = 0;
  std::vector<double> inputs;
  std::vector<double> outputs;
  std::vector<std::uint64_t> ids;   ///< the cases' ids
  std::vector<input_class> classes;  ///< the cases' classes

  /// Column k of the inputs, column j of the outputs.
  const double* input_column(std::size_t k) const { return inputs.data() + k * count; }
  const double* output_column(std::size_t j) const { return outputs.data() + j * count; }
  double* output_column(std::size_t j) { return outputs.data() + j * count; }
};

/// The cases as columns, outputs zero. Precondition: every case has the operation and type of
/// the first (throws shadowproof::internal_error otherwise). An empty vector gives an empty
/// batch of shadow-matrix f32.
case_batch make_batch(const std::vector<test_case>& cases);

/// Case i of the batch as a test_case (its inputs copied back out of the columns).
test_case case_at(const case_batch& batch, std::size_t i);

/// Runs `impl` on every case of the batch and writes its outputs into batch.outputs, exactly
/// as run_and_grade does (outputs zeroed before each call). Precondition: impl.op and
/// impl.type are the batch's.
void run_implementation(const implementation& impl, case_batch& batch);

/// Which batch code to use (filters and column grader): the fastest the processor supports, or
/// a given one (for tests and benchmarks; `avx2` on a processor without AVX2 and FMA falls
/// back to `generic`).
enum class batch_path { automatic, generic, avx2 };

/// True when this build has the AVX2 filters and the processor running it has AVX2 and FMA.
bool avx2_batch_available();

/// The exact outputs of every case, correctly rounded to the batch's type (+0 for an exact 0),
/// in the layout `conv` declares (storage order and vector side permute matrix entries; light
/// sign, clamping, depth convention and symmetric volumes change the values). Grading up to
/// scale (homogeneous, normalises_plane) is not applied: these are the canonical-scale values.
struct batch_references {
  std::size_t count = 0;
  std::vector<double> values;               ///< output j of case i at values[j * count + i]; 0 where undefined
  std::vector<std::uint32_t> undefined;     ///< per case: bit j set when output j does not exist
  std::vector<std::int8_t> point_class;     ///< shadow-point: the exact class of V (point_class); −1 otherwise
  /// Per case, what decided it: 0 the batch filter, 1 a kernel for one case (exact
  /// expansions or a degenerate class), 2 intervals, 3 rationals.
  std::vector<std::uint8_t> decided_by;
};

/// Computes the references of every case. Counters, when given, are incremented as
/// grade_case's filtered oracle would: decided_by_intervals for all but the cases rationals
/// decided.
void compute_references(const case_batch& batch, const conventions& conv, batch_references& out,
                        oracle_counters* counters = nullptr, batch_path path = batch_path::automatic);

/// The grades of every case, field for field those of grade_case (filtered and naive oracles
/// grade alike): per output the ulps and flags of output_grade, per case the summary of
/// case_grade. Outputs of a case graded up to scale use that scale, as grade_case does.
struct batch_grades {
  std::size_t count = 0, outputs_per_case = 0;
  /// Output j of case i at [j * count + i]: output_grade::ulps (0 unless counted) and flags.
  std::vector<std::uint64_t> ulps;
  std::vector<std::uint8_t> flags;  ///< bits: 1 counted, 2 nonfinite, 4 garbage, 8 exact value undefined
  std::vector<std::uint64_t> max_ulps;     ///< per case, as case_grade
  std::vector<std::uint8_t> worst_output;  ///< per case
  std::vector<std::uint8_t> nonfinite, garbage, misclassified;  ///< per case (counts, and 0/1)
  std::vector<std::int8_t> got_class;      ///< shadow-point: the float image's image_class; −1 otherwise
  std::vector<double> plane_value;         ///< shadow-point: P·(image, 1) rounded to double; NaN where none

  static constexpr std::uint8_t counted = 1, nonfinite_output = 2, garbage_output = 4, exact_undefined = 8;
};

/// Grades the batch's outputs against `refs` (from compute_references with the same
/// conventions), column by column (eight floats or four doubles at a time with AVX2, per
/// `path`). Cases graded up to scale, and the meaning of shadow-point images (classes and
/// plane values), go through grade_case's own code one case at a time.
void grade_batch(const case_batch& batch, const conventions& conv, const batch_references& refs, batch_grades& out,
                 batch_path path = batch_path::automatic);

}  // namespace shadowproof
