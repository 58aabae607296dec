#pragma once
/// Catch2 matchers for float routines (link shadowproof::testing and your Catch2):
///
///   CHECK_THAT(M, shadowproof::catch2::rounds_to(shadowproof::shadow_matrix_of(P, L).within_ulps(2)));
///   CHECK(shadowproof::check(shadowproof::operation::shadow_matrix, my_shadow_matrix, {1000, 7}));
///
/// On failure, Catch2 prints the outputs, the expectation, and every failing entry named by
/// (row, col) with the exact value, its correct rounding, the ulps and the shadowproof command
/// that prints the exact answer for those very inputs (expectation.h, check.h).
/// Catch2 v2 (catch2/catch.hpp) and v3 (catch2/matchers/catch_matchers.hpp) have the same
/// matcher interface; v3 is used when its headers are found, unless SHADOWPROOF_CATCH2_V2 is
/// defined.
#if !defined(SHADOWPROOF_CATCH2_V2) && __has_include(<catch2/matchers/catch_matchers.hpp>)
#include <catch2/catch_tostring.hpp>
#include <catch2/matchers/catch_matchers.hpp>
#define SHADOWPROOF_CATCH2_MATCHER_BASE ::Catch::Matchers::MatcherBase
#else
#include <catch2/catch.hpp>
#define SHADOWPROOF_CATCH2_MATCHER_BASE ::Catch::MatcherBase
#endif

#include <string>
#include <utility>

#include "shadowproof/testing/check.h"
#include "shadowproof/testing/expectation.h"

namespace shadowproof::catch2 {

/// Matches outputs (a C array, std::array, std::vector or span of float or double, or
/// output_values) that meet the expectation. Its description, printed when the check fails,
/// is the expectation followed by the explanation of the failure.
class rounds_to_matcher final : public SHADOWPROOF_CATCH2_MATCHER_BASE<output_values> {
 public:
  explicit rounds_to_matcher(expectation e) : expected_(std::move(e)) {}

  bool match(const output_values& got) const override {
    // Catch2 describes a matcher after matching (and copies it in between): keep the reason.
    last_ = expected_.match(got);
    return last_.matches;
  }
  std::string describe() const override {
    return expected_.describe() + (last_.matches || last_.explanation.empty() ? "" : "\n" + last_.explanation);
  }

 private:
  expectation expected_;
  mutable match_result last_{true, ""};
};

/// CHECK_THAT(outputs, rounds_to(shadow_matrix_of(P, L).within_ulps(2).up_to_scale())).
inline rounds_to_matcher rounds_to(expectation e) { return rounds_to_matcher(std::move(e)); }

}  // namespace shadowproof::catch2

#undef SHADOWPROOF_CATCH2_MATCHER_BASE
