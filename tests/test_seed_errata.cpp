// What the reference derivations (../shared/seeds, seeds 001-004) get wrong, beyond the errata in
// test_shadow.cpp, test_reflect.cpp and test_project.cpp: each mistake with the smallest exact
// counterexample we know and the vector convention it is read with, and the candidates that turn
// out not to be mistakes, with the reason. docs/derivations.md proves each symbolically.
#include <catch2/catch.hpp>

#include "shadowproof/constructions/normal_matrix.h"
#include "shadowproof/constructions/project.h"
#include "shadowproof/constructions/reflect.h"

using namespace shadowproof;

namespace {

rational q(long n, long d = 1) { return rational(n, d); }

vec4<rational> ndc(const mat4<rational>& M, const vec4<rational>& X) {
  const vec4<rational> v = M * X;
  return make_vec4<rational>(v[0] / v[3], v[1] / v[3], v[2] / v[3], 1);
}

}  // namespace

// ---- seed 001 ----------------------------------------------------------------------------------

TEST_CASE("seed 001 erratum (no matrix): (p0 - L0)·N = 0 puts the line in the plane only if also L·N = 0",
          "[erratum][seed001]") {
  // The plane y = 0 through p0 = 0 with N = (0, 1, 0); the line L0 + d L through L0 = 0.
  const auto plane_y0 = make_plane<rational>(0, 1, 0, 0);
  const auto L0 = make_point<rational>(0, 0, 0);
  CHECK(evaluate(plane_y0, L0) == 0);  // the seed's condition (p0 - L0)·N = 0 holds
  // With L = (0, 1, 0), L·N = 1: the point at d = 1 is (0, 1, 0), off the plane.
  const auto L = make_vec4<rational>(0, 1, 0, 0);
  CHECK(evaluate(plane_y0, L0 + rational(1) * L) == 1);
  // With L·N = 0 as well (L = (1, 0, 1)) every point of the line is on the plane.
  const auto along = make_vec4<rational>(1, 0, 1, 0);
  for (int d = -3; d <= 3; ++d) CHECK(evaluate(plane_y0, L0 + rational(d) * along) == 0);
}

// ---- seed 002 ----------------------------------------------------------------------------------

TEST_CASE("seed 002 erratum (column vectors, theta from tan(theta) = z/(x_p - x)): the later -cot shear",
          "[erratum][seed002]") {
  // θ = 45°, φ = 90°: cot θ = 1, cot φ = 0. The seed's x_p = x + z cot θ sends (0, 0, 1) to (1, 0, 0).
  const auto X = make_point<rational>(0, 0, 1);
  // Its first slide's matrix, M_orth H with +cot, agrees; the library's oblique_shear(c, d) has
  // -c, -d, so +cot is oblique_shear(-cot θ, -cot φ).
  CHECK(oblique_parallel_projection<rational>(-1, 0) * X == make_point<rational>(1, 0, 0));
  // The later slide's H with -cot, for the same θ, sends it to (-1, 0, 0) instead ...
  CHECK(oblique_parallel_projection<rational>(1, 0) * X == make_point<rational>(-1, 0, 0));
  // ... because it sends the projector (cot θ, cot φ, -1) to (2 cot θ, 2 cot φ, -1), not the z axis.
  const auto projector = make_vec4<rational>(1, 0, -1, 0);
  CHECK(oblique_shear<rational>(1, 0) * projector == make_vec4<rational>(2, 0, -1, 0));
  CHECK(oblique_shear<rational>(-1, 0) * projector == make_vec4<rational>(0, 0, -1, 0));
  // It is right for the angles measured from the other side (θ' = 180° − θ): projector (1, 0, 1).
  CHECK(oblique_shear<rational>(1, 0) * make_vec4<rational>(1, 0, 1, 0) == make_vec4<rational>(0, 0, 1, 0));
}

// ---- seed 003 ----------------------------------------------------------------------------------

