// Grading on several threads (shadowproof/verify/parallel.h): the grades and counters are the
// same for any number of threads, and the same as one thread's grade_case.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "shadowproof/impls/builtin.h"
#include "shadowproof/verify/batch.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/parallel.h"
#include "shadowproof/verify/report.h"

using namespace shadowproof;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void require_identical(const case_grade& a, const case_grade& b) {
  REQUIRE(a.id == b.id);
  REQUIRE(a.outputs.size() == b.outputs.size());
  for (std::size_t j = 0; j < a.outputs.size(); ++j) {
    const output_grade &x = a.outputs[j], &y = b.outputs[j];
    REQUIRE(x.exact_defined == y.exact_defined);
    REQUIRE(same_bits(x.reference, y.reference));
    REQUIRE(same_bits(x.got, y.got));
    REQUIRE(x.ulps == y.ulps);
    REQUIRE(same_bits(x.bits, y.bits));
    REQUIRE(same_bits(x.relative, y.relative));
    REQUIRE(x.nonfinite == y.nonfinite);
    REQUIRE(x.garbage == y.garbage);
  }
  REQUIRE(a.max_ulps == b.max_ulps);
  REQUIRE(a.worst_output == b.worst_output);
  REQUIRE(a.exact_class == b.exact_class);
  REQUIRE(a.got_class == b.got_class);
  REQUIRE(a.misclassified == b.misclassified);
  REQUIRE(a.plane_value.has_value() == b.plane_value.has_value());
  if (a.plane_value) REQUIRE(same_bits(*a.plane_value, *b.plane_value));
  REQUIRE(a.scale_pivot == b.scale_pivot);
}

// A few implementations of different operations and conventions (homogeneous, clamped,
// column-major), enough cases for many slices.
std::vector<const implementation*> sample_implementations() {
  std::vector<const implementation*> sample;
  for (const char* name : {"seed000-general-f32", "seed001-clamped-f32", "eigen-intersection-f64", "reflect-divide-f64",
                           "glm-frustum-f32", "normal-inverse-transpose-f64", "perspective-closed-form-f32"})
    for (const implementation& impl : builtin_implementations())
      if (impl.name == name) sample.push_back(&impl);
  return sample;
}

}  // namespace

TEST_CASE("run_and_grade gives the same grades and counters on any number of threads", "[parallel]") {
  const auto sample = sample_implementations();
  REQUIRE(sample.size() >= 4);
  for (const implementation* impl : sample) {
    const auto cases = generate_cases(impl->op, impl->type, 1500, 12, std::nullopt, impl->conv);
    oracle_counters one_thread;
    const std::vector<case_grade> expected = run_and_grade(*impl, cases, oracle_mode::filtered, &one_thread);
    for (unsigned jobs : {1u, 2u, 3u, 8u}) {
      INFO("implementation " << impl->name << ", " << jobs << " threads");
      oracle_counters counters;
      const std::vector<case_grade> grades = run_and_grade_in_parallel(*impl, cases, jobs, oracle_mode::filtered, &counters);
      REQUIRE(grades.size() == expected.size());
      for (std::size_t i = 0; i < grades.size(); ++i) require_identical(grades[i], expected[i]);
      CHECK(counters.decided_by_intervals == one_thread.decided_by_intervals);
      CHECK(counters.fell_back_to_rationals == one_thread.fell_back_to_rationals);
    }
  }
}

TEST_CASE("grade_in_parallel grades each case as grade_case does", "[parallel]") {
  const implementation* impl = sample_implementations().front();
  const auto cases = generate_cases(impl->op, impl->type, 700, 4, std::nullopt, impl->conv);
  std::vector<std::vector<double>> outputs(cases.size(), std::vector<double>(signature(impl->op).output_count));
  for (std::size_t i = 0; i < cases.size(); ++i) impl->run(cases[i].inputs.data(), outputs[i].data());
  for (oracle_mode mode : {oracle_mode::filtered, oracle_mode::naive}) {
    const std::vector<case_grade> grades = grade_in_parallel(cases, impl->conv, outputs, 3, mode);
    for (std::size_t i = 0; i < cases.size(); ++i) require_identical(grades[i], grade_case(cases[i], impl->conv, outputs[i].data(), mode));
  }
  CHECK_THROWS_AS(grade_in_parallel(cases, impl->conv, {}, 2), internal_error);
}

TEST_CASE("the batch grader gives the same columns on any number of threads", "[parallel][batch]") {
  for (const implementation* impl : sample_implementations()) {
    const auto cases = generate_cases(impl->op, impl->type, 9000, 21, std::nullopt, impl->conv);  // three slices and a bit
    case_batch expected_batch = make_batch(cases);
    batch_references expected_refs;
    batch_grades expected;
    oracle_counters one_thread;
    grade_batch_in_parallel(expected_batch, impl->conv, expected_refs, expected, 1, impl, &one_thread);
    for (unsigned jobs : {2u, 5u}) {
      INFO("implementation " << impl->name << ", " << jobs << " threads");
      case_batch batch = make_batch(cases);
      batch_references refs;
      batch_grades grades;
      oracle_counters counters;
      grade_batch_in_parallel(batch, impl->conv, refs, grades, jobs, impl, &counters);
      REQUIRE(std::memcmp(batch.outputs.data(), expected_batch.outputs.data(), batch.outputs.size() * sizeof(double)) == 0);
      REQUIRE(std::memcmp(refs.values.data(), expected_refs.values.data(), refs.values.size() * sizeof(double)) == 0);
      REQUIRE(refs.undefined == expected_refs.undefined);
      REQUIRE(refs.point_class == expected_refs.point_class);
      REQUIRE(refs.decided_by == expected_refs.decided_by);
      REQUIRE(grades.ulps == expected.ulps);
      REQUIRE(grades.flags == expected.flags);
      REQUIRE(grades.max_ulps == expected.max_ulps);
      REQUIRE(grades.worst_output == expected.worst_output);
      REQUIRE(grades.nonfinite == expected.nonfinite);
      REQUIRE(grades.garbage == expected.garbage);
      REQUIRE(grades.misclassified == expected.misclassified);
      REQUIRE(grades.got_class == expected.got_class);
      REQUIRE(std::memcmp(grades.plane_value.data(), expected.plane_value.data(), grades.plane_value.size() * sizeof(double)) == 0);
      CHECK(counters.decided_by_intervals == one_thread.decided_by_intervals);
      CHECK(counters.fell_back_to_rationals == one_thread.fell_back_to_rationals);
    }
  }
}
