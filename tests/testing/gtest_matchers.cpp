// The matchers and the property runner through GoogleTest (include/shadowproof/testing/gtest.h):
// a match, the description and explanation GoogleTest prints for a planted defect, verbatim,
// and a property check.
#include "shadowproof/testing/gtest.h"

#include <array>
#include <cmath>

#include "shadowproof/constructions/reflect.h"

using shadowproof::gtest::passes;
using shadowproof::gtest::rounds_to;

namespace {

// The ground y = 0 and the point light (2, 5, 1): P·L = 5, M = 5 I − L Pᵀ (README).
const std::array<float, 4> ground{0, 1, 0, 0};
const std::array<float, 4> lamp{2, 5, 1, 1};
const std::array<float, 16> ground_shadow{5, -2, 0, 0, 0, 0, 0, 0, 0, -1, 5, 0, 0, -1, 0, 5};

// A double mirror routine that rounds the exact matrix correctly (reflect.h over rationals,
// then MPFR's correct rounding): the fixed point of every metric, so no case may fail.
void correctly_rounded_mirror(const double* in, double* out) {
  using shadowproof::exact_value;
  const auto P = shadowproof::make_plane(exact_value(in[0]), exact_value(in[1]), exact_value(in[2]), exact_value(in[3]));
  const auto M = shadowproof::reflection_matrix(P);
  for (std::size_t i = 0; i < 16; ++i) out[i] = shadowproof::to_nearest_double(M(i / 4, i % 4));
}

}  // namespace

TEST(ShadowproofGtestMatchers, TheExactShadowMatrixMatches) {
  EXPECT_THAT(ground_shadow, rounds_to(shadowproof::shadow_matrix_of(ground, lamp)));
}

TEST(ShadowproofGtestMatchers, APlantedDefectIsExplainedEntryByEntry) {
  auto M = ground_shadow;
  M[15] = 6;  // (3,3): exactly 5; a float step is 2^-21 in [4, 8), so 6 is 2^21 steps away
  const auto matcher = ::testing::Matcher<const std::array<float, 16>&>(
      rounds_to(shadowproof::shadow_matrix_of(ground, lamp).within_ulps(2)));
  ::testing::StringMatchResultListener why;
  EXPECT_FALSE(matcher.MatchAndExplain(M, &why));
  EXPECT_EQ(why.str(),
            "\n  1 of 16 outputs fail (ulps>2):\n"
            "  (3,3): got 6 (0x1.8p+2), exact 5, correctly rounded 5 (0x1.4p+2): 2097152 ulps\n"
            "  inputs (f32): plane (0, 1, 0, 0), light (2, 5, 1, 1)\n"
            "  exact answer: shadowproof shadow --plane 0x0p+0,0x1p+0,0x0p+0,0x0p+0 --light "
            "0x1p+1,0x1.4p+2,0x1p+0,0x1p+0\n");
  const std::string description = ::testing::DescribeMatcher<const std::array<float, 16>&>(matcher);
  EXPECT_EQ(description,
            "is the correctly rounded shadow-matrix of plane (0, 1, 0, 0), light (2, 5, 1, 1) in f32, within 2 ulps");
}

TEST(ShadowproofGtestMatchers, APropertyCheckPassesACorrectlyRoundingMirror) {
  EXPECT_TRUE(passes(shadowproof::check(shadowproof::operation::reflection_matrix, correctly_rounded_mirror, {300, 4})));
}
