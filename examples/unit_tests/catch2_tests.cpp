// The engine's shadow matrix under Catch2: one configuration through the matcher, thousands of
// generated ones (a third exactly degenerate) through the property runner. The tests tagged
// [.planted] run the routine with the planted defect and are expected to fail.
#define CATCH_CONFIG_MAIN
#include <shadowproof/testing/catch2.h>

#include <array>

#include "engine_shadow.h"

using shadowproof::catch2::rounds_to;

namespace {

void engine_routine(const float* inputs, float* outputs) { engine::shadow_matrix(inputs, inputs + 4, outputs); }
void defective_routine(const float* inputs, float* outputs) {
  engine::shadow_matrix_with_planted_defect(inputs, inputs + 4, outputs);
}

}  // namespace

TEST_CASE("the shadow matrix of a lamp over the ground is exact") {
  const float ground[4] = {0, 1, 0, 0}, lamp[4] = {2, 5, 1, 1};
  std::array<float, 16> M{};
  engine::shadow_matrix(ground, lamp, M.data());
  CHECK_THAT(M, rounds_to(shadowproof::shadow_matrix_of(ground, lamp)));
}

TEST_CASE("the shadow matrix is within one ulp of the exact one, degenerate lights included") {
  CHECK(shadowproof::check(shadowproof::operation::shadow_matrix, engine_routine,
                           {3000, 1, {shadowproof::input_class::regular, shadowproof::input_class::near_degenerate,
                                      shadowproof::input_class::degenerate},
                            shadowproof::failure_policy::ulps_above(1)}));
}

TEST_CASE("planted defect: a lamp over a raised floor", "[.planted]") {
  const float floor[4] = {0, 1, 0, -1}, lamp[4] = {2, 5, 1, 1};  // y = 1: P·L = 4, M(3,3) = 4 + 1
  std::array<float, 16> M{};
  engine::shadow_matrix_with_planted_defect(floor, lamp, M.data());
  CHECK_THAT(M, rounds_to(shadowproof::shadow_matrix_of(floor, lamp).within_ulps(1)));
}

TEST_CASE("planted defect: the property runner finds and shrinks it", "[.planted]") {
  CHECK(shadowproof::check(shadowproof::operation::shadow_matrix, defective_routine,
                           {300, 1, {shadowproof::input_class::regular}, shadowproof::failure_policy::ulps_above(1)}));
}
