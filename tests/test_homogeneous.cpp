// Homogeneous vectors and matrices, generic over the number type.
#include <catch2/catch.hpp>

#include "shadowproof/core/homogeneous.h"
#include "support/random_exact.h"

using namespace shadowproof;
using shadowproof::testing::random_exact;

namespace {

mat4<rational> random_matrix(random_exact& r) {
  mat4<rational> m;
  for (auto& row : m.m)
    for (auto& x : row) x = r.small();
  return m;
}

}  // namespace

TEMPLATE_TEST_CASE("matrix times vector follows the column-vector convention", "[homogeneous]", rational, double, float) {
  using T = TestType;
  const auto t = translation<T>(1, 2, 3);
  CHECK(t * make_point<T>(10, 20, 30) == make_point<T>(11, 22, 33));
  CHECK(t * make_vec4<T>(1, 0, 0, 0) == make_vec4<T>(1, 0, 0, 0));  // directions do not move
  CHECK(scaling<T>(2, 3, 4) * make_point<T>(1, 1, 1) == make_point<T>(2, 3, 4));
}

TEMPLATE_TEST_CASE("determinants of triangular and permutation matrices", "[homogeneous]", rational, double, float) {
  using T = TestType;
  // Upper triangular: the product of the diagonal, 2·3·5·7 = 210.
  CHECK(determinant(make_mat4<T>({2, 9, 9, 9, 0, 3, 9, 9, 0, 0, 5, 9, 0, 0, 0, 7})) == T(210));
  // Swapping two rows of the identity: -1; a 4-cycle of rows: (-1)^3 = -1.
  CHECK(determinant(make_mat4<T>({0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1})) == T(-1));
  CHECK(determinant(make_mat4<T>({0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 0})) == T(-1));
  CHECK(determinant(make_mat4<T>({1, 2, 3, 4, 2, 4, 6, 8, 0, 1, 0, 1, 5, 5, 5, 5})) == T(0));
}

TEST_CASE("A·adj(A) = det(A)·I and det is multiplicative", "[homogeneous][property]") {
  random_exact r(31);
  for (int i = 0; i < 200; ++i) {
    const auto A = random_matrix(r), B = random_matrix(r);
    CHECK(A * adjugate(A) == determinant(A) * identity4<rational>());
    CHECK(adjugate(A) * A == determinant(A) * identity4<rational>());
    CHECK(determinant(A * B) == determinant(A) * determinant(B));
    CHECK(determinant(transpose(A)) == determinant(A));
  }
}

TEST_CASE("matrix product is associative and distributes over vectors", "[homogeneous][property]") {
  random_exact r(32);
  for (int i = 0; i < 100; ++i) {
    const auto A = random_matrix(r), B = random_matrix(r), C = random_matrix(r);
    const auto V = r.point();
    CHECK((A * B) * C == A * (B * C));
    CHECK((A * B) * V == A * (B * V));
    CHECK(transpose(A * B) == transpose(B) * transpose(A));
  }
}

TEST_CASE("proportional means equal up to a non-zero scale", "[homogeneous]") {
  const auto A = make_mat4<rational>({1, 2, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  CHECK(proportional(A, rational(-3, 7) * A));
  CHECK_FALSE(proportional(A, A + identity4<rational>()));
  CHECK_FALSE(proportional(A, mat4<rational>{}));
  CHECK(proportional(make_vec4<rational>(1, 2, 3, 4), make_vec4<rational>(-2, -4, -6, -8)));
  CHECK_FALSE(proportional(make_vec4<rational>(1, 2, 3, 4), make_vec4<rational>(1, 2, 3, 5)));
  CHECK_FALSE(proportional(make_vec4<rational>(0, 0, 0, 0), make_vec4<rational>(0, 0, 0, 0)));
}

TEST_CASE("converting to float rounds each entry correctly and back is exact", "[homogeneous]") {
  const auto v = make_vec4<rational>(rational(1, 10), rational(1, 3), 2, rational(-5, 4));
  const auto f = convert<float>(v);
  CHECK(f[0] == 0.1f);
  CHECK(f[1] == 1.0f / 3.0f);  // 1/3 correctly rounded equals IEEE division of 1 by 3
  CHECK(f[2] == 2.0f);
  CHECK(convert<rational>(f)[3] == rational(-5, 4));
}
