#pragma once
/// GoogleTest matchers for float routines (link shadowproof::testing and GTest::gmock):
///
///   EXPECT_THAT(M, shadowproof::gtest::rounds_to(shadowproof::shadow_matrix_of(P, L).within_ulps(2)));
///   EXPECT_TRUE(shadowproof::gtest::passes(shadowproof::check(shadowproof::operation::shadow_matrix, f, {1000, 7})));
///
/// On failure, GoogleTest prints the expectation and every failing entry named by (row, col)
/// with the exact value, its correct rounding, the ulps and the shadowproof command that prints
/// the exact answer for those very inputs (expectation.h, check.h).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ostream>
#include <utility>

#include "shadowproof/testing/check.h"
#include "shadowproof/testing/expectation.h"

namespace shadowproof::gtest {

/// A GoogleTest matcher (EXPECT_THAT, ASSERT_THAT) for outputs meeting the expectation: a C
/// array, std::array, std::vector or span of float or double, or output_values.
class rounds_to_matcher {
 public:
  using is_gtest_matcher = void;
  explicit rounds_to_matcher(expectation e) : expected_(std::move(e)) {}

  template <class Outputs>
  bool MatchAndExplain(const Outputs& got, std::ostream* why) const {
    const match_result r = expected_.match(output_values(got));
    if (!r.matches && why) *why << "\n" << r.explanation;
    return r.matches;
  }
  void DescribeTo(std::ostream* out) const { *out << expected_.describe(); }
  void DescribeNegationTo(std::ostream* out) const { *out << "is not: " << expected_.describe(); }

 private:
  expectation expected_;
};

/// EXPECT_THAT(outputs, rounds_to(shadow_matrix_of(P, L).within_ulps(2).up_to_scale())).
inline rounds_to_matcher rounds_to(expectation e) { return rounds_to_matcher(std::move(e)); }

/// EXPECT_TRUE(passes(check(...))): success with the case count, or failure with the report.
inline ::testing::AssertionResult passes(const check_result& r) {
  if (r) return ::testing::AssertionSuccess() << r;
  return ::testing::AssertionFailure() << "\n" << r.report;
}

}  // namespace shadowproof::gtest
