// The any-language protocol: writing and reading case lines, reading output lines.
#include <charconv>
#include <cmath>
#include <cstdio>
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


std::string without_prefix(const error& e) {
  const std::string what = e.what();
  const std::string prefix = "[shadowproof." + e.id() + "] ";
  return what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
}

// A 3x3 matrix input or output of the operation (normal-matrix), subject to matrix3_layout.
bool is_matrix3_group(operation op, const input_group& g) { return signature(op).matrix_size == 3 && g.size == 9; }

std::size_t laid_out_size(matrix3_layout layout) {
  switch (layout) {
    case matrix3_layout::packed: return 9;
    case matrix3_layout::padded: return 12;
    case matrix3_layout::mat4: return 16;
  }
  return 9;
}

std::size_t written_size(operation op, const input_group& g, const conventions& conv) {
  return is_matrix3_group(op, g) ? laid_out_size(conv.matrix3_input) : g.size;
}

// Storage and vector side transpose a matrix; both together cancel.
bool transposed(const conventions& conv) {
  return (conv.storage == storage_order::column_major) != (conv.vectors == vector_side::row);
}

// Position of entry (p, q) of the stored 3x3 grid (p: the group of three, q: within it) in a
// line laid out in `layout`.
std::size_t laid_out_index(std::size_t p, std::size_t q, matrix3_layout layout) {
  return layout == matrix3_layout::packed ? 3 * p + q : 4 * p + q;
}

// What a mat4 embedding fixes at position i (not in the 3x3 block): 1 in the corner, else 0.
double embedding_value(std::size_t i) { return i == 15 ? 1.0 : 0.0; }
bool in_block(std::size_t i) { return i % 4 < 3 && i < 12; }

// 9 stored numbers (in storage order) from a laid-out line; empty message when the embedding
// entries hold, else what is wrong.
std::string unpack_matrix3(std::vector<double>& v, matrix3_layout layout, const char* what) {
  if (layout == matrix3_layout::mat4)
    for (std::size_t i = 0; i < 16; ++i)
      if (!in_block(i) && !(v[i] == embedding_value(i)))
        return std::string(what) + " entry " + std::to_string(i) + " lies outside the 3x3 block of a mat4 " +
               "embedding [A 0; 0 1] and must be exactly " + (i == 15 ? "1" : "0") + ", not " + hex_string(v[i]);
  std::vector<double> stored(9);
  for (std::size_t p = 0; p < 3; ++p)
    for (std::size_t q = 0; q < 3; ++q) stored[3 * p + q] = v[laid_out_index(p, q, layout)];
  v = stored;
  return "";
}

// Takes a group as written under conv back to canonical form, in place; or says why not.
std::string canonical_group(operation op, const input_group& g, const conventions& conv, std::vector<double>& v) {
  if (g.name == "plane" && g.size == 4 && conv.plane == plane_form::equals_d) v[3] = v[3] == 0 ? 0.0 : -v[3];
  if (!is_matrix3_group(op, g)) return "";
  if (std::string bad = unpack_matrix3(v, conv.matrix3_input, "input"); !bad.empty()) return bad;
  if (transposed(conv)) {  // stored grid (p, q) is A(q, p)
    std::vector<double> a(9);
    for (std::size_t p = 0; p < 3; ++p)
      for (std::size_t q = 0; q < 3; ++q) a[3 * q + p] = v[3 * p + q];
    v = a;
  }
  return "";
}

// The inverse of canonical_group: a canonical group as written under conv.
std::vector<double> written_group(operation op, const input_group& g, const conventions& conv, const double* x) {
  std::vector<double> v(x, x + g.size);
  if (g.name == "plane" && g.size == 4 && conv.plane == plane_form::equals_d) v[3] = v[3] == 0 ? 0.0 : -v[3];
  if (!is_matrix3_group(op, g)) return v;
  std::vector<double> out(laid_out_size(conv.matrix3_input), 0.0);
  if (conv.matrix3_input == matrix3_layout::mat4)
    for (std::size_t i = 0; i < 16; ++i)
      if (!in_block(i)) out[i] = embedding_value(i);
  for (std::size_t p = 0; p < 3; ++p)
    for (std::size_t q = 0; q < 3; ++q)
      out[laid_out_index(p, q, conv.matrix3_input)] = transposed(conv) ? v[3 * q + p] : v[3 * p + q];
  return out;
}

// The shortest decimal that reads back as the same double (a JSON number).
std::string shortest_json_number(double x) {
  char buffer[64];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, r.ptr);
}

