// Distances between floats: ulps, bits of error, bit-exact hex text.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "shadowproof/core/number.h"
#include "shadowproof/core/ulp.h"

using namespace shadowproof;

TEST_CASE("neighbouring floats are one ulp apart, in both directions", "[ulp]") {
  const float one = 1.0f;
  CHECK(ulp_distance(one, std::nextafter(one, 2.0f)) == 1);
  CHECK(ulp_distance(std::nextafter(one, 2.0f), one) == 1);
  CHECK(ulp_distance(one, std::nextafter(one, 0.0f)) == 1);
  const double d = 3.0;
  CHECK(ulp_distance(d, std::nextafter(std::nextafter(d, 4.0), 4.0)) == 2);
}

TEST_CASE("the ulp line is continuous through zero and ignores the sign of zero", "[ulp]") {
  const float tiny = std::numeric_limits<float>::denorm_min();
  CHECK(ulp_distance(0.0f, -0.0f) == 0);
  CHECK(ulp_distance(-tiny, tiny) == 2);
  CHECK(ulp_distance(0.0, std::numeric_limits<double>::denorm_min()) == 1);
  // 1.0f is 0x3f800000: that many representable floats lie in (0, 1].
  CHECK(ulp_distance(0.0f, 1.0f) == 0x3f800000u);
  CHECK(ulp_distance(-1.0f, 1.0f) == 2u * 0x3f800000u);
}

TEST_CASE("bits of error are log2(ulps + 1)", "[ulp]") {
  CHECK(bits_of_error(0) == 0.0);
  CHECK(bits_of_error(1) == 1.0);
  CHECK(bits_of_error(3) == 2.0);
  CHECK(bits_of_error(1023) == 10.0);
}

TEST_CASE("hex text reads back bit for bit", "[ulp]") {
  CHECK(hex_string(1.5) == "0x1.8p+0");
  CHECK(hex_string(-0.0) == "-0x0p+0");
  CHECK(hex_string(std::numeric_limits<double>::infinity()) == "inf");
  CHECK(hex_string(-std::numeric_limits<double>::infinity()) == "-inf");
  CHECK(hex_string(std::nan("")) == "nan");
  for (double x : {0.1, 1e-310, 123456.789, static_cast<double>(0.1f), -std::numeric_limits<double>::max()})
    CHECK(parse_number(hex_string(x)) == exact_value(x));
}