TEST_CASE("seed 003, not an erratum with row vectors: T(dN)·Rᵀ·S·R·T(-dN) read left to right is the reflection",
          "[not_erratum][seed003]") {
  // N = (1,2,2)/3, U = (2,1,-2)/3, V = (2,-2,1)/3 are the rows of the rotation of q = (2, -1, -1, 0);
  // d = 3. With row vectors X' = X M_row and T_row(t) = T(t)ᵀ, the printed order reflects
  // X = (1, 2, 3) to X − 2(⟨N, X⟩ + d) N = (1, 2, 3) − (40/3)(1, 2, 2)/3 = (−31/9, −62/9, −53/9).
  const auto f = frame_from_quaternion<rational>(2, -1, -1, 0);
  REQUIRE(f.rows[1] == std::array<rational, 3>{q(1, 3), q(2, 3), q(2, 3)});
  REQUIRE(f.rows[0] == std::array<rational, 3>{q(2, 3), q(1, 3), q(-2, 3)});
  const rational d = 3;
  const auto& N = f.rows[1];
  const mat4<rational> R = frame_matrix(f), S = scaling<rational>(1, -1, 1);
  const mat4<rational> T_dN = translation<rational>(d * N[0], d * N[1], d * N[2]);
  const mat4<rational> T_minus_dN = translation<rational>(-d * N[0], -d * N[1], -d * N[2]);
  const mat4<rational> M_row = transpose(T_dN) * transpose(R) * S * R * transpose(T_minus_dN);
  // X M_row as a column: M_rowᵀ X.
  const auto X = make_point<rational>(1, 2, 3);
  CHECK(transpose(M_row) * X == make_point<rational>(q(-31, 9), q(-62, 9), q(-53, 9)));
  CHECK(transpose(M_row) == reflection_matrix(frame_plane(f, d)));
  // Read with column vectors (this project's convention) the same product reflects about
  // ⟨N, X⟩ − d = 0 (test_reflect.cpp has the smallest counterexample).
  CHECK(reflection_by_frame_as_printed_in_seed003(f, d) * X != make_point<rational>(q(-31, 9), q(-62, 9), q(-53, 9)));
}

TEST_CASE("seed 003 erratum (column or row vectors): the frame needs a unit normal N", "[erratum][seed003]") {
  // The seed's conditions <U,U> = <V,V> = 1, <U,V> = <U,N> = <N,V> = 0 allow N = (0, 2, 0), read
  // off 2y = 0 or 2y - 2 = 0: rows U = (1,0,0), N = (0,2,0), V = (0,0,1).
  frame3<rational> f;
  f.rows = {{{1, 0, 0}, {0, 2, 0}, {0, 0, 1}}};
  // d = 0: the product is diag(1, -4, 1, 1); (0, 1, 0) goes to (0, -4, 0), not (0, -1, 0).
  CHECK(reflection_by_frame(f, rational(0)) == scaling<rational>(1, -4, 1));
  CHECK(reflection_by_frame(f, rational(0)) * make_point<rational>(0, 1, 0) == make_point<rational>(0, -4, 0));
  CHECK(reflection_matrix(make_plane<rational>(0, 2, 0, 0)) * make_point<rational>(0, 1, 0) == make_point<rational>(0, -1, 0));
  // d = -2, the mirror 2y - 2 = 0 (y = 1): the origin goes to (0, 20, 0), not (0, 2, 0).
  CHECK(reflection_by_frame(f, rational(-2)) * make_point<rational>(0, 0, 0) == make_point<rational>(0, 20, 0));
  CHECK(reflection_matrix(make_plane<rational>(0, 2, 0, -2)) * make_point<rational>(0, 0, 0) == make_point<rational>(0, 2, 0));
  // Read with row vectors the product is the transpose and fails the same way on (0, 1, 0).
  CHECK(transpose(reflection_by_frame(f, rational(0))) * make_point<rational>(0, 1, 0) == make_point<rational>(0, -4, 0));
}