struct convention_spelling {
  const char* name;
  std::vector<std::string> values;  // index = enumerator value; the first is the default
};

const std::vector<convention_spelling>& spellings() {
  static const std::vector<convention_spelling> s = {
      {"layout", {"row-major", "column-major"}},
      {"vectors", {"column", "row"}},
      {"light", {"towards-light", "along-rays"}},
      {"depth", {"gl", "d3d", "reverse-z"}},
      {"handedness", {"right", "left"}},
      {"angle", {"radians", "degrees"}},
      {"plane", {"n.x+d=0", "n.x=d"}},
      {"matrix3", {"packed", "padded", "mat4"}},
      {"matrix3-input", {"packed", "padded", "mat4"}},
      {"homogeneous", {"false", "true"}},
      {"symmetric", {"false", "true"}},
      {"sentinel", {"none", "zero", "identity"}},
      {"clamps-behind-receiver", {"false", "true"}},
  };
  return s;
}

// The enumerator values of conv in the order of spellings().
std::vector<int> convention_values(const conventions& c) {
  return {static_cast<int>(c.storage), static_cast<int>(c.vectors), static_cast<int>(c.light),
          static_cast<int>(c.depth),   static_cast<int>(c.hand),    static_cast<int>(c.angle),
          static_cast<int>(c.plane),   static_cast<int>(c.matrix3), static_cast<int>(c.matrix3_input), c.homogeneous ? 1 : 0,
          c.symmetric_view ? 1 : 0, static_cast<int>(c.sentinel), c.clamps_behind_receiver ? 1 : 0};
}

}  // namespace

std::vector<std::pair<std::string, std::string>> declared_conventions(const conventions& conv) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto values = convention_values(conv);
  for (std::size_t i = 0; i < spellings().size(); ++i)
    if (values[i] != 0) out.emplace_back(spellings()[i].name, spellings()[i].values[static_cast<std::size_t>(values[i])]);
  return out;
}

void set_convention(conventions& conv, std::string_view name, std::string_view value) {
  for (const auto& s : spellings()) {
    if (name != s.name) continue;
    for (std::size_t v = 0; v < s.values.size(); ++v) {
      if (value != s.values[v]) continue;
      const int k = static_cast<int>(v);
      if (name == "layout") conv.storage = static_cast<storage_order>(k);
      else if (name == "vectors") conv.vectors = static_cast<vector_side>(k);
      else if (name == "light") conv.light = static_cast<light_sign>(k);
      else if (name == "depth") conv.depth = static_cast<depth_convention>(k);
      else if (name == "handedness") conv.hand = static_cast<handedness>(k);
      else if (name == "angle") conv.angle = static_cast<angle_unit>(k);
      else if (name == "plane") conv.plane = static_cast<plane_form>(k);
      else if (name == "matrix3") conv.matrix3 = static_cast<matrix3_layout>(k);
      else if (name == "matrix3-input") conv.matrix3_input = static_cast<matrix3_layout>(k);
      else if (name == "homogeneous") conv.homogeneous = k != 0;
      else if (name == "symmetric") conv.symmetric_view = k != 0;
      else if (name == "sentinel") conv.sentinel = static_cast<sentinel_kind>(k);
      else conv.clamps_behind_receiver = k != 0;
      return;
    }
    std::string expected;
    for (const auto& v : s.values) expected += (expected.empty() ? "" : ", ") + v;
    throw error(errc::protocol_convention, "convention \"" + std::string(name) + "\" cannot be \"" +
                                               std::string(value) + "\"; expected one of " + expected);
  }
  std::string names;
  for (const auto& s : spellings()) names += (names.empty() ? "" : ", ") + std::string(s.name);
  throw error(errc::protocol_convention, "unknown convention \"" + std::string(name) + "\"; expected one of " + names);
}

std::size_t output_count(const test_case& c, const conventions& conv) {
  const auto& sig = signature(c.op);
  return sig.matrix_size == 3 ? laid_out_size(conv.matrix3) : sig.output_count;
}

test_case parse_case_line(std::string_view line, std::size_t line_number) {
  conventions ignored;
  return parse_case_line(line, line_number, ignored);
}

