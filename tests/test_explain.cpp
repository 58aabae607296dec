// Worked derivations with numbers: each ends in the matrix the library builds directly, and the
// numbers along the way are the ones derived by hand.
#include <catch2/catch.hpp>

#include <string>

#include "shadowproof/explain/explain.h"
#include "shadowproof/constructions/normal_matrix.h"
#include "shadowproof/constructions/reflect.h"
#include "shadowproof/constructions/shadow.h"

using namespace shadowproof;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

rational q(long n, long d = 1) { return rational(n, d); }

}  // namespace

TEST_CASE("explain shadow: the README example, derived by hand", "[explain]") {
  // P = (0,1,0,0), L = (2,5,1,1): P·L = 5 and L Pᵀ has L as its second column.
  const auto P = make_plane<rational>(0, 1, 0, 0);
  const auto L = make_light<rational>(2, 5, 1, 1);
  const explanation e = explain_shadow(P, L, {make_point<rational>(1, 2, 3)});
  CHECK(e.result == make_mat4<rational>({5, -2, 0, 0, 0, 0, 0, 0, 0, -1, 5, 0, 0, -1, 0, 5}));
  const std::string text = to_text(e);
  CHECK(contains(text, "P·L = 0·2 + 1·5 + 0·1 + 0·1 = 5"));
  // V = (1,2,3): P·V = 2, k = -2/5, V + kL = (1/5, 0, 13/5, 3/5), affine (1/3, 0, 13/3).
  CHECK(contains(text, "k = −(P·V)/(P·L) = −(2)/(5) = -2/5"));
  CHECK(contains(text, "V + kL = (1/5, 0, 13/5, 3/5)"));
  CHECK(contains(text, "affine image (x/w, y/w, z/w) = (1/3, 0, 13/3)"));
  CHECK(contains(text, "Pᵀ M = (0, 0, 0, 0) (holds)"));
  CHECK(contains(text, "[ 5 -2  0  0 ]"));
}

TEST_CASE("explain shadow ends in shadow_matrix for point, directional and degenerate lights", "[explain]") {
  const std::vector<std::pair<plane<rational>, light<rational>>> cases = {
      {make_plane<rational>(0, 1, 0, 0), make_light<rational>(2, 5, 1, 1)},
      {make_plane<rational>(1, 2, -3, q(1, 2)), make_light<rational>(q(-1, 3), 4, 2, 0)},
      {make_plane<rational>(0, 1, 0, -1), make_light<rational>(4, 10, 2, 2)},     // w = 2
      {make_plane<rational>(0, 1, 0, 0), make_light<rational>(-2, -5, -1, -1)},  // w < 0
      {make_plane<rational>(0, 1, 0, 0), make_light<rational>(1, 0, 0, 0)},      // parallel
      {make_plane<rational>(0, 1, 0, 0), make_light<rational>(3, 0, 1, 1)},      // light on plane
  };
  for (const auto& [P, L] : cases) {
    const explanation e = explain_shadow(P, L, {make_point<rational>(1, 2, 3), make_point<rational>(0, 0, 0)});
    CHECK(e.result == shadow_matrix(P, L));
    CHECK_FALSE(contains(to_text(e), "FAILS"));
  }
}

TEST_CASE("explain shadow calls P·L = 0 a degenerate result, not an error", "[explain]") {
  const explanation e = explain_shadow(make_plane<rational>(0, 1, 0, 0), make_light<rational>(1, 0, 0, 0));
  const std::string text = to_text(e);
  CHECK(contains(text, "P·L = 0: the light is parallel to the plane"));
  CHECK(contains(text, "rank 1"));
}

TEST_CASE("explain reflect: the mirror y = 1 sends the origin to (0, 2, 0)", "[explain]") {
  const explanation e = explain_reflection(make_plane<rational>(0, 1, 0, -1));
  CHECK(e.result == make_mat4<rational>({1, 0, 0, 0, 0, -1, 0, 2, 0, 0, 1, 0, 0, 0, 0, 1}));
  const std::string text = to_text(e);
  CHECK(contains(text, "n·n = 0·0 + 1·1 + 0·0 = 1"));
  CHECK(contains(text, "M M = I (holds)"));
  CHECK(contains(text, "det M = -1"));
}