TEST_CASE("seed 003 erratum (wording): S(1, -1, 1) mirrors in the xz-plane, it is not the reflection about the Y axis",
          "[erratum][seed003]") {
  const mat4<rational> S = scaling<rational>(1, -1, 1), half_turn_about_y = scaling<rational>(-1, 1, -1);
  // A reflection about the Y axis fixes the axis; S moves its point (0, 1, 0) to (0, -1, 0).
  CHECK(half_turn_about_y * make_point<rational>(0, 1, 0) == make_point<rational>(0, 1, 0));
  CHECK(S * make_point<rational>(0, 1, 0) == make_point<rational>(0, -1, 0));
  // S fixes the plane y = 0 instead, and reverses orientation; the half-turn does not.
  CHECK(S * make_point<rational>(3, 0, -2) == make_point<rational>(3, 0, -2));
  CHECK(determinant(S) == -1);
  CHECK(determinant(half_turn_about_y) == 1);
  // Built with the half-turn, the frame composition is no mirror: R = I, d = 0.
  const auto f = frame_from_quaternion<rational>(1, 0, 0, 0);
  const mat4<rational> R = frame_matrix(f);
  CHECK(transpose(R) * half_turn_about_y * R != reflection_matrix(frame_plane(f, rational(0))));
  CHECK(transpose(R) * S * R == reflection_matrix(frame_plane(f, rational(0))));
}

// ---- seed 004 ----------------------------------------------------------------------------------

TEST_CASE("seed 004 erratum (a row times a column): (a b c)(x y z)ᵀ is the number ax + by + cz, not (ax, by, cz)",
          "[erratum][seed004]") {
  // (a, b, c) = (1, 1, 0) and (x, y, z) = (1, -1, 0) are perpendicular: the dot product is 0 ...
  const auto n = make_vec4<rational>(1, 1, 0, 0), t = make_vec4<rational>(1, -1, 0, 0);
  CHECK(dot(n, t) == 0);
  // ... while the componentwise product the seed writes, (ax, by, cz) = (1, -1, 0), is not zero.
  const std::array<rational, 3> componentwise{n[0] * t[0], n[1] * t[1], n[2] * t[2]};
  CHECK(componentwise == std::array<rational, 3>{1, -1, 0});
}

TEST_CASE("seed 004 erratum: a 3x3 matrix times a 3x1 column is defined; the row form is its transpose",
          "[erratum][seed004]") {
  // M = S(2, 1, 1): the 3x3 normal matrix G = diag(1/2, 1, 1) times the column n = (1, 1, 0) is the
  // column (1/2, 1, 0) ...
  const mat4<rational> M = scaling<rational>(2, 1, 1);
  const mat4<rational> G = normal_matrix3(M);
  const auto n = make_vec4<rational>(1, 1, 0, 0);
  CHECK(G * n == make_vec4<rational>(q(1, 2), 1, 0, 0));
  // ... and the seed's row form N_p = N_c M_p→c (with M_p→c = M⁻¹) is the same numbers as a row:
  // (N_cᵀ M⁻¹)ᵀ = (M⁻¹)ᵀ N_c = G N_c.
  CHECK(transpose(inverse(M)) * n == G * n);
}

TEST_CASE("seed 004, not an erratum: M^T G = I is sufficient, any non-zero multiple of G keeps normals too",
          "[not_erratum][seed004]") {
  // M = S(2, 1, 1), G' = 2 (M⁻¹)ᵀ: every tangent stays perpendicular to every normal, yet
  // Mᵀ G' = 2 I. The condition forces Mᵀ G = λ I only; λ = 1 is a choice, and a normal's length
  // does not matter, so the seed's result is right.
  const mat4<rational> M = scaling<rational>(2, 1, 1);
  const mat4<rational> G2 = rational(2) * normal_matrix(M);
  const auto t = make_vec4<rational>(1, -1, 0, 0), n = make_vec4<rational>(1, 1, 0, 0);
  CHECK(dot(t, n) == 0);
  CHECK(dot(M * t, G2 * n) == 0);
  CHECK(transpose(M) * G2 == rational(2) * identity4<rational>());
  CHECK(transpose(M) * G2 != identity4<rational>());
}

