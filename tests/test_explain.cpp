// Worked derivations with numbers: each ends in the matrix the library builds directly, and the
// numbers along the way are the ones derived by hand.
#include <catch2/catch.hpp>

#include <string>

#include "shadowproof/explain/explain.h"
#include "shadowproof/constructions/basis.h"
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

// ---- point classes ------------------------------------------------------------------------------

TEST_CASE("explain shadow names each point's class with the parameter that decides it", "[explain]") {
  // Light (0, 4, 0), receiver y = 0: s = P·L = 4, w = 1, and λ* = s/(s − t) with t = P·V = V_y.
  const explanation e = explain_shadow(make_plane<rational>(0, 1, 0, 0), make_light<rational>(0, 4, 0, 1),
                                       {make_point<rational>(2, 2, 0), make_point<rational>(-1, -2, 2),
                                        make_point<rational>(1, 6, -2), make_point<rational>(2, 4, -1)});
  const std::string text = to_text(e);
  // t = 2: λ* = 4/2 = 2, beyond V: a real shadow at (0,4,0) + 2 (2,-2,0) = (4, 0, 0).
  CHECK(contains(text, "class shadow: a real shadow"));
  CHECK(contains(text, "λ* = s/(s − w t) = 2 > 1"));
  CHECK(contains(text, "affine image (x/w, y/w, z/w) = (4, 0, 0)"));
  // t = -2: λ* = 4/6 = 2/3, between the light and V: a false shadow.
  CHECK(contains(text, "class behind_receiver: a false shadow"));
  CHECK(contains(text, "λ* = s/(s − w t) = 2/3, between 0 and 1"));
  // t = 6: λ* = 4/(-2) = -2: an anti-shadow beyond the light.
  CHECK(contains(text, "class beyond_light: an anti-shadow"));
  CHECK(contains(text, "λ* = s/(s − w t) = -2 < 0"));
  // t = 4 = s: at infinity.
  CHECK(contains(text, "class at_infinity: at infinity"));
  for (const auto c : {point_class::on_receiver, point_class::shadow, point_class::behind_receiver, point_class::beyond_light,
                       point_class::at_infinity, point_class::at_light, point_class::light_on_plane,
                       point_class::light_parallel, point_class::line_in_plane})
    CHECK_FALSE(std::string(meaning_of(c)).empty());
}

TEST_CASE("explain shadow with a directional light decides the class by mu = t/s", "[explain]") {
  // Light towards (1, 2, 1), receiver y = 1: s = 2. V = (1, 3, 1): t = 2, μ = 1 > 0, a real shadow
  // at V − L = (0, 1, 0). V = (1, -1, 1): t = -2, μ = -1: a false shadow at (2, 1, 2).
  const std::string text = to_text(explain_shadow(make_plane<rational>(0, 1, 0, -1), make_light<rational>(1, 2, 1, 0),
                                                  {make_point<rational>(1, 3, 1), make_point<rational>(1, -1, 1)}));
  CHECK(contains(text, "μ = t/s = 1 > 0: downstream of V"));
  CHECK(contains(text, "affine image (x/w, y/w, z/w) = (0, 1, 0)"));
  CHECK(contains(text, "μ = t/s = -1 < 0: upstream of V"));
  CHECK(contains(text, "affine image (x/w, y/w, z/w) = (2, 1, 2)"));
}

// ---- reflection -----------------------------------------------------------------------------------

TEST_CASE("explain reflect follows a point to its mirror image", "[explain]") {
  // Mirror x + 2y + 2z = 3, X = (3, 1, 2): n·X + d = 6, n·n = 9, X' = X − (12/9)(1, 2, 2) = (5/3, -5/3, -2/3).
  const explanation e = explain_reflection(make_plane<rational>(1, 2, 2, -3), {make_point<rational>(3, 1, 2)});
  CHECK(contains(to_text(e), "X' = X − 2 (n·X + d)/(n·n) n = (5/3, -5/3, -2/3)"));
  CHECK(e.result * make_point<rational>(3, 1, 2) == make_point<rational>(q(5, 3), q(-5, 3), q(-2, 3)));
}

