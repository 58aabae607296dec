// A user's program: the shadow of (1,2,3) from the light (2,5,1) on y = 0 is (1/3, 0, 13/3).
#include <shadowproof/number.h>
#include <shadowproof/shadow.h>

#include <iostream>

int main() {
  using namespace shadowproof;
  const auto image = shadow_matrix(make_plane<rational>(0, 1, 0, 0), make_light<rational>(2, 5, 1, 1)) *
                     make_point<rational>(1, 2, 3);
  std::cout << to_string(image[0] / image[3]) << ' ' << to_string(image[1] / image[3]) << ' '
            << to_string(image[2] / image[3]) << '\n';
  return to_string(parse_number("0.1")) == "1/10" ? 0 : 1;
}
