// Handedness: a left-handed projection sees (x, y, z) as the right-handed one sees (x, y, −z).
#include <catch2/catch.hpp>

#include "shadowproof/constructions/handedness.h"
#include "shadowproof/constructions/project.h"

using namespace shadowproof;

TEST_CASE("a left-handed projection of (x, y, z) is the right-handed one of (x, y, −z)", "[handedness]") {
  const mat4<rational> right = frustum<rational>(-1, 2, -3, 1, 1, 10, depth_convention::d3d);
  const mat4<rational> left = with_handedness(right, handedness::left);
  const vec4<rational> p = make_point<rational>(rational(1, 2), -1, 4);
  const vec4<rational> mirrored = make_point<rational>(rational(1, 2), -1, -4);
  CHECK((left * p).v == (right * mirrored).v);
  // Twice is the identity map on matrices.
  CHECK(with_handedness(left, handedness::left) == right);
  CHECK(with_handedness(right, handedness::right) == right);
}

TEST_CASE("the near plane of a left-handed perspective lies at +n", "[handedness]") {
  // gl depth: z_ndc = −1 at the near plane; left-handed eye space has it at z = +n.
  const mat4<rational> M = with_handedness(perspective<rational>(2, 1, 3, 7, depth_convention::gl), handedness::left);
  const vec4<rational> image = M * make_point<rational>(0, 0, 3);
  CHECK(image[2] / image[3] == -1);
  const vec4<rational> far_image = M * make_point<rational>(0, 0, 7);
  CHECK(far_image[2] / far_image[3] == 1);
}

TEST_CASE("handedness names parse and print", "[handedness]") {
  CHECK(parse_handedness("left") == handedness::left);
  CHECK(to_string(handedness::right) == "right");
  CHECK_THROWS_WITH(parse_handedness("up"),
                    "[shadowproof.project.handedness] unknown handedness 'up': expected right or left");
}