TEST_CASE("explain reflect-frames: seed 003's composition for a rational rotation", "[explain]") {
  // q = (2, -1, -1, 0) has the rows U = (2,1,-2)/3, N = (1,2,2)/3, V = (2,-2,1)/3; with d = 3 the
  // mirror image of (1, 2, 3) is (1,2,3) − 2(11/3 + 3)(1,2,2)/3 = (−31/9, −62/9, −53/9).
  const explanation e = explain_reflection_by_frames({2, -1, -1, 0}, 3, {make_point<rational>(1, 2, 3)});
  const std::string text = to_text(e);
  CHECK(contains(text, "N = (1/3, 2/3, 2/3)"));
  CHECK(contains(text, "T(−dN) · that = (-31/9, -62/9, -53/9, 1) = X'"));
  CHECK(contains(text, "equals the closed form of the mirror (holds)"));
  CHECK(contains(text, "equals the mirror ⟨N, X⟩ − d = 0 (holds)"));
  CHECK(contains(text, "M_rowᵀ = M (holds)"));
  const auto f = frame_from_quaternion<rational>(2, -1, -1, 0);
  CHECK(e.result == reflection_matrix(frame_plane(f, rational(3))));
  CHECK_THROWS_WITH(explain_reflection_by_frames({0, 0, 0, 0}, 1), Catch::Contains("[shadowproof.geometry.zero_quaternion]"));
}

// ---- projections ----------------------------------------------------------------------------------

TEST_CASE("explain perspective rejects a near or far plane that is not in front of the eye", "[explain]") {
  CHECK_THROWS_WITH(explain_perspective_normalization(0, 3), Catch::Contains("[shadowproof.project.near_not_positive]"));
  CHECK_THROWS_WITH(explain_perspective_normalization(-1, 3), Catch::Contains("[shadowproof.project.near_not_positive]"));
  CHECK_THROWS_WITH(explain_perspective_normalization(1, 0), Catch::Contains("[shadowproof.project.far_not_positive]"));
}

TEST_CASE("explain ortho derives A and B as by hand and ends in orthographic", "[explain]") {
  // Box [-2, 2] x [-1, 1] x [-5, -1], gl: A = (−1 − 1)/(5 − 1) = −1/2, B = −1 + A·1 = −3/2.
  const explanation e = explain_orthographic(-2, 2, -1, 1, 1, 5, depth_convention::gl);
  CHECK(contains(to_text(e), "A = ((-1) − 1)/(4) = -1/2"));
  CHECK(contains(to_text(e), "B = (-1) + (-1/2)·1 = -3/2"));
  for (const auto c : {depth_convention::gl, depth_convention::d3d, depth_convention::reverse_z}) {
    const explanation x = explain_orthographic(q(-1, 3), 2, -1, q(1, 2), q(1, 10), 7, c);
    CHECK(x.result == orthographic<rational>(q(-1, 3), 2, -1, q(1, 2), q(1, 10), 7, c));
    CHECK_FALSE(contains(to_text(x), "FAILS"));
  }
  CHECK_THROWS_WITH(explain_orthographic(1, 1, -1, 1, 1, 2, depth_convention::gl),
                    Catch::Contains("[shadowproof.project.degenerate_volume]"));
}

TEST_CASE("explain oblique: the two signs of cot project the same point to opposite sides", "[explain]") {
  // cot θ = 1, cot φ = 0, the point (0, 0, 1): x_p = x + z cot θ = 1 with +cot, x − z cot θ = −1 with −cot.
  const auto X = make_point<rational>(0, 0, 1);
  const explanation plus = explain_oblique(1, 0, cot_sign::plus, std::nullopt, {X});
  const explanation minus = explain_oblique(1, 0, cot_sign::minus, std::nullopt, {X});
  CHECK(plus.result * X == make_point<rational>(1, 0, 0));
  CHECK(minus.result * X == make_point<rational>(-1, 0, 0));
  CHECK(minus.result == oblique_parallel_projection<rational>(1, 0));
  CHECK(plus.result == oblique_parallel_projection<rational>(-1, 0));
  CHECK(contains(to_text(plus), "H projector = (0, 0, -1, 0) (holds)"));
  CHECK(contains(to_text(minus), "H projector = (0, 0, 1, 0) (holds)"));
  const view_box box{-2, 6, -1, 3, q(1, 2), 5, depth_convention::d3d};
  const explanation kept = explain_oblique(q(2, 3), q(-1, 5), cot_sign::minus, box);
  CHECK(kept.result == oblique<rational>(-2, 6, -1, 3, q(1, 2), 5, q(2, 3), q(-1, 5), depth_convention::d3d));
  CHECK_FALSE(contains(to_text(kept), "FAILS"));
  CHECK(explain_oblique(q(2, 3), q(-1, 5), cot_sign::plus, box).result ==
        oblique<rational>(-2, 6, -1, 3, q(1, 2), 5, q(-2, 3), q(1, 5), depth_convention::d3d));
  CHECK(parse_cot_sign("plus") == cot_sign::plus);
  CHECK_THROWS_WITH(parse_cot_sign("sideways"), Catch::Contains("[shadowproof.explain.cot_sign]"));
}