test_case parse_case_line(std::string_view line, std::size_t line_number, conventions& conv) {
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
    if (!cls) fail("\"class\" must be regular, near-degenerate, degenerate or range");
    c.cls = *cls;
  }
  if (j.contains("closeness")) {
    const auto& k = j["closeness"];
    if (k.is_number()) c.closeness = k.get<double>();
    else if (k.is_string() && k.get<std::string>() == "-inf") c.closeness = -std::numeric_limits<double>::infinity();
    else fail("\"closeness\" must be a number or \"-inf\"");
  }
  if (j.contains("conventions")) {
    if (!j["conventions"].is_object()) fail("\"conventions\" must be an object");
    for (const auto& [name, value] : j["conventions"].items()) {
      const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
      try {
        set_convention(conv, name, text);
      } catch (const error& e) {
        throw error(errc::protocol_convention, where(line_number) + ": " + without_prefix(e));
      }
    }
  }
  for (const auto& g : signature(c.op).inputs) {
    const std::size_t written = written_size(c.op, g, conv);
    if (!j.contains(g.name) || !j[g.name].is_array() || j[g.name].size() != written)
      fail("\"" + g.name + "\" must be an array of " + std::to_string(written) + " numbers");
    std::vector<double> values;
    for (std::size_t i = 0; i < written; ++i) {
      std::optional<double> x;
      try {
        x = json_number(j[g.name][i], c.type, false);
      } catch (const error& e) {
        fail("\"" + g.name + "\"[" + std::to_string(i) + "]: " + e.what());
      }
      if (!x) fail("\"" + g.name + "\"[" + std::to_string(i) + "] = " + j[g.name][i].dump() +
                   " is not a finite number exactly representable in " + std::string(to_string(c.type)));
      values.push_back(*x == 0 ? 0.0 : *x);
    }
    const std::string bad = canonical_group(c.op, g, conv, values);
    if (!bad.empty()) fail("\"" + g.name + "\": " + bad);
    c.inputs.insert(c.inputs.end(), values.begin(), values.end());
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

std::string case_json_line(const test_case& c) { return case_json_line(c, conventions{}); }

std::string case_json_line(const test_case& c, const conventions& declared) {
  std::ostringstream out;
  out << "{\"id\": " << c.id << ", \"op\": \"" << to_string(c.op) << "\", \"type\": \""
      << to_string(c.type) << "\", \"class\": \"" << to_string(c.cls) << "\"";
  if (std::isinf(c.closeness) && c.closeness < 0) {
    out << ", \"closeness\": \"-inf\"";
  } else if (std::isfinite(c.closeness)) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", c.closeness);
    out << ", \"closeness\": " << text;
  }
  const auto conv = declared_conventions(declared);
  if (!conv.empty()) {
    out << ", \"conventions\": {";
    for (std::size_t i = 0; i < conv.size(); ++i)
      out << (i ? ", " : "") << '"' << conv[i].first << "\": \"" << conv[i].second << '"';
    out << '}';
  }
  const auto& sig = signature(c.op);
  std::vector<std::vector<double>> groups;
  std::size_t k = 0;
  for (const auto& g : sig.inputs) {
    groups.push_back(written_group(c.op, g, declared, c.inputs.data() + k));
    k += g.size;
  }
  // Each input group three times: bit-exact hex floats, exact decimals under "exact", and
  // shortest round-trip JSON numbers under "numbers".
  enum class form { hex, decimal, number };
  auto write_groups = [&](form f) {
    for (std::size_t gi = 0; gi < groups.size(); ++gi) {
      out << (f != form::hex && gi == 0 ? "" : ", ") << '"' << sig.inputs[gi].name << "\": [";
      for (std::size_t i = 0; i < groups[gi].size(); ++i) {
        const double x = groups[gi][i];
        out << (i ? ", " : "");
        if (f == form::hex) out << '"' << hex_string(x) << '"';
        else if (f == form::decimal) out << '"' << exact_decimal(x) << '"';
        else out << shortest_json_number(x);
      }
      out << ']';
    }
  };
  write_groups(form::hex);
  out << ", \"exact\": {";
  write_groups(form::decimal);
  out << "}, \"numbers\": {";
  write_groups(form::number);
  out << "}}";
  return out.str();
}

output_line parse_output_line(std::string_view line, std::size_t line_number, const test_case& c,
                              const conventions& conv) {
  output_line o = parse_output_line(line, line_number, c.type, output_count(c, conv));
  if (signature(c.op).matrix_size == 3) {
    const std::string bad = unpack_matrix3(o.values, conv.matrix3, "output");
    if (!bad.empty()) throw error(errc::protocol_output, where(line_number) + ": " + bad);
  }
  return o;
}

}  // namespace shadowproof
