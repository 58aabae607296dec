// Change of basis (seed 004): child -> parent from the child's axes and origin; the inverse of
// the 3x3 part is its transpose exactly when the axes are orthonormal.
#include <catch2/catch.hpp>

#include <functional>

#include "shadowproof/constructions/basis.h"
#include "shadowproof/core/error.h"
#include "shadowproof/constructions/reflect.h"
#include "support/exact_helpers.h"

using namespace shadowproof;
using shadowproof::testing::q;
using shadowproof::testing::error_text;

namespace {

// The columns of the quaternion rotation: frame_from_quaternion gives the rows of an orthonormal
// matrix, and its columns are orthonormal too.
struct axes {
  vec3<rational> x, y, z;
};
axes axes_of(const frame3<rational>& f) {
  axes a;
  for (std::size_t i = 0; i < 3; ++i) {
    a.x[i] = f.rows[i][0];
    a.y[i] = f.rows[i][1];
    a.z[i] = f.rows[i][2];
  }
  return a;
}

}  // namespace

TEST_CASE("child point (a, b, c) goes to O + a X + b Y + c Z", "[basis]") {
  const vec3<rational> X{1, 2, 0}, Y{0, 1, 3}, Z{q(1, 2), 0, 1}, O{5, -1, 2};
  const mat4<rational> M = child_to_parent(X, Y, Z, O);
  // (a, b, c) = (2, −1, 4): O + 2X − Y + 4Z = (5 + 2 + 0 + 2, −1 + 4 − 1 + 0, 2 + 0 − 3 + 4).
  CHECK(M * make_point<rational>(2, -1, 4) == make_point<rational>(9, 2, 3));
  // Directions (w = 0) ignore the origin.
  CHECK(M * make_vec4<rational>(0, 1, 0, 0) == make_vec4<rational>(0, 1, 3, 0));
  CHECK(parent_to_child(X, Y, Z, O) * make_point<rational>(9, 2, 3) == make_point<rational>(2, -1, 4));
}

TEST_CASE("for rational orthonormal frames the inverse of the 3x3 part is its transpose, exactly", "[basis]") {
  const frame3<rational> frames[] = {
      frame_from_quaternion<rational>(1, 2, 3, 4), frame_from_quaternion<rational>(2, -1, 0, 5),
      frame_from_quaternion<rational>(q(1, 2), q(1, 3), q(-1, 5), 1), frame_from_quaternion<rational>(0, 1, 1, 1)};
  const vec3<rational> O{q(3, 7), -2, 11};
  for (const auto& f : frames) {
    const axes a = axes_of(f);
    REQUIRE(is_orthonormal(a.x, a.y, a.z));
    const mat4<rational> A = linear_part(child_to_parent(a.x, a.y, a.z, O));
    CHECK(inverse(A) == transpose(A));
    // The seed's shortcut (rows X, Y, Z and translation −(X·O, Y·O, Z·O)) is the exact inverse.
    CHECK(parent_to_child_orthonormal(a.x, a.y, a.z, O) == parent_to_child(a.x, a.y, a.z, O));
    CHECK(parent_to_child_orthonormal(a.x, a.y, a.z, O) * child_to_parent(a.x, a.y, a.z, O) ==
          identity4<rational>());
  }
}

TEST_CASE("for non-orthonormal axes the transpose is not the inverse", "[basis]") {
  const vec3<rational> O{1, 2, 3};
  struct named { const char* what; vec3<rational> x, y, z; };
  const named cases[] = {
      // Orthogonal but not unit: A = diag(2, 1, 1), A⁻¹ = diag(1/2, 1, 1) ≠ Aᵀ = A.
      {"scaled axis", {2, 0, 0}, {0, 1, 0}, {0, 0, 1}},
      // Unit but not orthogonal: X·Y = 3/5.
      {"skewed axes", {1, 0, 0}, {q(3, 5), q(4, 5), 0}, {0, 0, 1}},
      // Orthogonal, one axis of length 1/2.
      {"half-length axis", {0, q(1, 2), 0}, {1, 0, 0}, {0, 0, 1}},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    CHECK_FALSE(is_orthonormal(c.x, c.y, c.z));
    const mat4<rational> A = linear_part(child_to_parent(c.x, c.y, c.z, O));
    CHECK(inverse(A) != transpose(A));
    CHECK(parent_to_child_orthonormal(c.x, c.y, c.z, O) != parent_to_child(c.x, c.y, c.z, O));
  }
  // By hand for the scaled axis: A⁻¹ has 1/2 where Aᵀ has 2.
  const mat4<rational> A = linear_part(child_to_parent<rational>({2, 0, 0}, {0, 1, 0}, {0, 0, 1}, O));
  CHECK(inverse(A)(0, 0) == q(1, 2));
  CHECK(transpose(A)(0, 0) == 2);
}

TEST_CASE("linearly dependent axes have no parent -> child matrix", "[basis]") {
  CHECK(error_text([] {
          parent_to_child<rational>({1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 0});
        }) ==
        "[shadowproof.matrix.singular] the matrix is singular (determinant 0): it flattens space, so "
        "neither its inverse nor its normal matrix (M⁻¹)ᵀ exists");
}