TEST_CASE("explain games101 solves the third row as by hand and ends in games101_projection", "[explain]") {
  // n = −1, f = −4: A = n + f = −5, B = −nf = −4; with c = 1 the window's top is −n/c = 1.
  const explanation e = explain_games101(-1, -4, 1, q(4, 3), {make_point<rational>(q(1, 2), q(1, 4), -2)});
  const std::string text = to_text(e);
  CHECK(contains(text, "A = -5, B = -4"));
  CHECK(contains(text, "top = 1, right = 4/3"));
  CHECK_FALSE(contains(text, "FAILS"));
  CHECK(e.result == games101_projection<rational>(-1, -4, 1, q(4, 3)));
  CHECK_THROWS_WITH(explain_games101(1, -4, 1, 1), Catch::Contains("[shadowproof.project.games101_sign]"));
}

// ---- change of basis ------------------------------------------------------------------------------

TEST_CASE("explain change-of-basis walks a child point to the parent", "[explain]") {
  // Axes (0,1,0), (-1,0,0), (0,0,1) at (2, 1, 0): the child point (1, 1, 0) is
  // (2,1,0) + (0,1,0) + (-1,0,0) = (1, 2, 0); the axes are orthonormal, so the shortcut is exact.
  const explanation e = explain_change_of_basis({0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {2, 1, 0}, {make_point<rational>(1, 1, 0)});
  const std::string text = to_text(e);
  CHECK(contains(text, "M_c→p (a, b, c, 1) = (1, 2, 0, 1)"));
  CHECK(contains(text, "equals the inverse (holds)"));
  CHECK(e.result == child_to_parent<rational>({0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {2, 1, 0}));
  // Scaled axes: the inverse is exact, the transpose shortcut is not.
  CHECK(contains(to_text(explain_change_of_basis({2, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0})), "shortcut = inverse: no"));
  CHECK_THROWS_WITH(explain_change_of_basis({1, 0, 0}, {2, 0, 0}, {0, 0, 1}, {0, 0, 0}),
                    Catch::Contains("[shadowproof.matrix.singular]"));
}

TEST_CASE("explain normal-matrix follows a normal by G and by M", "[explain]") {
  // M = S(2, 1, 1), n = (1, 1, 0): G n = (1/2, 1, 0), M n = (2, 1, 0), which M would get wrong.
  const std::string text = to_text(explain_normal_matrix(scaling<rational>(2, 1, 1), {make_vec4<rational>(1, 1, 0, 0)}));
  CHECK(contains(text, "G n = (1/2, 1, 0)"));
  CHECK(contains(text, "M n = (2, 1, 0) (a different direction"));
}

// ---- figures ---------------------------------------------------------------------------------------

TEST_CASE("every explanation draws its case, from its exact numbers, the same bytes every time", "[explain][figure]") {
  const auto V = make_point<rational>(2, 2, 0);
  const std::vector<explanation> all = {
      explain_shadow(make_plane<rational>(0, 1, 0, 0), make_light<rational>(0, 4, 0, 1), {V}),
      explain_shadow(make_plane<rational>(0, 1, 0, -1), make_light<rational>(1, 2, 1, 0), {make_point<rational>(1, 3, 1)}),
      explain_reflection(make_plane<rational>(1, 2, 2, -3), {make_point<rational>(3, 1, 2)}),
      explain_reflection_by_frames({2, -1, -1, 0}, 3, {make_point<rational>(1, 2, 3)}),
      explain_perspective_normalization(1, 3),
      explain_frustum(-1, 1, -1, 1, 1, 4, depth_convention::reverse_z, true),
      explain_orthographic(-2, 2, -1, 1, 1, 5, depth_convention::gl),
      explain_oblique(1, 0, cot_sign::plus, std::nullopt),
      explain_games101(-1, -4, 1, 1),
      explain_normal_matrix(scaling<rational>(2, 1, 1)),
      explain_change_of_basis({0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {2, 1, 0})};
  for (const auto& e : all) {
    INFO(e.title);
    CHECK_FALSE(e.picture.empty());
    const std::string svg = to_svg(e.picture);
    CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    CHECK(svg == to_svg(e.picture));
    CHECK(contains(svg, "</svg>"));
    CHECK_FALSE(e.picture.caption.empty());
  }
  // The labels carry the exact numbers: the real shadow of (2, 2, 0) is (4, 0, 0).
  CHECK(contains(to_svg(all[0].picture), "real shadow (4, 0, 0)"));
  CHECK(contains(all[0].picture.caption, "$V = (2, 2, 0)$: real shadow at $(4, 0, 0)$"));
  CHECK(contains(to_svg(all[3].picture), "X' = (-31/9, -62/9, -53/9)"));
}
