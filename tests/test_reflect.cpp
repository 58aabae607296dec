// The planar reflection matrix: closed form, its properties, and the frame composition.
#include <catch2/catch.hpp>

#include "shadowproof/constructions/reflect.h"
#include "support/random_exact.h"

using namespace shadowproof;
using shadowproof::testing::random_exact;

namespace {

rational squared_distance(const vec4<rational>& a, const vec4<rational>& b) {
  rational s = 0;
  for (std::size_t i = 0; i < 3; ++i) s += (a[i] / a[3] - b[i] / b[3]) * (a[i] / a[3] - b[i] / b[3]);
  return s;
}

frame3<rational> random_frame(random_exact& r) {
  rational qw = r.small(), qx = r.small(), qy = r.small(), qz = r.small();
  while (qw == 0 && qx == 0 && qy == 0 && qz == 0) qw = r.small();
  return frame_from_quaternion(qw, qx, qy, qz);
}

}  // namespace

TEMPLATE_TEST_CASE("the mirror y = 1 maps the origin to (0, 2, 0)", "[reflect]", rational, double, float) {
  using T = TestType;
  const auto M = reflection_matrix(make_plane<T>(0, 1, 0, -1));
  CHECK(M == make_mat4<T>({1, 0, 0, 0,
                           0, -1, 0, 2,
                           0, 0, 1, 0,
                           0, 0, 0, 1}));
  CHECK(M * make_point<T>(0, 0, 0) == make_point<T>(0, 2, 0));
}

TEST_CASE("the mirror x + 2y + 2z = 3: the matrix derived by hand", "[reflect]") {
  // n = (1,2,2), n·n = 9: I - 2nnᵀ/9 and translation -2d n/9 = (2/3, 4/3, 4/3).
  const rational n9(1, 9);
  const auto expected = make_mat4<rational>({7 * n9, -4 * n9, -4 * n9, rational(2, 3),
                                             -4 * n9, 1 * n9, -8 * n9, rational(4, 3),
                                             -4 * n9, -8 * n9, 1 * n9, rational(4, 3),
                                             0, 0, 0, 1});
  CHECK(reflection_matrix(make_plane<rational>(1, 2, 2, -3)) == expected);
}

TEST_CASE("reflection is an involution with determinant -1", "[reflect][property]") {
  random_exact r(21);
  for (int i = 0; i < 300; ++i) {
    const auto M = reflection_matrix(r.plane_());
    CHECK(M * M == identity4<rational>());
    CHECK(determinant(M) == -1);
  }
}

TEST_CASE("points of the mirror are fixed and distances are preserved", "[reflect][property]") {
  random_exact r(22);
  for (int i = 0; i < 300; ++i) {
    const auto P = r.plane_();
    const auto M = reflection_matrix(P);
    // A point on P: start anywhere and slide along the normal by -(P·X)/(n·n).
    const auto X = r.point();
    const auto on_plane = X - (evaluate(P, X) / dot3(P.p, P.p)) * P.normal();
    REQUIRE(evaluate(P, on_plane) == 0);
    CHECK(M * on_plane == on_plane);
    const auto A = r.point(), B = r.point();
    CHECK(squared_distance(M * A, M * B) == squared_distance(A, B));
    // The mirror image is on the other side at the same distance: P·(MX) = -P·X.
    CHECK(evaluate(P, M * X) == -evaluate(P, X));
  }
}

TEST_CASE("scaling the plane equation does not change the reflection", "[reflect][property]") {
  random_exact r(23);
  for (int i = 0; i < 100; ++i) {
    const auto P = r.plane_();
    CHECK(reflection_matrix(plane<rational>{r.nonzero() * P.p}) == reflection_matrix(P));
  }
}

TEST_CASE("quaternion frames are orthonormal with rational coordinates", "[reflect]") {
  random_exact r(24);
  for (int i = 0; i < 100; ++i) {
    const auto f = random_frame(r);
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t b = 0; b < 3; ++b) {
        rational d = 0;
        for (std::size_t k = 0; k < 3; ++k) d += f.rows[a][k] * f.rows[b][k];
        CHECK(d == (a == b ? 1 : 0));
      }
  }
  // q = (1,1,0,0)/|q|²: the rotation by 90° about x, rows (1,0,0), (0,0,1), (0,-1,0) by hand.
  const auto f = frame_from_quaternion<rational>(1, 1, 0, 0);
  CHECK(f.rows[0] == std::array<rational, 3>{1, 0, 0});
  CHECK(f.rows[1] == std::array<rational, 3>{0, 0, -1});
  CHECK(f.rows[2] == std::array<rational, 3>{0, 1, 0});
}

TEST_CASE("the frame composition T(-dN)·Rᵀ·S·R·T(dN) equals the closed form", "[reflect][seed003]") {
  random_exact r(25);
  for (int i = 0; i < 200; ++i) {
    const auto f = random_frame(r);
    const rational d = r.small();
    CHECK(reflection_by_frame(f, d) == reflection_matrix(frame_plane(f, d)));
  }
}

TEST_CASE("seed 003, read with column vectors: T(dN)·Rᵀ·S·R·T(-dN) reflects about the wrong plane", "[reflect][seed003][erratum]") {
  // Read as X' = M X (this project's convention), the rightmost factor acts first. Mirror y - 1 = 0
  // (N = (0,1,0), d = -1) with the frame R = I: the true mirror image of the origin is (0,2,0);
  // the printed composition gives (0,-2,0). Read with row vectors, as the seed's steps are
  // listed, it is right (test_seed_errata.cpp), so this is a convention the seed leaves unstated.
  const auto identity_frame = frame_from_quaternion<rational>(1, 0, 0, 0);
  const auto origin = make_point<rational>(0, 0, 0);
  CHECK(reflection_by_frame(identity_frame, rational(-1)) * origin == make_point<rational>(0, 2, 0));
  CHECK(reflection_by_frame_as_printed_in_seed003(identity_frame, rational(-1)) * origin == make_point<rational>(0, -2, 0));
  // It agrees with the true reflection only when the mirror passes through the origin.
  random_exact r(26);
  for (int i = 0; i < 50; ++i) {
    const auto f = random_frame(r);
    const rational d = r.nonzero();
    CHECK(reflection_by_frame_as_printed_in_seed003(f, rational(0)) == reflection_matrix(frame_plane(f, rational(0))));
    CHECK(reflection_by_frame_as_printed_in_seed003(f, d) != reflection_matrix(frame_plane(f, d)));
    CHECK(reflection_by_frame_as_printed_in_seed003(f, d) == reflection_matrix(frame_plane(f, rational(-d))));
  }
}