TEST_CASE("seed 004 erratum: G = (M^-1)^T is not an orthogonal matrix", "[erratum][seed004]") {
  // M = S(2, 1, 1): G = diag(1/2, 1, 1) and GᵀG = diag(1/4, 1, 1) ≠ I.
  const mat4<rational> G = normal_matrix(scaling<rational>(2, 1, 1));
  CHECK(transpose(G) * G == scaling<rational>(q(1, 4), 1, 1));
}

TEST_CASE("seed 004 erratum (column vectors): persp->ortho is projective, not affine", "[erratum][seed004]") {
  // n = -1, f = -2. An affine map has last row (0, 0, 0, 1) and keeps w = 1; persp->ortho sends
  // the eye (0, 0, 0) to (0, 0, -nf, 0) = (0, 0, -2, 0), a point at infinity.
  const mat4<rational> M = games101_persp_to_ortho<rational>(-1, -2);
  CHECK(M * make_point<rational>(0, 0, 0) == make_vec4<rational>(0, 0, -2, 0));
  CHECK(!(M(3, 0) == 0 && M(3, 1) == 0 && M(3, 2) == 0 && M(3, 3) == 1));
}

TEST_CASE("seed 004 erratum (column vectors): rows 1, 2 and 4 of persp->ortho do not follow from the near plane alone",
          "[erratum][seed004]") {
  // n = -1, f = -2. K keeps every near-plane point as the seed asks, (x, y, n, 1) -> n (x, y, n, 1),
  // but its rows 1 and 4 differ from persp->ortho; the far centre rules it out.
  const rational n = -1, f = -2;
  const mat4<rational> K = make_mat4<rational>({n, 0, 1, -n,  //
                                                0, n, 0, 0,   //
                                                0, 0, n + f, -n * f,  //
                                                0, 0, 0, n});
  for (int x = -2; x <= 2; ++x)
    for (int y = -2; y <= 2; ++y) CHECK(K * make_point<rational>(x, y, n) == n * make_point<rational>(x, y, n));
  CHECK(K != games101_persp_to_ortho(n, f));
  CHECK(K * make_point<rational>(0, 0, f) != f * make_point<rational>(0, 0, f));
  CHECK(games101_persp_to_ortho(n, f) * make_point<rational>(0, 0, f) == f * make_point<rational>(0, 0, f));
}

TEST_CASE("seed 004 erratum (column vectors): the box goes onto [-1, 1]^3, not [-2, 2]^3", "[erratum][seed004]") {
  // n = -1, f = -2, fovy = 90° (cot = 1), aspect 1: the near window is [-1, 1]^2 and its corner
  // (1, 1, -1) lands on (1, 1, 1): the scale 2/(r - l) halves the width 2.
  const mat4<rational> P = games101_projection<rational>(-1, -2, 1, 1);
  CHECK(ndc(P, make_point<rational>(1, 1, -1)) == make_point<rational>(1, 1, 1));
  CHECK(ndc(P, make_point<rational>(1, 1, -1)) != make_point<rational>(2, 2, 2));
}

TEST_CASE("seed 004 erratum (column vectors, y up): top = tan(fovy/2)·zNear with GAMES101's negative zNear flips the image",
          "[erratum][seed004]") {
  // n = -1, f = -2, fovy = 90°: tan(fovy/2) = 1, aspect 1. The seed's top = 1·n = -1, so
  // bottom = 1 and the scale 2/(top - bottom) = -1: the top edge of the view (0, 1, -1) lands
  // at NDC y = -1.
  const rational n = -1, f = -2, top = n, right = top;
  const mat4<rational> seed = scaling<rational>(1 / right, 1 / top, 2 / (n - f)) *
                              translation<rational>(0, 0, -(n + f) / 2) * games101_persp_to_ortho(n, f);
  CHECK(ndc(seed, make_point<rational>(0, 1, -1))[1] == -1);
  // With top = -n/c = 1 (the library) it lands at +1.
  CHECK(ndc(games101_projection<rational>(n, f, 1, 1), make_point<rational>(0, 1, -1))[1] == 1);
}
