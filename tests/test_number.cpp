// Exact number layer: parsing every accepted syntax, rejecting everything else, printing, and
// correct rounding to float and double.
#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>

#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"

using namespace shadowproof;

namespace {

rational pow2(int e) {
  rational r = 1;
  mpz_class p = 1;
  p <<= static_cast<unsigned>(e < 0 ? -e : e);
  return e < 0 ? rational(1, 1) / rational(p) : rational(p);
}

std::string error_id_of(const std::string& text, const number_limits& limits = {}) {
  try {
    parse_number(text, limits);
  } catch (const error& e) {
    return e.id();
  }
  return "no error";
}

}  // namespace

TEST_CASE("integers, decimals, fractions and hex floats are read exactly", "[number]") {
  CHECK(parse_number("42") == 42);
  CHECK(parse_number("-7") == -7);
  CHECK(parse_number("+7") == 7);
  CHECK(parse_number("0.1") == rational(1, 10));
  CHECK(parse_number("-2.5e-3") == rational(-1, 400));
  CHECK(parse_number("1.5E+2") == 150);
  CHECK(parse_number("1e3") == 1000);
  CHECK(parse_number(".5") == rational(1, 2));
  CHECK(parse_number("5.") == 5);
  CHECK(parse_number("000120.0500") == rational(2401, 20));
  CHECK(parse_number("1/3") == rational(1, 3));
  CHECK(parse_number("-4/6") == rational(-2, 3));
  CHECK(parse_number("0x1.8p-3") == rational(3, 16));
  CHECK(parse_number("0x10") == 16);
  CHECK(parse_number("-0X.8P1") == -1);
  CHECK(parse_number("0xA.Cp0") == rational(43, 4));
  CHECK(parse_number("0e999999999999") == 0);
}

TEST_CASE("f32: and f64: take the nearest float or double bit-exactly", "[number]") {
  // 0.1f = 13421773 · 2^-27 and 0.1 = 3602879701896397 · 2^-55 (IEEE 754 round to nearest).
  CHECK(parse_number("f32:0.1") == rational(13421773) * pow2(-27));
  CHECK(parse_number("f64:0.1") == rational(mpz_class("3602879701896397")) * pow2(-55));
  CHECK(parse_number("f32:0.5") == rational(1, 2));
  CHECK(parse_number("f32:1/3") == rational(11184811) * pow2(-25));
  CHECK(parse_number("f32:1e-50") == 0);  // underflows to zero: finite, accepted
}

TEST_CASE("the printer writes canonical exact rationals", "[number]") {
  CHECK(to_string(rational(7, 3)) == "7/3");
  CHECK(to_string(rational(-8, 2)) == "-4");
  CHECK(to_string(rational(0)) == "0");
  CHECK(to_string(parse_number("0.25")) == "1/4");
}

TEST_CASE("rounding to double is correct where mpq_get_d truncates", "[number][rounding]") {
  const rational tenth(1, 10);
  CHECK(to_nearest_double(tenth) == 0.1);
  // GMP's own conversion truncates towards zero: one ulp below the nearest double.
  CHECK(mpq_get_d(tenth.get_mpq_t()) == std::nextafter(0.1, 0.0));
  CHECK(to_nearest_float(tenth) == 0.1f);
}

TEST_CASE("halfway cases round to even, in normal and subnormal range", "[number][rounding]") {
  CHECK(to_nearest_double(1 + pow2(-53)) == 1.0);
  CHECK(to_nearest_double(1 + 3 * pow2(-53)) == 1.0 + std::ldexp(1.0, -51));
  CHECK(to_nearest_double(pow2(-1074)) == std::numeric_limits<double>::denorm_min());
  CHECK(to_nearest_double(pow2(-1075)) == 0.0);
  CHECK(to_nearest_double(3 * pow2(-1076)) == std::numeric_limits<double>::denorm_min());
  CHECK(to_nearest_double(-3 * pow2(-1075)) == -2 * std::numeric_limits<double>::denorm_min());
  CHECK(to_nearest_float(pow2(-149)) == std::numeric_limits<float>::denorm_min());
  CHECK(to_nearest_float(pow2(-150)) == 0.0f);
  CHECK(to_nearest_float(3 * pow2(-150)) == 2 * std::numeric_limits<float>::denorm_min());
  CHECK(to_nearest_float(1 + pow2(-24)) == 1.0f);
}

TEST_CASE("overflow rounds to infinity and the largest finite values are exact", "[number][rounding]") {
  CHECK(std::isinf(to_nearest_double(pow2(1024))));
  CHECK(to_nearest_double(exact_value(DBL_MAX)) == DBL_MAX);
  CHECK(to_nearest_double(exact_value(DBL_MAX) + pow2(969) - 1) == DBL_MAX);  // just below the tie
  CHECK(std::isinf(to_nearest_double(exact_value(DBL_MAX) + pow2(970))));
  CHECK(std::isinf(to_nearest_float(pow2(128))));
  CHECK(to_nearest_float(exact_value(FLT_MAX)) == FLT_MAX);
}

