// Enclosures of cot(fovy/2) and square roots, and their correct rounding by Ziv's strategy.
#include <catch2/catch.hpp>

#include <cmath>

#include "shadowproof/constructions/irrational.h"

using namespace shadowproof;

TEST_CASE("cot(fovy/2) enclosures contain the value and shrink with precision", "[irrational]") {
  // fovy = 1/2: cot(1/4) = 3.91631736464594…, from the C library's long double tan (independent).
  const long double expected = 1.0L / std::tan(0.25L);
  for (long p : {64L, 128L, 256L}) {
    const enclosure e = cot_half_angle(0.5, angle_unit::radians, p);
    CHECK(e.lo < e.hi);
    CHECK(e.lo.get_d() <= static_cast<double>(expected) * (1 + 1e-15));
    CHECK(e.hi.get_d() >= static_cast<double>(expected) * (1 - 1e-15));
    // The width is a few units of the p-bit last place of a number near 4.
    const rational width = e.hi - e.lo;
    CHECK(width <= rational(mpz_class(1), mpz_class(1) << static_cast<unsigned>(p - 4)));
  }
  // Degrees: 90° is exactly 1 inside every enclosure; 60° is √3.
  const enclosure right = cot_half_angle(90, angle_unit::degrees, 128);
  CHECK(right.lo <= 1);
  CHECK(right.hi >= 1);
  const enclosure sixty = cot_half_angle(60, angle_unit::degrees, 128);
  CHECK(sixty.lo * sixty.lo < 3);
  CHECK(sixty.hi * sixty.hi > 3);
}

TEST_CASE("the field of view is in range exactly when 0 < fovy < a half turn", "[irrational]") {
  CHECK(field_of_view_in_range(1.0, angle_unit::radians));
  CHECK(field_of_view_in_range(3.141592653589793, angle_unit::radians));   // the double just below π
  CHECK_FALSE(field_of_view_in_range(3.1415926535897936, angle_unit::radians));  // the double above π
  CHECK_FALSE(field_of_view_in_range(0.0, angle_unit::radians));
  CHECK_FALSE(field_of_view_in_range(-1.0, angle_unit::radians));
  CHECK(field_of_view_in_range(179.99998474121094, angle_unit::degrees));
  CHECK_FALSE(field_of_view_in_range(180.0, angle_unit::degrees));
}

TEST_CASE("exact square roots of rationals are found, and only those", "[irrational]") {
  CHECK(exact_sqrt(rational(9, 4)) == rational(3, 2));
  CHECK(exact_sqrt(rational(0)) == rational(0));
  CHECK_FALSE(exact_sqrt(rational(2)).has_value());
  CHECK_FALSE(exact_sqrt(rational(9, 8)).has_value());
  CHECK_THROWS_AS(exact_sqrt(rational(-1)), internal_error);
}

TEST_CASE("a correctly rounding representative rounds as IEEE sqrt does", "[irrational]") {
  // IEEE 754 square roots are correctly rounded: sqrtf and sqrt are an independent oracle.
  for (int q : {2, 3, 5, 7, 10, 1000003}) {
    const rational m = signed_sqrt_representative(1, rational(q));
    CHECK(to_nearest_float(m) == std::sqrt(static_cast<float>(q)));
    CHECK(to_nearest_double(m) == std::sqrt(static_cast<double>(q)));
    const rational neg = signed_sqrt_representative(-1, rational(q));
    CHECK(to_nearest_double(neg) == -std::sqrt(static_cast<double>(q)));
  }
  // A rational root is exact, and 1/√2 rounds as sqrt(1/2).
  CHECK(signed_sqrt_representative(-1, rational(1, 4)) == rational(-1, 2));
  CHECK(to_nearest_float(signed_sqrt_representative(1, rational(1, 2))) == std::sqrt(0.5f));
}

TEST_CASE("Ziv's loop stops at the first precision that decides, and refuses to guess", "[irrational]") {
  int calls = 0;
  const rational m = correctly_rounding_representative(
      [&](long p) {
        ++calls;
        return sqrt_enclosure(rational(2), p);
      },
      "sqrt 2");
  CHECK(calls == 1);  // 64 bits decide √2 for float and double
  CHECK(to_nearest_double(m) == std::sqrt(2.0));
  // An enclosure that never shrinks past a rounding boundary (1 ± 2^-60 around the double
  // midpoint 1 + 2^-53) is reported, never rounded one way or the other.
  const rational midpoint = rational(1) + rational(mpz_class(1), mpz_class(1) << 53);
  const rational eps(mpz_class(1), mpz_class(1) << 60);
  CHECK_THROWS_AS(correctly_rounding_representative([&](long) { return enclosure{midpoint - eps, midpoint + eps}; },
                                                    "a midpoint"),
                  internal_error);
}
