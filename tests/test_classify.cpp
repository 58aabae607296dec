// Exact classification of a point under a receiver plane and a light.
#include <catch2/catch.hpp>

#include "shadowproof/constructions/classify.h"
#include "shadowproof/constructions/shadow.h"
#include "support/random_exact.h"

using namespace shadowproof;
using shadowproof::testing::random_exact;

namespace {

const plane<rational> ground = make_plane<rational>(0, 1, 0, 0);

point_class class_of(const light<rational>& L, rational x, rational y, rational z) {
  return classify_point(ground, L, make_point(x, y, z));
}

}  // namespace

TEST_CASE("a point light over the ground reaches every class at hand-picked points", "[classify]") {
  const auto L = make_light<rational>(2, 5, 1, 1);  // light at height 5
  CHECK(class_of(L, 7, 0, -3) == point_class::on_receiver);
  CHECK(class_of(L, 0, 1, 0) == point_class::shadow);
  CHECK(class_of(L, 0, rational(49, 10), 0) == point_class::shadow);
  CHECK(class_of(L, 1, -1, 1) == point_class::behind_receiver);
  CHECK(class_of(L, 0, 7, 0) == point_class::beyond_light);
  CHECK(class_of(L, -1, 5, 0) == point_class::at_infinity);
  CHECK(class_of(L, 2, 5, 1) == point_class::at_light);
}

TEST_CASE("the classes match what the matrix does to each point", "[classify]") {
  const auto L = make_light<rational>(2, 5, 1, 1);
  const auto M = shadow_matrix(ground, L);
  CHECK(M * make_point<rational>(7, 0, -3) == make_vec4<rational>(35, 0, -15, 5));  // V itself, scaled by 5
  CHECK((M * make_point<rational>(-1, 5, 0))[3] == 0);                                // at infinity
  CHECK(is_zero(M * make_point<rational>(2, 5, 1)));                                  // at the light
}

TEST_CASE("a light below the receiver mirrors the classes", "[classify]") {
  const auto L = make_light<rational>(0, -4, 0, 1);
  CHECK(class_of(L, 3, -1, 0) == point_class::shadow);
  CHECK(class_of(L, 3, 1, 0) == point_class::behind_receiver);
  CHECK(class_of(L, 3, -6, 0) == point_class::beyond_light);
  CHECK(class_of(L, 3, -4, 0) == point_class::at_infinity);
  CHECK(class_of(L, 0, -4, 0) == point_class::at_light);
}

TEST_CASE("w = 2 and w = -3 name the same point light and give the same classes", "[classify]") {
  const auto L1 = make_light<rational>(2, 5, 1, 1);
  const auto L2 = make_light<rational>(4, 10, 2, 2);
  const auto L3 = make_light<rational>(-6, -15, -3, -3);
  for (const auto& V : {make_point<rational>(0, 1, 0), make_point<rational>(1, -1, 1), make_point<rational>(0, 7, 0),
                        make_point<rational>(-1, 5, 0), make_point<rational>(2, 5, 1), make_point<rational>(7, 0, -3)}) {
    const auto expected = classify_point(ground, L1, V);
    CHECK(classify_point(ground, L2, V) == expected);
    CHECK(classify_point(ground, L3, V) == expected);
  }
  CHECK(classify_point(ground, L3, make_point<rational>(0, 1, 0)) == point_class::shadow);
  CHECK(classify_point(ground, L3, make_point<rational>(2, 5, 1)) == point_class::at_light);
}

TEST_CASE("a directional light casts from above and falsely from below", "[classify]") {
  const auto towards_sky = make_light<rational>(1, 2, 1, 0);
  CHECK(class_of(towards_sky, 0, 1, 0) == point_class::shadow);
  CHECK(class_of(towards_sky, 0, 1000, 0) == point_class::shadow);  // no light height to pass
  CHECK(class_of(towards_sky, 0, -1, 0) == point_class::behind_receiver);
  CHECK(class_of(towards_sky, 5, 0, 5) == point_class::on_receiver);
  // The opposite direction is the opposite light: the classes swap.
  const auto towards_ground = make_light<rational>(-1, -2, -1, 0);
  CHECK(class_of(towards_ground, 0, 1, 0) == point_class::behind_receiver);
  CHECK(class_of(towards_ground, 0, -1, 0) == point_class::shadow);
}

TEST_CASE("a point light on the receiver sends every point off the plane to itself", "[classify][degenerate]") {
  const auto L = make_light<rational>(3, 0, 1, 1);
  CHECK(class_of(L, 0, 2, 0) == point_class::light_on_plane);
  CHECK(class_of(L, 0, -2, 0) == point_class::light_on_plane);
  const auto image = shadow_matrix(ground, L) * make_point<rational>(0, 2, 0);
  CHECK(proportional(image, L.l));
  CHECK(class_of(L, 5, 0, 5) == point_class::line_in_plane);
  CHECK(class_of(L, 3, 0, 1) == point_class::line_in_plane);  // the light itself, on the plane
  CHECK(is_zero(shadow_matrix(ground, L) * make_point<rational>(5, 0, 5)));
}

