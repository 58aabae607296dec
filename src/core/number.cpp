// Exact number parsing, printing and correct rounding (MPFR).
#include "shadowproof/core/number.h"

#include <mpfr.h>

#include <cctype>
#include <cmath>
#include <string>

#include "shadowproof/core/error.h"

namespace shadowproof {
namespace {

// Exponents with more digits than this cannot produce a number within any sane bit limit
// (except for a zero mantissa, handled before); rejecting them keeps the arithmetic bounded.
constexpr std::size_t max_exponent_digits = 9;

std::string quoted(std::string_view text) {
  constexpr std::size_t shown = 60;
  std::string s(text.substr(0, shown));
  if (text.size() > shown) s += "... (" + std::to_string(text.size()) + " characters)";
  return "\"" + s + "\"";
}

[[noreturn]] void throw_malformed(std::string_view text, const std::string& why) {
  throw error(errc::number_malformed,
              "cannot read " + quoted(text) + " as a number: " + why +
                  " (expected an integer 42, a decimal 0.1 or -2.5e-3, a fraction 1/3, a hex "
                  "float 0x1.8p-3, or f32:<number> / f64:<number>)");
}

[[noreturn]] void throw_too_large(std::string_view text, const number_limits& limits) {
  throw error(errc::number_too_large,
              quoted(text) + " needs more than " + std::to_string(limits.max_bits) +
                  " bits in its numerator or denominator (the limit is " +
                  std::to_string(limits.max_bits) + " bits; raise it with --max-bits)");
}

void check_size(const rational& q, std::string_view text, const number_limits& limits) {
  if (bit_size(q) > limits.max_bits) throw_too_large(text, limits);
}

bool all_of(std::string_view s, int (*pred)(int)) {
  for (char c : s)
    if (!pred(static_cast<unsigned char>(c))) return false;
  return true;
}

// Splits an optional leading sign off `s`; returns true for '-'.
bool take_sign(std::string_view& s) {
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    bool negative = s[0] == '-';
    s.remove_prefix(1);
    return negative;
  }
  return false;
}

// Parses a decimal exponent of at most max_exponent_digits digits with optional sign.
long parse_exponent(std::string_view s, std::string_view text, const number_limits& limits,
                    bool mantissa_is_zero) {
  bool negative = take_sign(s);
  if (s.empty() || !all_of(s, isdigit)) throw_malformed(text, "the exponent is not an integer");
  while (s.size() > 1 && s[0] == '0') s.remove_prefix(1);
  if (s.size() > max_exponent_digits) {
    if (mantissa_is_zero) return 0;
    throw_too_large(text, limits);
  }
  long e = std::stol(std::string(s));
  return negative ? -e : e;
}

std::string_view strip_leading_zeros(std::string_view s) {
  while (!s.empty() && s[0] == '0') s.remove_prefix(1);
  return s;
}

mpz_class integer_from_digits(std::string_view digits, int base) {
  if (digits.empty()) return 0;
  return mpz_class(std::string(digits), base);
}

// value = sign · mantissa · base^exponent with base 10 (decimal) or 2 (hex float, after
// the mantissa digits are read in base 16). Sizes are checked before any big power is formed.
rational scaled_integer(bool negative, std::string_view digits, int digit_base, long exponent,
                        int power_base, std::string_view text, const number_limits& limits) {
  const double bits_per_digit = std::log2(static_cast<double>(digit_base));
  const double bits_per_unit = std::log2(static_cast<double>(power_base));
  digits = strip_leading_zeros(digits);
  // Trailing zero digits move into the exponent so a zero mantissa digit never counts.
  while (!digits.empty() && digits.back() == '0') {
    digits.remove_suffix(1);
    exponent += (digit_base == 10) ? 1 : 4;  // a hex digit is 2^4
  }
  if (digits.empty()) return 0;
  // The mantissa m ≥ base^(len-1) has no trailing zero digit, so it shares at most a few bits
  // with the denominator; both bounds below are lower bounds on the exact result's size.
  double mantissa_bits = (digits.size() - 1) * bits_per_digit;
  if (exponent >= 0 &&
      mantissa_bits + static_cast<double>(exponent) * bits_per_unit > limits.max_bits + 8.0)
    throw_too_large(text, limits);
  if (exponent < 0 && static_cast<double>(-exponent) > 4.0 * limits.max_bits + 8.0)
    throw_too_large(text, limits);
  if (mantissa_bits > 4.0 * limits.max_bits + 64.0) throw_too_large(text, limits);

  mpz_class m = integer_from_digits(digits, digit_base);
  mpz_class power;
  mpz_ui_pow_ui(power.get_mpz_t(), static_cast<unsigned long>(power_base),
                static_cast<unsigned long>(exponent >= 0 ? exponent : -exponent));
  rational q = exponent >= 0 ? rational(m * power) : rational(m, power);
  q.canonicalize();
  if (negative) q = -q;
  check_size(q, text, limits);
  return q;
}

rational parse_decimal(std::string_view s, std::string_view text, const number_limits& limits) {
  bool negative = take_sign(s);
  std::string_view exponent_part;
  if (auto e = s.find_first_of("eE"); e != std::string_view::npos) {
    exponent_part = s.substr(e + 1);
    s = s.substr(0, e);
    if (exponent_part.empty()) throw_malformed(text, "the exponent is empty");
  }
  std::string_view int_part = s, frac_part;
  if (auto dot = s.find('.'); dot != std::string_view::npos) {
    int_part = s.substr(0, dot);
    frac_part = s.substr(dot + 1);
  }
  if (int_part.empty() && frac_part.empty()) throw_malformed(text, "there are no digits");
  if (!all_of(int_part, isdigit) || !all_of(frac_part, isdigit))
    throw_malformed(text, "unexpected character");
  std::string digits = std::string(int_part) + std::string(frac_part);
  bool zero = strip_leading_zeros(digits).empty();
  long exponent = exponent_part.empty() ? 0 : parse_exponent(exponent_part, text, limits, zero);
  if (zero) return 0;
  exponent -= static_cast<long>(frac_part.size());
  return scaled_integer(negative, digits, 10, exponent, 10, text, limits);
}

rational parse_hex_float(std::string_view s, std::string_view text, const number_limits& limits) {
  bool negative = take_sign(s);
  s.remove_prefix(2);  // "0x"
  std::string_view exponent_part;
  if (auto p = s.find_first_of("pP"); p != std::string_view::npos) {
    exponent_part = s.substr(p + 1);
    s = s.substr(0, p);
    if (exponent_part.empty()) throw_malformed(text, "the binary exponent after 'p' is empty");
  }
  std::string_view int_part = s, frac_part;
  if (auto dot = s.find('.'); dot != std::string_view::npos) {
    int_part = s.substr(0, dot);
    frac_part = s.substr(dot + 1);
  }
  if (int_part.empty() && frac_part.empty()) throw_malformed(text, "there are no hex digits");
  auto hex = [](std::string_view d) {
    for (char c : d)
      if (!std::isxdigit(static_cast<unsigned char>(c))) return false;
    return true;
  };
  if (!hex(int_part) || !hex(frac_part)) throw_malformed(text, "unexpected character in hex float");
  std::string digits = std::string(int_part) + std::string(frac_part);
  bool zero = strip_leading_zeros(digits).empty();
  long exponent = exponent_part.empty() ? 0 : parse_exponent(exponent_part, text, limits, zero);
  if (zero) return 0;
  exponent -= 4 * static_cast<long>(frac_part.size());
  return scaled_integer(negative, digits, 16, exponent, 2, text, limits);
}

rational parse_fraction(std::string_view s, std::size_t slash, std::string_view text,
                        const number_limits& limits) {
  std::string_view num = s.substr(0, slash), den = s.substr(slash + 1);
  bool negative = take_sign(num);
  if (num.empty() || den.empty() || !all_of(num, isdigit) || !all_of(den, isdigit))
    throw_malformed(text, "a fraction is two integers p/q, the sign only before p");
  // Each written part must fit the limit (checked on the digits, before any big arithmetic).
  for (std::string_view part : {num, den}) {
    std::string_view d = strip_leading_zeros(part);
    if (!d.empty() && (d.size() - 1) * std::log2(10.0) > limits.max_bits + 4.0)
      throw_too_large(text, limits);
  }
  mpz_class p(std::string(num), 10), q(std::string(den), 10);
  if (q == 0) throw error(errc::number_zero_denominator, "the fraction " + quoted(text) + " divides by zero");
  if (mpz_sizeinbase(p.get_mpz_t(), 2) > limits.max_bits ||
      mpz_sizeinbase(q.get_mpz_t(), 2) > limits.max_bits)
    throw_too_large(text, limits);
  rational r(p, q);
  r.canonicalize();
  return negative ? rational(-r) : r;
}

bool starts_with_hex_prefix(std::string_view s) {
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  return s.size() >= 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
}

rational parse_exact(std::string_view s, std::string_view text, const number_limits& limits) {
  if (s.empty()) throw_malformed(text, "it is empty");
  if (auto slash = s.find('/'); slash != std::string_view::npos)
    return parse_fraction(s, slash, text, limits);
  if (starts_with_hex_prefix(s)) return parse_hex_float(s, text, limits);
  return parse_decimal(s, text, limits);
}

bool names_non_finite(std::string_view s) {
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  std::string lower;
  for (char c : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

// RAII guard for MPFR's exponent range, which is process-wide (thread-local) state.
class exponent_range {
 public:
  exponent_range(mpfr_exp_t emin, mpfr_exp_t emax) : emin_(mpfr_get_emin()), emax_(mpfr_get_emax()) {
    mpfr_set_emin(emin);
    mpfr_set_emax(emax);
  }
  ~exponent_range() {
    mpfr_set_emin(emin_);
    mpfr_set_emax(emax_);
  }
  exponent_range(const exponent_range&) = delete;
  exponent_range& operator=(const exponent_range&) = delete;

 private:
  mpfr_exp_t emin_, emax_;
};

// Rounds q to a binary format with `precision` significand bits whose values are m·2^e with
// 1/2 ≤ m < 1 and emin ≤ e ≤ emax (MPFR's convention); subnormals are emulated exactly.
template <class Result>
Result round_to_format(const rational& q, mpfr_prec_t precision, mpfr_exp_t emin, mpfr_exp_t emax,
                       Result (*get)(mpfr_srcptr, mpfr_rnd_t)) {
  exponent_range range(emin, emax);
  mpfr_t x;
  mpfr_init2(x, precision);
  int inexact = mpfr_set_q(x, q.get_mpq_t(), MPFR_RNDN);
  inexact = mpfr_check_range(x, inexact, MPFR_RNDN);
  mpfr_subnormalize(x, inexact, MPFR_RNDN);
  Result r = get(x, MPFR_RNDN);  // exact: x already has the format's precision and range
  mpfr_clear(x);
  return r;
}

}  // namespace

rational parse_number(std::string_view text, const number_limits& limits) {
  for (std::string_view prefix : {"f32:", "f64:"}) {
    if (text.substr(0, 4) != prefix) continue;
    std::string_view body = text.substr(4);
    if (names_non_finite(body))
      throw error(errc::number_not_finite, quoted(text) + " is not a finite number; shadowproof "
                                                      "takes finite inputs only");
    rational exact = parse_exact(body, text, limits);
    double rounded = prefix == "f32:" ? static_cast<double>(to_nearest_float(exact))
                                      : to_nearest_double(exact);
    if (std::isinf(rounded))
      throw error(errc::number_not_finite, quoted(text) + " overflows the " +
                                           std::string(prefix == "f32:" ? "float" : "double") +
                                           " format to infinity");
    return exact_value(rounded);
  }
  if (names_non_finite(text))
    throw error(errc::number_not_finite,
                quoted(text) + " is not a finite number; shadowproof takes finite inputs only");
  return parse_exact(text, text, limits);
}

std::vector<rational> parse_number_list(std::string_view text, std::size_t count,
                                        std::string_view what, const number_limits& limits) {
  std::vector<rational> values;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    std::string_view item = text.substr(start, comma == std::string_view::npos ? text.npos : comma - start);
    while (!item.empty() && std::isspace(static_cast<unsigned char>(item.front()))) item.remove_prefix(1);
    while (!item.empty() && std::isspace(static_cast<unsigned char>(item.back()))) item.remove_suffix(1);
    values.push_back(parse_number(item, limits));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
    if (values.size() > count) break;  // already too many: stop parsing
  }
  if (values.size() != count)
    throw error(errc::number_list_length,
                std::string(what) + " expects " + std::to_string(count) +
                    " comma-separated numbers, got " + (values.size() > count ? "more" : std::to_string(values.size())) +
                    " in " + quoted(text));
  return values;
}

std::string to_string(const rational& q) {
  rational canonical = q;  // a rational built from (p, q) by hand may not be reduced yet
  canonical.canonicalize();
  return canonical.get_str(10);
}

std::size_t bit_size(const rational& q) {
  if (q == 0) return 0;
  std::size_t n = mpz_sizeinbase(q.get_num_mpz_t(), 2);
  std::size_t d = mpz_sizeinbase(q.get_den_mpz_t(), 2);
  return n > d ? n : d;
}

double to_nearest_double(const rational& q) {
  return round_to_format<double>(q, 53, -1073, 1024, &mpfr_get_d);
}

float to_nearest_float(const rational& q) {
  return round_to_format<float>(q, 24, -148, 128, &mpfr_get_flt);
}

rational exact_value(double x) {
  if (!std::isfinite(x))
    throw error(errc::number_not_finite, std::string("the value ") + (std::isnan(x) ? "nan" : "inf") +
                                         " is not finite and has no exact rational value");
  return rational(x);  // mpq_set_d is exact for finite doubles
}

bool representable_in_float(double x) {
  return std::isfinite(x) && static_cast<double>(static_cast<float>(x)) == x;
}

}  // namespace shadowproof
