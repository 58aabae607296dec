// A user's program, built against an installed shadowproof through find_package. It uses one
// entry point of each installed library: the exact shadow of (1,2,3) from the light (2,5,1) on
// y = 0 is (1/3, 0, 13/3); the built-in implementations grade their own correctly rounded
// answer as 0 ulps; a unit square at height 1 over the ground under a vertical sun casts a
// shadow of area 1.
#include <shadowproof/clip/scene.h>
#include <shadowproof/clip/shadow_region.h>
#include <shadowproof/constructions/shadow.h>
#include <shadowproof/core/number.h>
#include <shadowproof/impls/builtin.h>
#include <shadowproof/verify/grade.h>

#include <iostream>
#include <vector>

int main() {
  using namespace shadowproof;
  const auto image = shadow_matrix(make_plane<rational>(0, 1, 0, 0), make_light<rational>(2, 5, 1, 1)) *
                     make_point<rational>(1, 2, 3);
  std::cout << to_string(image[0] / image[3]) << ' ' << to_string(image[1] / image[3]) << ' '
            << to_string(image[2] / image[3]) << '\n';

  // Ground y = 0 and the sun straight above: M = diag(1, 0, 1, 1) · (P·L) − L Pᵀ with P·L = 1,
  // i.e. the identity with row 1 zeroed; every entry is exact in float.
  const implementation& impl = find_builtin_implementation("seed000-general-f32");
  test_case c{0, operation::shadow_matrix, scalar_type::f32, input_class::regular, {0, 1, 0, 0, 0, 1, 0, 0}};
  const double exact[16] = {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const case_grade g = grade_case(c, impl.conv, exact);
  std::cout << builtin_implementations().size() << " implementations, " << g.max_ulps << " ulps\n";

  scene s;
  s.receiver.outer.vertices = {{0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}};
  s.light_source = make_light<rational>(0, 1, 0, 0);
  caster square;
  square.name = "square";
  square.is_polygon = true;
  square.vertices = {{1, 1, 1}, {2, 1, 1}, {2, 1, 2}, {1, 1, 2}};
  square.faces = {{0, 1, 2, 3}};
  s.casters.push_back(square);
  std::cout << "area² " << to_string(compute_shadow_region(s).area_squared) << '\n';
  return to_string(parse_number("0.1")) == "1/10" ? 0 : 1;
}