TEST_CASE("a light parallel to the receiver sends every point off the plane to infinity", "[classify][degenerate]") {
  const auto L = make_light<rational>(1, 0, 2, 0);
  CHECK(class_of(L, 0, 2, 0) == point_class::light_parallel);
  CHECK(class_of(L, 0, -3, 0) == point_class::light_parallel);
  const auto image = shadow_matrix(ground, L) * make_point<rational>(0, 2, 0);
  CHECK(image[3] == 0);
  CHECK(proportional(image, L.l));
  CHECK(class_of(L, 4, 0, 1) == point_class::line_in_plane);
}

TEST_CASE("class names are stable", "[classify]") {
  CHECK(to_string(point_class::on_receiver) == "on_receiver");
  CHECK(to_string(point_class::shadow) == "shadow");
  CHECK(to_string(point_class::behind_receiver) == "behind_receiver");
  CHECK(to_string(point_class::beyond_light) == "beyond_light");
  CHECK(to_string(point_class::at_infinity) == "at_infinity");
  CHECK(to_string(point_class::at_light) == "at_light");
  CHECK(to_string(point_class::light_on_plane) == "light_on_plane");
  CHECK(to_string(point_class::light_parallel) == "light_parallel");
  CHECK(to_string(point_class::line_in_plane) == "line_in_plane");
}

// Independent of classify_point's formula: locate the image on the ray from the light through
// V, Q = ℓ + u (V − ℓ). u > 1: Q is past V (a real shadow); 0 < u < 1: Q between the light and
// V (V is behind the receiver); u < 0: Q on the other side of the light (anti-shadow).
TEST_CASE("classes agree with where the image sits on the ray from the light", "[classify][property]") {
  random_exact r(11);
  int seen_shadow = 0, seen_behind = 0, seen_beyond = 0;
  for (int i = 0; i < 2000; ++i) {
    const auto P = r.plane_();
    const auto L = r.point_light();
    const auto V = r.point();
    const auto c = classify_point(P, L, V);
    const auto Q = shadow_matrix(P, L) * V;
    if (Q[3] == 0 || is_zero(Q)) {
      CHECK((c == point_class::at_infinity || c == point_class::at_light || c == point_class::light_on_plane ||
             c == point_class::line_in_plane));
      continue;
    }
    if (dot(P.p, L.l) == 0) continue;
    const vec4<rational> light_point = rational(1) / L.l[3] * L.l;
    std::size_t axis = 0;
    while (axis < 3 && V[axis] == light_point[axis]) ++axis;
    REQUIRE(axis < 3);
    const rational u = (Q[axis] / Q[3] - light_point[axis]) / (V[axis] - light_point[axis]);
    if (u == 1) {
      CHECK(c == point_class::on_receiver);
    } else if (u > 1) {
      CHECK(c == point_class::shadow);
      ++seen_shadow;
    } else if (u > 0) {
      CHECK(c == point_class::behind_receiver);
      ++seen_behind;
    } else {
      CHECK(c == point_class::beyond_light);
      ++seen_beyond;
    }
  }
  CHECK(seen_shadow > 100);
  CHECK(seen_behind > 100);
  CHECK(seen_beyond > 100);
}

TEST_CASE("directional classes agree with the direction of travel to the receiver", "[classify][property]") {
  random_exact r(12);
  for (int i = 0; i < 1000; ++i) {
    const auto P = r.plane_();
    const auto L = r.directional_light();
    const auto V = r.point();
    const auto c = classify_point(P, L, V);
    if (dot(P.p, L.l) == 0) continue;
    const auto Q = shadow_matrix(P, L) * V;
    // Q/w = V + u·dir: u < 0 means the shadow lies away from the light (a real shadow).
    std::size_t axis = 0;
    while (L.l[axis] == 0) ++axis;
    const rational u = (Q[axis] / Q[3] - V[axis]) / L.l[axis];
    if (u == 0) CHECK(c == point_class::on_receiver);
    else CHECK(c == (u < 0 ? point_class::shadow : point_class::behind_receiver));
  }
}

TEMPLATE_TEST_CASE("the float instances classify simple integer configurations the same way", "[classify]", double, float) {
  using T = TestType;
  const auto P = make_plane<T>(0, 1, 0, 0);
  const auto L = make_light<T>(2, 5, 1, 1);
  CHECK(classify_point(P, L, make_point<T>(0, 1, 0)) == point_class::shadow);
  CHECK(classify_point(P, L, make_point<T>(-1, 5, 0)) == point_class::at_infinity);
  CHECK(classify_point(P, L, make_point<T>(0, 7, 0)) == point_class::beyond_light);
}