TEST_CASE("rounding agrees with glibc strtod and strtof on random decimals", "[number][rounding]") {
  // glibc's strtod/strtof are correctly rounded: an independent oracle.
  std::mt19937_64 rng(20261121);
  for (int i = 0; i < 3000; ++i) {
    std::string s = (rng() % 2) ? "-" : "";
    const int digits = 1 + static_cast<int>(rng() % 25);
    for (int k = 0; k < digits; ++k) s += static_cast<char>('0' + rng() % 10);
    if (rng() % 2) s.insert(s.size() - static_cast<std::size_t>(rng() % digits), ".");
    const int exponent = static_cast<int>(rng() % 700) - 350;
    s += "e" + std::to_string(exponent);
    if (s.find('.') != std::string::npos && s[s.find('.') + 1] == 'e') s.insert(s.find('e'), "0");
    const rational q = parse_number(s);
    INFO(s);
    CHECK(to_nearest_double(q) == std::strtod(s.c_str(), nullptr));
    CHECK(to_nearest_float(q) == std::strtof(s.c_str(), nullptr));
  }
}

TEST_CASE("malformed numbers are rejected with a message naming the text", "[number][errors]") {
  for (const char* bad : {"", "abc", "1..2", "1e", "1e+", "0x", "0x1p", "--1", "1 2", "1,5",
                          "1/", "/2", "1/2/3", "1/-3", "0x1.8q3", "f32:", "f16:1", "1e2.5", "٣"}) {
    INFO(bad);
    CHECK(error_id_of(bad) == "number.malformed");
  }
  try {
    parse_number("1..2");
    FAIL("no error");
  } catch (const error& e) {
    CHECK(std::string(e.what()) ==
          "[shadowproof.number.malformed] cannot read \"1..2\" as a number: unexpected character "
          "(expected an integer 42, a decimal 0.1 or -2.5e-3, a fraction 1/3, a hex float "
          "0x1.8p-3, or f32:<number> / f64:<number>)");
  }
}

TEST_CASE("a zero denominator is its own error", "[number][errors]") {
  CHECK(error_id_of("1/0") == "number.zero_denominator");
  CHECK(error_id_of("-5/000") == "number.zero_denominator");
}

TEST_CASE("NaN and infinity are rejected, also when a decimal overflows f32 or f64", "[number][errors]") {
  for (const char* bad : {"nan", "inf", "-inf", "Infinity", "f32:nan", "f64:-inf", "f32:1e39",
                          "f64:1e309", "f32:-3.5e38"}) {
    INFO(bad);
    CHECK(error_id_of(bad) == "number.not_finite");
  }
  CHECK(error_id_of("f32:3.4e38") == "no error");
}

TEST_CASE("numbers over the bit limit are rejected before they are built", "[number][errors][limits]") {
  CHECK(error_id_of("1e999999") == "number.too_large");
  CHECK(error_id_of("1e-999999") == "number.too_large");
  CHECK(error_id_of("0x1p99999999") == "number.too_large");
  CHECK(error_id_of("1e9999999999999") == "number.too_large");
  mpz_class big;
  mpz_ui_pow_ui(big.get_mpz_t(), 3, 100000);  // 1/3^100000, written out: 158497 bits
  CHECK(error_id_of("1/" + big.get_str()) == "number.too_large");
  CHECK(error_id_of(big.get_str()) == "number.too_large");
  CHECK(error_id_of(std::string(5000, '7')) == "number.too_large");
  try {
    parse_number("1e999999");
    FAIL("no error");
  } catch (const error& e) {
    CHECK(std::string(e.what()) ==
          "[shadowproof.number.too_large] \"1e999999\" needs more than 4096 bits in its numerator "
          "or denominator (the limit is 4096 bits; raise it with --max-bits)");
  }
}

TEST_CASE("the bit limit is exact and configurable", "[number][limits]") {
  number_limits eight{8};
  CHECK(parse_number("255", eight) == 255);    // 8 bits
  CHECK(error_id_of("256", eight) == "number.too_large");  // 9 bits
  CHECK(parse_number("1/255", eight) == rational(1, 255));
  CHECK(error_id_of("1/256", eight) == "number.too_large");
  CHECK(parse_number("2.55e2", eight) == 255);
  CHECK(error_id_of("0.001", eight) == "number.too_large");  // 1/1000 needs 10 bits
  // The default limit admits 2^4095 and rejects 2^4096 (4097 bits).
  CHECK(error_id_of("0x1p4095") == "no error");
  CHECK(error_id_of("0x1p4096") == "number.too_large");
  CHECK(error_id_of("0x1p-4095") == "no error");
  CHECK(error_id_of("0x1p-4096") == "number.too_large");
}

TEST_CASE("a number list has exactly the expected length", "[number]") {
  auto v = parse_number_list("1, 1/2 ,0.25,f32:1", 4, "--plane");
  REQUIRE(v.size() == 4);
  CHECK(v[1] == rational(1, 2));
  CHECK(v[2] == rational(1, 4));
  CHECK(v[3] == 1);
  try {
    parse_number_list("1,2,3", 4, "--plane");
    FAIL("no error");
  } catch (const error& e) {
    CHECK(e.id() == "number.list_length");
    CHECK(std::string(e.what()) ==
          "[shadowproof.number.list_length] --plane expects 4 comma-separated numbers, got 3 in \"1,2,3\"");
  }
  CHECK_THROWS_AS(parse_number_list("1,2,3,4,5", 4, "--plane"), error);
  CHECK_THROWS_AS(parse_number_list("1,,3,4", 4, "--plane"), error);
}

TEST_CASE("exact_value of a double is exact and refuses NaN", "[number]") {
  CHECK(exact_value(0.1) == rational(mpz_class("3602879701896397")) * pow2(-55));
  CHECK(exact_value(-0.0) == 0);
  CHECK_THROWS_AS(exact_value(std::nan("")), error);
  CHECK_THROWS_AS(exact_value(HUGE_VAL), error);
}
