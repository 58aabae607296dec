// The any-language protocol: writing and reading case lines, reading output lines.
#include <cmath>
#include <limits>
#include <sstream>

#include <gmpxx.h>

#include <nlohmann/json.hpp>

#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"
#include "shadowproof/core/ulp.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/protocol.h"

namespace shadowproof {
namespace {

std::string where(std::size_t line_number) { return "line " + std::to_string(line_number); }

// A JSON value as a number exactly representable in t; nothing when it is not.
std::optional<double> json_number(const nlohmann::json& v, scalar_type t, bool allow_special) {
  double x = 0;
  if (v.is_null()) {
    if (!allow_special) return std::nullopt;
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (v.is_number()) {
    x = v.get<double>();  // JSON numbers: nlohmann reads them correctly rounded to double
  } else if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "nan" || s == "NaN" || s == "inf" || s == "-inf" || s == "Infinity" || s == "-Infinity") {
      if (!allow_special) return std::nullopt;
      if (s == "nan" || s == "NaN") return std::numeric_limits<double>::quiet_NaN();
      return s[0] == '-' ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    }
    const rational q = parse_number(s);
    x = to_nearest_double(q);
    if (!std::isfinite(x) || exact_value(x) != q) return std::nullopt;
  } else {
    return std::nullopt;
  }
  if (!representable(x, t)) return std::nullopt;
  return x;
}

nlohmann::json parse_line(std::string_view line, std::size_t line_number, errc id) {
  try {
    return nlohmann::json::parse(line);
  } catch (const nlohmann::json::exception& e) {
    throw error(id, where(line_number) + ": not a JSON object: " + e.what());
  }
}

}  // namespace

test_case parse_case_line(std::string_view line, std::size_t line_number) {
  const nlohmann::json j = parse_line(line, line_number, errc::protocol_case);
  auto fail = [&](const std::string& what) { throw error(errc::protocol_case, where(line_number) + ": " + what); };
  if (!j.is_object()) fail("expected a JSON object");
  test_case c;
  if (!j.contains("id") || !j["id"].is_number_unsigned()) fail("\"id\" must be a non-negative integer");
  c.id = j["id"].get<std::uint64_t>();
  if (!j.contains("op") || !j["op"].is_string()) fail("\"op\" is missing");
  const auto op = operation_from_string(j["op"].get<std::string>());
  if (!op) fail("unknown \"op\" \"" + j["op"].get<std::string>() + "\"");
  c.op = *op;
  if (!j.contains("type") || !j["type"].is_string()) fail("\"type\" is missing");
  const auto type = scalar_type_from_string(j["type"].get<std::string>());
  if (!type) fail("\"type\" must be \"f32\" or \"f64\"");
  c.type = *type;
  if (j.contains("class")) {
    const auto cls = j["class"].is_string() ? input_class_from_string(j["class"].get<std::string>()) : std::nullopt;
    if (!cls) fail("\"class\" must be regular, near-degenerate or degenerate");
    c.cls = *cls;
  }
  for (const auto& g : signature(c.op).inputs) {
    if (!j.contains(g.name) || !j[g.name].is_array() || j[g.name].size() != g.size)
      fail("\"" + g.name + "\" must be an array of " + std::to_string(g.size) + " numbers");
    for (std::size_t i = 0; i < g.size; ++i) {
      std::optional<double> x;
      try {
        x = json_number(j[g.name][i], c.type, false);
      } catch (const error& e) {
        fail("\"" + g.name + "\"[" + std::to_string(i) + "]: " + e.what());
      }
      if (!x) fail("\"" + g.name + "\"[" + std::to_string(i) + "] = " + j[g.name][i].dump() +
                   " is not a finite number exactly representable in " + std::string(to_string(c.type)));
      c.inputs.push_back(*x == 0 ? 0.0 : *x);
    }
  }
  if (const std::string why = invalid_inputs_reason(c); !why.empty()) fail(why);
  return c;
}

output_line parse_output_line(std::string_view line, std::size_t line_number, scalar_type type,
                              std::size_t count) {
  const nlohmann::json j = parse_line(line, line_number, errc::protocol_output);
  auto fail = [&](const std::string& what) { throw error(errc::protocol_output, where(line_number) + ": " + what); };
  if (!j.is_object()) fail("expected a JSON object");
  output_line o;
  if (!j.contains("id") || !j["id"].is_number_unsigned()) fail("\"id\" must be a non-negative integer");
  o.id = j["id"].get<std::uint64_t>();
  if (!j.contains("output") || !j["output"].is_array() || j["output"].size() != count)
    fail("\"output\" must be an array of " + std::to_string(count) + " numbers");
  for (std::size_t i = 0; i < count; ++i) {
    std::optional<double> x;
    try {
      x = json_number(j["output"][i], type, true);
    } catch (const error& e) {
      fail("\"output\"[" + std::to_string(i) + "]: " + e.what());
    }
    if (!x) fail("\"output\"[" + std::to_string(i) + "] = " + j["output"][i].dump() + " is not exactly a " +
                 std::string(to_string(type)) + " value (outputs are never rounded by the grader)");
    o.values.push_back(*x);
  }
  return o;
}

std::string exact_decimal(double x) {
  if (!std::isfinite(x)) throw error(errc::verify_not_finite, "exact_decimal needs a finite number");
  if (x == 0) return std::signbit(x) ? "-0" : "0";
  int e = 0;
  const double m = std::frexp(std::fabs(x), &e);  // |x| = m 2^e, m in [0.5, 1)
  mpz_class mant = static_cast<unsigned long>(std::ldexp(m, 53));
  int exp2 = e - 53;  // |x| = mant · 2^exp2
  std::string digits;
  int point = 0;  // digits after the decimal point
  if (exp2 >= 0) {
    mant <<= exp2;
    digits = mant.get_str();
  } else {
    mpz_class five;
    mpz_ui_pow_ui(five.get_mpz_t(), 5, static_cast<unsigned long>(-exp2));
    mant *= five;  // |x| = mant · 10^exp2
    digits = mant.get_str();
    point = -exp2;
  }
  if (point > 0) {
    if (static_cast<int>(digits.size()) <= point) digits.insert(0, point - digits.size() + 1, '0');
    digits.insert(digits.size() - point, ".");
    while (digits.back() == '0') digits.pop_back();
    if (digits.back() == '.') digits.pop_back();
  }
  return (x < 0 ? "-" : "") + digits;
}

std::string case_json_line(const test_case& c) {
  std::ostringstream out;
  out << "{\"id\": " << c.id << ", \"op\": \"" << to_string(c.op) << "\", \"type\": \""
      << to_string(c.type) << "\", \"class\": \"" << to_string(c.cls) << "\"";
  const auto& sig = signature(c.op);
  // Each input group twice: bit-exact hex floats, then (under "exact") exact decimals.
  auto write_groups = [&](bool exact) {
    std::size_t k = 0;
    bool first = true;
    for (const auto& g : sig.inputs) {
      out << (exact && first ? "" : ", ") << '"' << g.name << "\": [";
      first = false;
      for (std::size_t i = 0; i < g.size; ++i, ++k)
        out << (i ? ", " : "") << '"' << (exact ? exact_decimal(c.inputs[k]) : hex_string(c.inputs[k])) << '"';
      out << ']';
    }
  };
  write_groups(false);
  out << ", \"exact\": {";
  write_groups(true);
  out << "}}";
  return out.str();
}

}  // namespace shadowproof
