// The normal matrix G = (M⁻¹)ᵀ: tangents and normals stay perpendicular under G, not under M.
#include <catch2/catch.hpp>

#include <functional>

#include "shadowproof/core/error.h"
#include "shadowproof/constructions/normal_matrix.h"
#include "support/exact_helpers.h"

using namespace shadowproof;
using shadowproof::testing::q;
using shadowproof::testing::error_text;

namespace {

vec4<rational> direction(const rational& x, const rational& y, const rational& z) {
  return make_vec4<rational>(x, y, z, 0);
}

// Non-uniform scale S(2, 1/3, 5), then a shear x += (1/2) y + z, y += (−3/4) z, then a
// translation (7, −1, 2): affine, det = 2·(1/3)·5 = 10/3.
mat4<rational> scale_shear_translate() {
  const mat4<rational> shear = make_mat4<rational>({1, q(1, 2), 1, 0,  //
                                                    0, 1, q(-3, 4), 0,  //
                                                    0, 0, 1, 0,  //
                                                    0, 0, 0, 1});
  return translation<rational>(7, -1, 2) * shear * scaling<rational>(2, q(1, 3), 5);
}

}  // namespace

TEST_CASE("inverse times matrix is the identity, exactly", "[normal_matrix]") {
  const mat4<rational> M = scale_shear_translate();
  CHECK(inverse(M) * M == identity4<rational>());
  CHECK(M * inverse(M) == identity4<rational>());
  // A projective (non-affine) matrix too.
  const mat4<rational> P = make_mat4<rational>({1, 2, 0, 3, 0, 1, 4, 0, 5, 0, 1, 0, 0, 6, 0, 1});
  CHECK(inverse(P) * P == identity4<rational>());
}

TEST_CASE("G = (M^-1)^T keeps transformed tangents perpendicular to transformed normals",
          "[normal_matrix]") {
  const mat4<rational> M = scale_shear_translate();
  const mat4<rational> G = normal_matrix(M);
  // Surface normals with two tangents each (t · n = 0 by hand).
  struct frame { vec4<rational> n, t1, t2; };
  const frame frames[] = {
      {direction(1, 1, 0), direction(1, -1, 0), direction(0, 0, 1)},
      {direction(1, 2, 3), direction(3, 0, -1), direction(2, -1, 0)},
      {direction(q(1, 2), q(-2, 3), 5), direction(4, 3, 0), direction(10, 0, -1)},
  };
  for (const auto& fr : frames) {
    REQUIRE(dot3(fr.n, fr.t1) == 0);
    REQUIRE(dot3(fr.n, fr.t2) == 0);
    const vec4<rational> n_image = G * fr.n;
    CHECK(dot3(M * fr.t1, n_image) == 0);
    CHECK(dot3(M * fr.t2, n_image) == 0);
    // The shaders' 3x3 version agrees on the normal's direction part for an affine M.
    const vec4<rational> n3 = normal_matrix3(M) * fr.n;
    CHECK(n3[0] == n_image[0]);
    CHECK(n3[1] == n_image[1]);
    CHECK(n3[2] == n_image[2]);
  }
}

TEST_CASE("M itself breaks perpendicularity under non-uniform scale (seed 004's point)", "[normal_matrix]") {
  // S(2, 1, 1) on the plane x + y = 0: normal n = (1, 1, 0), tangent t = (1, −1, 0).
  // M t = (2, −1, 0), M n = (2, 1, 0): (M t)·(M n) = 4 − 1 = 3 ≠ 0.
  // G n = (1/2, 1, 0):                  (M t)·(G n) = 1 − 1 = 0.
  const mat4<rational> M = scaling<rational>(2, 1, 1);
  const vec4<rational> n = direction(1, 1, 0), t = direction(1, -1, 0);
  CHECK(M * t == direction(2, -1, 0));
  CHECK(dot3(M * t, M * n) == 3);
  CHECK(normal_matrix(M) * n == direction(q(1, 2), 1, 0));
  CHECK(dot3(M * t, normal_matrix(M) * n) == 0);
}

TEST_CASE("M itself also breaks perpendicularity under a shear", "[normal_matrix]") {
  // Shear x += y: plane y = 0 has normal (0, 1, 0) and tangent (1, 0, 0); the tangent stays
  // (1, 0, 0) but M n = (1, 1, 0) is no longer perpendicular to it; G n = (0, 1, 0) with
  // G = (M⁻¹)ᵀ = [1 0 0; −1 1 0; 0 0 1] is.
  const mat4<rational> M = make_mat4<rational>({1, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  const vec4<rational> n = direction(0, 1, 0), t = direction(1, 0, 0);
  CHECK(dot3(M * t, M * n) == 1);
  CHECK(normal_matrix(M) == make_mat4<rational>({1, 0, 0, 0, -1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}));
  CHECK(normal_matrix(M) * n == direction(0, 1, 0));
  CHECK(dot3(M * t, normal_matrix(M) * n) == 0);
}

TEST_CASE("planes map to planes under G: (G P)·(M X) = P·X", "[normal_matrix]") {
  const mat4<rational> M = scale_shear_translate();
  const mat4<rational> G = normal_matrix(M);
  const vec4<rational> P = make_vec4<rational>(2, -1, q(1, 3), 4);
  const vec4<rational> points[] = {make_point<rational>(1, 2, 3), make_point<rational>(q(-1, 2), 0, 7),
                                   make_point<rational>(-2, -6, 0)};
  for (const auto& X : points) CHECK(dot(G * P, M * X) == dot(P, X));
}

TEST_CASE("the adjugate form is det(M) times G and needs no division", "[normal_matrix]") {
  const mat4<rational> M = scale_shear_translate();
  CHECK(normal_matrix_adjugate(M) == determinant(M) * normal_matrix(M));
  CHECK(determinant(M) == q(10, 3));
  // A mirror (det < 0): the adjugate form points normals the other way, as documented.
  const mat4<rational> mirror = scaling<rational>(-1, 1, 1);
  CHECK(normal_matrix(mirror) * direction(0, 1, 0) == direction(0, 1, 0));
  CHECK(normal_matrix_adjugate(mirror) * direction(0, 1, 0) == direction(0, -1, 0));
}

TEST_CASE("a singular matrix has no normal matrix: clear error", "[normal_matrix]") {
  const std::string expected =
      "[shadowproof.matrix.singular] the matrix is singular (determinant 0): it flattens space, so neither "
      "its inverse nor its normal matrix (M⁻¹)ᵀ exists";
  // Flattening z (rank 3).
  CHECK(error_text([] { normal_matrix(scaling<rational>(1, 1, 0)); }) == expected);
  // Rank 3 without a zero row or column: row 2 = row 0 + row 1.
  const mat4<rational> M = make_mat4<rational>({1, 2, 3, 4, 0, 1, 5, 6, 1, 3, 8, 10, 0, 0, 0, 1});
  CHECK(error_text([&] { normal_matrix(M); }) == expected);
  // The linear part alone can be singular while M is not: only normal_matrix3 refuses then.
  const mat4<rational> projective = make_mat4<rational>({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0});
  CHECK(error_text([&] { normal_matrix(projective); }) == "no error");
  CHECK(error_text([&] { normal_matrix3(projective); }) == expected);
  // The adjugate form never throws; for rank 3 it has rank 1 (all 2x2 minors vanish).
  const mat4<rational> C = normal_matrix_adjugate(M);
  CHECK_FALSE(is_zero(C));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 4; ++l) CHECK(C(i, j) * C(k, l) == C(i, l) * C(k, j));
}
