#pragma once
/// Exact numbers: the rational scalar, its parser and printer, and correct rounding to floats.
#include <gmpxx.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace shadowproof {

/// The exact scalar: a GMP rational, always in canonical form (coprime, positive denominator).
using rational = mpq_class;

/// Size guard applied to every parsed number: numerator and denominator each at most
/// `max_bits` bits. Over the limit the parser throws error "number.too_large" instead of
/// allocating (1e999999 would need 3.3 million bits).
struct number_limits {
  std::size_t max_bits = 4096;
};

/// Parses one number exactly. Accepted forms (optional sign everywhere):
///   integer `42`; decimal `0.1` (= 1/10), `-2.5e-3` (= -1/400); fraction `1/3`;
///   C hex float `0x1.8p-3` (= 3/16); `f32:<decimal>` / `f64:<decimal>`: the float / double
///   nearest to the decimal (round to nearest, ties to even), taken bit-exactly.
/// Throws error "number.malformed", "number.zero_denominator", "number.not_finite" (f32:/f64:
/// of nan/inf or a decimal that overflows the format) or "number.too_large".
rational parse_number(std::string_view text, const number_limits& limits = {});

/// Parses exactly `count` comma-separated numbers ("1,2,3"); throws "number.list_length" when
/// there are more or fewer. `what` names the list in messages (e.g. "--plane").
std::vector<rational> parse_number_list(std::string_view text, std::size_t count,
                                        std::string_view what, const number_limits& limits = {});

/// Exact text of q: "7/3", "-4", "0".
std::string to_string(const rational& q);

/// Number of bits of the larger of |numerator| and denominator (0 for 0).
std::size_t bit_size(const rational& q);

/// The double nearest to q (round to nearest, ties to even; overflow gives ±inf, underflow
/// gives a subnormal or ±0). Unlike mpq_get_d, which truncates, this is correctly rounded.
double to_nearest_double(const rational& q);
/// The float nearest to q, with the same rules as to_nearest_double.
float to_nearest_float(const rational& q);

/// Exact value of a finite float or double; throws "number.not_finite" for NaN or ±inf.
rational exact_value(double x);

/// True when x is finite and exactly a float value (so every float routine receives it
/// unrounded).
bool representable_in_float(double x);

// ---------------------------------------------------------------------------------------
// number_cast: one formula, many number types. Rational -> float rounds correctly;
// float -> rational is exact; same type is the identity.

template <class To, class From>
To number_cast(const From& x) {
  if constexpr (std::is_same_v<To, From>) {
    return x;
  } else if constexpr (std::is_same_v<To, rational> && std::is_floating_point_v<From>) {
    return exact_value(static_cast<double>(x));
  } else if constexpr (std::is_same_v<From, rational> && std::is_same_v<To, double>) {
    return to_nearest_double(x);
  } else if constexpr (std::is_same_v<From, rational> && std::is_same_v<To, float>) {
    return to_nearest_float(x);
  } else {
    // Other targets (e.g. intervals) need an enclosing conversion of their own, not this one.
    static_assert(!std::is_same_v<From, rational>, "no correctly rounded cast to this type");
    return static_cast<To>(x);
  }
}

}  // namespace shadowproof