TEST_CASE("explain reflect ends in reflection_matrix", "[explain]") {
  for (const auto& P : {make_plane<rational>(1, 2, 2, -3), make_plane<rational>(q(1, 3), -1, 5, 7),
                        make_plane<rational>(0, 0, -2, 0)}) {
    const explanation e = explain_reflection(P);
    CHECK(e.result == reflection_matrix(P));
    CHECK_FALSE(contains(to_text(e), "FAILS"));
  }
}

TEST_CASE("explain perspective solves alpha and beta as by hand", "[explain]") {
  // n = 1, f = 3: alpha = (1+3)/(1-3) = -2, beta = 2*1*3/(1-3) = -3.
  const explanation e = explain_perspective_normalization(1, 3);
  CHECK(e.result == make_mat4<rational>({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0}));
  const std::string text = to_text(e);
  CHECK(contains(text, "det = (-1)·1 − 1·(-3) = 2"));
  CHECK(contains(text, "= -2\n"));
  CHECK(contains(text, "near: N (0, 0, -1, 1) = (0, 0, -1, 1), depth -1 (holds)"));
  CHECK(contains(text, "far: N (0, 0, -3, 1) = (0, 0, 3, 3), depth 1 (holds)"));
}

TEST_CASE("explain perspective ends in perspective_normalization", "[explain]") {
  for (const auto& [n, f] : {std::pair{q(1), q(100)}, std::pair{q(1, 10), q(7, 3)}, std::pair{q(5), q(2)}})
    CHECK(explain_perspective_normalization(n, f).result == perspective_normalization(n, f));
  CHECK_THROWS_WITH(explain_perspective_normalization(2, 2), Catch::Contains("[shadowproof.project.degenerate_volume]"));
}

TEST_CASE("explain frustum ends in frustum for every convention, finite and infinite far", "[explain]") {
  for (const auto c : {depth_convention::gl, depth_convention::d3d, depth_convention::reverse_z})
    for (const bool infinite : {false, true}) {
      const explanation e = explain_frustum(-1, 2, q(-1, 2), 1, q(1, 2), 10, c, infinite);
      CHECK(e.result == frustum<rational>(-1, 2, q(-1, 2), 1, q(1, 2), 10, c, infinite));
      CHECK_FALSE(contains(to_text(e), "FAILS"));
      CHECK(contains(to_text(e), "(holds)"));
    }
  CHECK_THROWS_WITH(explain_frustum(1, 1, -1, 1, 1, 10, depth_convention::gl, false),
                    Catch::Contains("[shadowproof.project.degenerate_volume]"));
}

TEST_CASE("explain normal-matrix: a stretch by 2 in x halves the normal's x", "[explain]") {
  const auto M = make_mat4<rational>({2, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  const explanation e = explain_normal_matrix(M);
  // (M⁻¹)ᵀ of [diag(2,1,1) t; 0 1] is [diag(1/2,1,1) 0; -tᵀ diag(1/2,1,1) 1] with t = (5,0,0).
  CHECK(e.result == make_mat4<rational>({q(1, 2), 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, q(-5, 2), 0, 0, 1}));
  const std::string text = to_text(e);
  CHECK(contains(text, "= 2\n"));
  CHECK(contains(text, "Mᵀ G = I (holds)"));
  CHECK(contains(text, "M is affine"));
}

TEST_CASE("explain normal-matrix ends in normal_matrix and rejects a singular matrix", "[explain]") {
  const auto shear = make_mat4<rational>({1, q(1, 2), 0, 0, 0, 1, 0, 0, 3, 0, 2, 1, 0, 0, 0, 1});
  CHECK(explain_normal_matrix(shear).result == normal_matrix(shear));
  const auto projective = make_mat4<rational>({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0});
  CHECK(explain_normal_matrix(projective).result == normal_matrix(projective));
  CHECK_FALSE(contains(to_text(explain_normal_matrix(projective)), "M is affine"));
  const auto flat = make_mat4<rational>({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1});
  CHECK_THROWS_WITH(explain_normal_matrix(flat), Catch::Contains("[shadowproof.matrix.singular]"));
}
