// Planes and lights: construction and the errors for impossible ones.
#include <catch2/catch.hpp>

#include "shadowproof/core/light.h"
#include "shadowproof/core/plane.h"

using namespace shadowproof;

TEST_CASE("a zero plane normal is rejected with its own error", "[plane][errors]") {
  try {
    make_plane<rational>(0, 0, 0, 1);
    FAIL("no error");
  } catch (const error& e) {
    CHECK(e.id() == "geometry.zero_normal");
    CHECK(std::string(e.what()) == "[shadowproof.geometry.zero_normal] the plane (a,b,c,d) needs a non-zero "
                                   "normal (a,b,c); a = b = c = 0 is not a plane");
  }
  CHECK_NOTHROW(make_plane<rational>(0, 0, rational(1, 1000), 0));
}

TEST_CASE("a zero light is rejected; a light with only w is a point light at the origin", "[light][errors]") {
  CHECK_THROWS_AS(make_light<rational>(0, 0, 0, 0), error);
  try {
    make_light<double>(0, 0, 0, 0);
    FAIL("no error");
  } catch (const error& e) {
    CHECK(e.id() == "geometry.zero_light");
  }
  CHECK(make_light<rational>(0, 0, 0, 3).is_point());
  CHECK(make_light<rational>(1, 0, 0, 0).is_directional());
}

TEST_CASE("the plane value is positive on the side the normal points to", "[plane]") {
  const auto P = make_plane<rational>(0, 2, 0, -4);  // y = 2
  CHECK(evaluate(P, make_point<rational>(0, 3, 0)) == 2);
  CHECK(evaluate(P, make_point<rational>(5, 2, -7)) == 0);
  CHECK(evaluate(P, make_point<rational>(0, 0, 0)) == -4);
}
