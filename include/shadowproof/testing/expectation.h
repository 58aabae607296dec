#pragma once
/// "These numbers are the correctly rounded answer of this operation for these inputs": what a
/// matcher checks, free of any test framework (testing/catch2.h and testing/gtest.h wrap it).
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

#include "shadowproof/testing/failure_policy.h"
#include "shadowproof/testing/output_values.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof {

/// The outcome of matching outputs against an expectation.
struct match_result {
  bool matches = false;
  /// Empty when the outputs match. Otherwise every failing entry, named "(row,col)" for a
  /// matrix or "x"/"y"/"z" for a point, with what the routine gave, the exact value, its
  /// correct rounding and the ulps between them; then the shadowproof command that prints the
  /// exact answer for these very inputs.
  std::string explanation;
};

/// The exact answer of `op` for one set of float (or double) inputs, correctly rounded to the
/// inputs' format, and how close outputs must be to it. Built by the *_of functions below and
/// refined by chaining: shadow_matrix_of(P, L).within_ulps(2).up_to_scale().
/// Conventions (conventions.h) default to the library's: row-major, column vectors, a
/// directional light pointing towards the light, OpenGL depth; each is mapped exactly, so a
/// declared convention is never counted as an error and never hides one.
class expectation {
 public:
  /// `inputs`: signature(op).input_count numbers, each finite and exactly a value of `type`,
  /// naming an instance of op (a plane has a non-zero normal, a light is not all zeros).
  /// Throws error "testing.input" otherwise, naming the input.
  expectation(operation op, scalar_type type, std::vector<double> inputs);

  /// Each output may be up to n ulps from the correctly rounded exact value (default 0).
  expectation within_ulps(std::uint64_t n) const;
  /// Fails on what `policy` says instead (e.g. failure_policy::parse("ulps>4,nonfinite")).
  expectation failing_on(const failure_policy& policy) const;
  /// Any non-zero multiple of the exact matrix is right (a homogeneous result): graded against
  /// λ·exact with λ = got[k] / exact[k], k the entry of largest exact magnitude.
  expectation up_to_scale() const;
  /// The matrix is stored column by column (OpenGL, GLM, Eigen's default).
  expectation column_major() const;
  /// The matrix multiplies row vectors, v M (DirectX): the transpose of the canonical one.
  expectation row_vectors() const;
  /// A directional light's (x, y, z) is the direction the light travels, not towards it.
  expectation light_along_rays() const;
  /// Projections: the NDC depth range of near and far.
  expectation depth(depth_convention c) const;
  /// All conventions at once.
  expectation with_conventions(const conventions& c) const;

  /// Grades `got` (signature(op).output_count numbers in the same format as the inputs).
  /// Outputs of the wrong count or format do not match, with an explanation saying so.
  match_result match(const output_values& got) const;
  /// "is the correctly rounded shadow-matrix of plane (0, 1, 0, 0), light (2, 5, 1, 1) in f32,
  /// within 2 ulps, up to scale": the inputs as exact rationals.
  std::string describe() const;

  operation op() const { return case_.op; }
  const test_case& as_case() const { return case_; }
  const conventions& conv() const { return conv_; }
  const failure_policy& policy() const { return policy_; }

 private:
  test_case case_;
  conventions conv_;
  failure_policy policy_;
};

namespace detail {
// Throws error "testing.input" when a group has `given` numbers instead of `expected`, or a
// format other than the groups before it; records the format of the first group.
void check_group(scalar_type& type, bool& typed, scalar_type group_type, const char* name, std::size_t expected,
                 std::size_t given);

// Appends the numbers of one input group (anything std::data accepts) to `inputs`, recording
// their format in `type`; throws error "testing.input" for a wrong count or mixed formats.
template <class G>
void append_group(std::vector<double>& inputs, scalar_type& type, bool& typed, const G& group, const char* name,
                  std::size_t expected) {
  static_assert(is_float_range<G>::value, "an input group is an array or container of float or double");
  const bool single = std::is_same_v<element_of<G>, float>;
  check_group(type, typed, single ? scalar_type::f32 : scalar_type::f64, name, expected, std::size(group));
  for (const auto& x : group) inputs.push_back(static_cast<double>(x));
}
}  // namespace detail

// ===========================================================================================
// The expectations, one per graded operation (operations.def). Each input group is a C array,
// std::array, std::vector or span of float or double (all groups in one format).

/// The shadow matrix M = (P·L) I − L Pᵀ of the plane P[4] and the light L[4], 16 entries.
template <class P, class L>
expectation shadow_matrix_of(const P& plane, const L& light) {
  std::vector<double> in;
  scalar_type t = scalar_type::f32;
  bool typed = false;
  detail::append_group(in, t, typed, plane, "plane", 4);
  detail::append_group(in, t, typed, light, "light", 4);
  return expectation(operation::shadow_matrix, t, std::move(in));
}

/// The affine shadow of the point V[3] from the light L[4] on the plane P[4], 3 entries.
template <class P, class L, class V>
expectation shadow_point_of(const P& plane, const L& light, const V& point) {
  std::vector<double> in;
  scalar_type t = scalar_type::f32;
  bool typed = false;
  detail::append_group(in, t, typed, plane, "plane", 4);
  detail::append_group(in, t, typed, light, "light", 4);
  detail::append_group(in, t, typed, point, "point", 3);
  return expectation(operation::shadow_point, t, std::move(in));
}

/// The mirror matrix about the plane P[4], 16 entries.
template <class P>
expectation reflection_matrix_of(const P& plane) {
  std::vector<double> in;
  scalar_type t = scalar_type::f32;
  bool typed = false;
  detail::append_group(in, t, typed, plane, "plane", 4);
  return expectation(operation::reflection_matrix, t, std::move(in));
}

/// The orthographic projection of the box l, r, b, t, n, f (6 numbers), 16 entries.
template <class B>
expectation ortho_matrix_of(const B& box) {
  std::vector<double> in;
  scalar_type t = scalar_type::f32;
  bool typed = false;
  detail::append_group(in, t, typed, box, "box", 6);
  return expectation(operation::ortho, t, std::move(in));
}

/// The perspective frustum of the box l, r, b, t, n, f (6 numbers), 16 entries.
template <class B>
expectation frustum_matrix_of(const B& box) {
  std::vector<double> in;
  scalar_type t = scalar_type::f32;
  bool typed = false;
  detail::append_group(in, t, typed, box, "box", 6);
  return expectation(operation::frustum, t, std::move(in));
}

/// The perspective projection of camera = cot(fovy/2), aspect, n, f, 16 entries.
template <class C>
expectation perspective_matrix_of(const C& camera) {
  std::vector<double> in;
  scalar_type t = scalar_type::f32;
  bool typed = false;
  detail::append_group(in, t, typed, camera, "camera", 4);
  return expectation(operation::perspective, t, std::move(in));
}

/// The normal matrix (A⁻¹)ᵀ of the 3x3 matrix A given row by row (9 numbers), 9 entries.
template <class A>
expectation normal_matrix_of(const A& matrix) {
  std::vector<double> in;
  scalar_type t = scalar_type::f32;
  bool typed = false;
  detail::append_group(in, t, typed, matrix, "matrix", 9);
  return expectation(operation::normal_matrix, t, std::move(in));
}

/// Any operation, its inputs flattened in signature order.
template <class I>
expectation result_of(operation op, const I& inputs) {
  std::vector<double> in;
  scalar_type t = scalar_type::f32;
  bool typed = false;
  detail::append_group(in, t, typed, inputs, "inputs", signature(op).input_count);
  return expectation(op, t, std::move(in));
}

}  // namespace shadowproof
