// The engine's shadow matrix under GoogleTest, as catch2_tests.cpp does under Catch2. The
// DISABLED_ tests run the routine with the planted defect and are expected to fail.
#include <shadowproof/testing/gtest.h>

#include <array>

#include "engine_shadow.h"

using shadowproof::gtest::passes;
using shadowproof::gtest::rounds_to;

namespace {

void engine_routine(const float* inputs, float* outputs) { engine::shadow_matrix(inputs, inputs + 4, outputs); }
void defective_routine(const float* inputs, float* outputs) {
  engine::shadow_matrix_with_planted_defect(inputs, inputs + 4, outputs);
}

}  // namespace

TEST(EngineShadow, LampOverTheGroundIsExact) {
  const std::array<float, 4> ground{0, 1, 0, 0}, lamp{2, 5, 1, 1};
  std::array<float, 16> M{};
  engine::shadow_matrix(ground.data(), lamp.data(), M.data());
  EXPECT_THAT(M, rounds_to(shadowproof::shadow_matrix_of(ground, lamp)));
}

TEST(EngineShadow, WithinOneUlpOnGeneratedCases) {
  shadowproof::check_settings settings{3000, 2};
  settings.fail_on = shadowproof::failure_policy::parse("ulps>1");
  EXPECT_TRUE(passes(shadowproof::check(shadowproof::operation::shadow_matrix, engine_routine, settings)));
}

TEST(EngineShadow, DISABLED_PlantedDefectOverARaisedFloor) {
  const std::array<float, 4> floor{0, 1, 0, -1}, lamp{2, 5, 1, 1};
  std::array<float, 16> M{};
  engine::shadow_matrix_with_planted_defect(floor.data(), lamp.data(), M.data());
  EXPECT_THAT(M, rounds_to(shadowproof::shadow_matrix_of(floor, lamp).within_ulps(1)));
}

TEST(EngineShadow, DISABLED_PlantedDefectFoundByThePropertyRunner) {
  EXPECT_TRUE(passes(shadowproof::check(shadowproof::operation::shadow_matrix, defective_routine,
                                        {300, 1, {shadowproof::input_class::regular}})));
}
