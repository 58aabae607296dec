// The planar shadow matrix and every closed form the reference derivations give for it.
#include <catch2/catch.hpp>

#include "shadowproof/constructions/shadow.h"
#include "support/random_exact.h"

using namespace shadowproof;
using shadowproof::testing::random_exact;

namespace {

template <class T>
std::array<T, 3> affine3(const vec4<T>& v) {
  return {T(v[0] / v[3]), T(v[1] / v[3]), T(v[2] / v[3])};
}

}  // namespace

TEMPLATE_TEST_CASE("point light onto the ground: the matrix derived by hand", "[shadow]", rational, double, float) {
  using T = TestType;
  // P = (0,1,0,0), L = (2,5,1,1): P·L = 5 and L Pᵀ has L as its second column.
  const auto M = shadow_matrix(make_plane<T>(0, 1, 0, 0), make_light<T>(2, 5, 1, 1));
  const auto expected = make_mat4<T>({5, -2, 0, 0,
                                      0, 0, 0, 0,
                                      0, -1, 5, 0,
                                      0, -1, 0, 5});
  CHECK(M == expected);
}

TEST_CASE("the shadow of a point is where the ray from the light meets the plane", "[shadow]") {
  // Light (2,5,1), point (1,2,3): direction (-1,-3,2) reaches y = 0 after 5/3 of it.
  const auto P = make_plane<rational>(0, 1, 0, 0);
  const auto L = make_light<rational>(2, 5, 1, 1);
  const auto image = shadow_matrix(P, L) * make_point<rational>(1, 2, 3);
  CHECK(affine3(image) == std::array<rational, 3>{rational(1, 3), 0, rational(13, 3)});
  CHECK(shadow_image(P, L, make_point<rational>(1, 2, 3)) == image);
}

TEST_CASE("every image lies exactly on the receiver", "[shadow][property]") {
  random_exact r(1);
  for (int i = 0; i < 500; ++i) {
    const auto P = r.plane_();
    const auto L = i % 2 ? r.point_light() : r.directional_light();
    const auto V = r.point();
    CHECK(dot(P.p, shadow_matrix(P, L) * V) == 0);
  }
}

TEST_CASE("scaling the plane or the light scales the matrix: the same projective map", "[shadow][property]") {
  random_exact r(2);
  for (int i = 0; i < 200; ++i) {
    const auto P = r.plane_();
    const auto L = r.point_light();
    const rational lambda = r.nonzero(), mu = r.nonzero();
    const auto M = shadow_matrix(P, L);
    const auto scaled = shadow_matrix(plane<rational>{lambda * P.p}, light<rational>{mu * L.l});
    if (is_zero(M)) continue;  // cannot happen for a valid plane and light, but keep the check honest
    CHECK(scaled == (lambda * mu) * M);
    CHECK(proportional(scaled, M));
  }
}

TEST_CASE("a light with w = 2 or w = -1 is the same light as w = 1", "[shadow]") {
  const auto P = make_plane<rational>(1, 2, -1, 3);
  const auto M1 = shadow_matrix(P, make_light<rational>(1, 5, 2, 1));
  const auto M2 = shadow_matrix(P, make_light<rational>(2, 10, 4, 2));
  const auto Mneg = shadow_matrix(P, make_light<rational>(-1, -5, -2, -1));
  CHECK(M2 == rational(2) * M1);
  CHECK(Mneg == rational(-1) * M1);
}

// ---- seed 000: directional light onto a general plane, entry by entry ----------------------

TEMPLATE_TEST_CASE("seed 000's closed form equals the general matrix for a directional light", "[shadow][seed000]",
                   rational, double, float) {
  using T = TestType;
  random_exact r(3);
  for (int i = 0; i < 200; ++i) {
    // Integers in [-20, 20]: every product and sum is exact in float and double too.
    const T a = r.integer(-20, 20), b = r.integer(-20, 20), c = r.integer(-20, 20), d = r.integer(-20, 20);
    const T lx = r.integer(-20, 20), ly = r.integer(-20, 20), lz = r.integer(-20, 20);
    if (a == 0 && b == 0 && c == 0) continue;
    if (lx == 0 && ly == 0 && lz == 0) continue;
    const auto P = make_plane<T>(a, b, c, d);
    CHECK(shadow_matrix_directional_closed_form(P, lx, ly, lz) == shadow_matrix(P, make_light<T>(lx, ly, lz, 0)));
    // The seed's L need not point towards the light: -L gives -M, the same projective map.
    CHECK(shadow_matrix_directional_closed_form(P, T(-lx), T(-ly), T(-lz)) ==
          T(-1) * shadow_matrix(P, make_light<T>(lx, ly, lz, 0)));
  }
}

TEST_CASE("seed 000 erratum (no matrix): the intersection condition is (V + kL)·P = 0, not V + kL = 0", "[shadow][seed000][erratum]") {
  // V = (1,2,3,1), L = (1,1,0,0), P = (0,1,0,0). The seed's own k = -(V·P)/(L·P) = -2.
  const auto V = make_point<rational>(1, 2, 3);
  const auto L = make_vec4<rational>(1, 1, 0, 0);
  const auto P = make_vec4<rational>(0, 1, 0, 0);
  const rational k = -dot(V, P) / dot(L, P);
  CHECK(k == -2);
  const auto hit = V + k * L;
  CHECK(dot(hit, P) == 0);   // the corrected condition holds: the point is on the plane
  CHECK(!is_zero(hit));      // the printed condition V + kL = 0 does not
  CHECK(hit[3] == 1);        // and cannot for any k: the w coordinate is 1 + 0·k
}

// ---- seed 001: ground plane at height h, two shader methods ---------------------------------

