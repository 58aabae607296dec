// Tests of vec3.h: 3D point algebra over rational, double and float. The inputs are small
// integers, exact in every type, so every expected value is exact too (derived by hand).
#include <catch2/catch.hpp>

#include "shadowproof/core/vec3.h"

using namespace shadowproof;

namespace {

template <class T>
std::array<T, 3> v3(int x, int y, int z) {
  return {T(x), T(y), T(z)};
}

}  // namespace

TEMPLATE_TEST_CASE("cross product of the axes follows the right-hand rule", "", rational, double, float) {
  // x × y = z, y × z = x, z × x = y, and the other order negates.
  CHECK(cross(v3<TestType>(1, 0, 0), v3<TestType>(0, 1, 0)) == v3<TestType>(0, 0, 1));
  CHECK(cross(v3<TestType>(0, 1, 0), v3<TestType>(0, 0, 1)) == v3<TestType>(1, 0, 0));
  CHECK(cross(v3<TestType>(0, 0, 1), v3<TestType>(1, 0, 0)) == v3<TestType>(0, 1, 0));
  CHECK(cross(v3<TestType>(0, 1, 0), v3<TestType>(1, 0, 0)) == v3<TestType>(0, 0, -1));
}

TEMPLATE_TEST_CASE("cross product is orthogonal to both factors and zero for parallel ones", "", rational, double, float) {
  // (1,2,3) × (4,5,6) = (2·6 − 3·5, 3·4 − 1·6, 1·5 − 2·4) = (−3, 6, −3).
  const auto a = v3<TestType>(1, 2, 3), b = v3<TestType>(4, 5, 6);
  const auto c = cross(a, b);
  CHECK(c == v3<TestType>(-3, 6, -3));
  CHECK(dot(c, a) == TestType(0));
  CHECK(dot(c, b) == TestType(0));
  CHECK(is_zero(cross(a, v3<TestType>(-2, -4, -6))));
  CHECK_FALSE(is_zero(c));
}

TEMPLATE_TEST_CASE("dot, difference, sum, scaled and lerp componentwise", "", rational, double, float) {
  const auto a = v3<TestType>(1, -2, 3), b = v3<TestType>(4, 0, -1);
  CHECK(dot(a, b) == TestType(1));  // 4 + 0 − 3
  CHECK(dot(a, b) == dot(b, a));
  CHECK(difference(a, b) == v3<TestType>(-3, -2, 4));
  CHECK(sum(a, b) == v3<TestType>(5, -2, 2));
  CHECK(scaled(TestType(-2), a) == v3<TestType>(-2, 4, -6));
  CHECK(lerp(a, b, TestType(0)) == a);
  CHECK(lerp(a, b, TestType(1)) == b);
  CHECK(lerp(v3<TestType>(0, 0, 0), v3<TestType>(4, 8, -2), TestType(0.5)) == v3<TestType>(2, 4, -1));
}

TEMPLATE_TEST_CASE("plane value is zero on the plane and signs the sides", "", rational, double, float) {
  // P = (0, 0, 2, −4): the plane z = 2, positive above it.
  const vec4<TestType> P = make_vec4<TestType>(TestType(0), TestType(0), TestType(2), TestType(-4));
  CHECK(plane_value(P, v3<TestType>(7, -3, 2)) == TestType(0));
  CHECK(plane_value(P, v3<TestType>(0, 0, 5)) == TestType(6));
  CHECK(plane_value(P, v3<TestType>(0, 0, 0)) == TestType(-4));
}

TEST_CASE("rational cross products are exact where doubles round") {
  // (1/3, 1, 0) × (1, 3, 0) = (0, 0, 1/3·3 − 1·1) = 0: parallel exactly.
  const std::array<rational, 3> a{rational(1, 3), rational(1), rational(0)}, b{rational(1), rational(3), rational(0)};
  CHECK(is_zero(cross(a, b)));
}