TEST_CASE("seed 001 method 1 (ray/plane intersection) equals the general matrix", "[shadow][seed001]") {
  random_exact r(4);
  for (int i = 0; i < 300; ++i) {
    const rational h = r.small();
    std::array<rational, 3> dir{r.small(), r.nonzero(), r.small()};
    std::array<rational, 3> X{r.small(), r.small(), r.small()};
    const auto M = shadow_matrix(make_plane<rational>(0, 1, 0, -h), make_light<rational>(dir[0], dir[1], dir[2], 0));
    const auto expected = affine3(M * make_point(X[0], X[1], X[2]));
    CHECK(ground_shadow_by_intersection(X, dir, h) == expected);
    // normalize(lightDir) in the shader only rescales dir; the image does not move.
    const rational s = r.nonzero();
    CHECK(ground_shadow_by_intersection(X, {s * dir[0], s * dir[1], s * dir[2]}, h) == expected);
  }
}

TEST_CASE("seed 001 method 2 (similar triangles) equals the matrix above the ground", "[shadow][seed001]") {
  random_exact r(5);
  for (int i = 0; i < 300; ++i) {
    const rational h = r.small();
    std::array<rational, 3> dir{r.small(), r.nonzero(), r.small()};
    std::array<rational, 3> X{r.small(), h + abs(r.small()), r.small()};
    const auto M = shadow_matrix(make_plane<rational>(0, 1, 0, -h), make_light<rational>(dir[0], dir[1], dir[2], 0));
    CHECK(ground_shadow_by_similar_triangles(X, dir, h) == affine3(M * make_point(X[0], X[1], X[2])));
  }
}

TEST_CASE("seed 001 method 2 leaves points below the ground where the matrix gives a false shadow", "[shadow][seed001]") {
  // h = 0, light towards (1,2,1), X = (1,-1,1) below the ground. The matrix slides X along the
  // light direction up to y = 0: X + (1/2)(1,2,1) = (3/2, 0, 3/2). The clamp keeps X.
  const std::array<rational, 3> X{1, -1, 1}, dir{1, 2, 1};
  const auto M = shadow_matrix(make_plane<rational>(0, 1, 0, 0), make_light<rational>(1, 2, 1, 0));
  CHECK(affine3(M * make_point<rational>(1, -1, 1)) == std::array<rational, 3>{rational(3, 2), 0, rational(3, 2)});
  CHECK(ground_shadow_by_similar_triangles(X, dir, rational(0)) == X);
}

// ---- seed 002: point light onto y = 0 as T(l) N T(-l) ---------------------------------------

TEST_CASE("seed 002's T(l)·N·T(-l) is 1/yl times the general matrix", "[shadow][seed002]") {
  random_exact r(6);
  for (int i = 0; i < 200; ++i) {
    const rational xl = r.small(), yl = r.nonzero(), zl = r.small();
    const auto general = shadow_matrix(make_plane<rational>(0, 1, 0, 0), make_light<rational>(xl, yl, zl, 1));
    const auto seed = ground_shadow_matrix_by_translation(xl, yl, zl);
    CHECK(seed == rational(1) / yl * general);
  }
}

TEST_CASE("seed 002's coordinate formula x_p = x_l - (x - x_l)/((y - y_l)/y_l) holds", "[shadow][seed002]") {
  // Light (2,5,1), point (1,2,3): x_p = 2 - (1-2)/((2-5)/5) = 1/3, z_p = 1 - (3-1)/(-3/5) = 13/3.
  const auto image = ground_shadow_matrix_by_translation<rational>(2, 5, 1) * make_point<rational>(1, 2, 3);
  CHECK(affine3(image) == std::array<rational, 3>{rational(1, 3), 0, rational(13, 3)});
}

// ---- seed 003: Q = L - (V - L)(<N,L> + d)/<N, V - L> ----------------------------------------

TEST_CASE("seed 003's Q formula equals the general matrix", "[shadow][seed003]") {
  random_exact r(7);
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    const auto P = r.plane_();
    const std::array<rational, 3> L{r.small(), r.small(), r.small()}, V{r.small(), r.small(), r.small()};
    const rational along = P.a() * (V[0] - L[0]) + P.b() * (V[1] - L[1]) + P.c() * (V[2] - L[2]);
    if (along == 0) continue;  // the ray is parallel to the plane: the formula divides by zero
    const auto M = shadow_matrix(P, make_light<rational>(L[0], L[1], L[2], 1));
    const auto image = M * make_point(V[0], V[1], V[2]);
    if (image[3] == 0) continue;  // V as high as the light: no finite Q exists
    CHECK(shadow_point_by_ray(P, L, V) == affine3(image));
    ++checked;
  }
  CHECK(checked > 200);
}

TEST_CASE("seed 003 erratum (no matrix): the printed t = -(<N,L>+d)/<N,(P-L)t> has a stray t", "[shadow][seed003][erratum]") {
  // Light L = (0,2,0), point V = (0,1,0), plane y = 0. The ray L + (V - L) t meets y = 0 at
  // t = 2 (hand: 2 - t = 0). The corrected formula gives it; the printed one, evaluated at the
  // true t, gives -(2)/(<N, V - L>·2) = -2/(-2) = 1 ≠ 2.
  const rational NL_plus_d = 2, N_dot_dir = -1;  // <N,L> + d and <N, V - L>
  const rational true_t = 2;
  CHECK(-NL_plus_d / N_dot_dir == true_t);
  CHECK(-NL_plus_d / (N_dot_dir * true_t) != true_t);
  const auto Q = shadow_point_by_ray(make_plane<rational>(0, 1, 0, 0), {0, 2, 0}, {0, 1, 0});
  CHECK(Q == std::array<rational, 3>{0, 0, 0});
}
