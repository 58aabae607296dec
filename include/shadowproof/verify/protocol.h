#pragma once
/// The case-file protocol through which a program in any language is graded: one JSON object
/// per line for each case (`shadowproof cases`) and for each set of outputs (`shadowproof grade`).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/verify/cases.h"

namespace shadowproof {

/// Writes the case as the JSON object of the case-file protocol (one line, no newline):
/// {"id": 0, "op": "shadow-matrix", "type": "f32", "class": "regular", "closeness": -1.25,
///  "plane": [hex...], "light": [hex...], "exact": {"plane": [decimal...], ...}}; closeness is
/// log2 of the relative distance to the degeneracy (two decimals, "-inf" exactly on it).
std::string case_json_line(const test_case& c);

/// Exact decimal expansion of a finite double ("0.100000001490116119384765625").
std::string exact_decimal(double x);

/// Reads one line of a case file (case_json_line's format; "class", "closeness" and "exact"
/// optional).
/// Every input must be a hex-float or exact string (or a JSON number) exactly representable
/// in the case's type. Throws error "protocol.case" naming the line and field otherwise, and
/// for a plane with a zero normal or an all-zero light.
test_case parse_case_line(std::string_view line, std::size_t line_number);

/// One line of an implementation's outputs: {"id": 0, "output": [numbers]}.
struct output_line {
  std::uint64_t id = 0;
  std::vector<double> values;
};

/// Reads one line of outputs for a case of type `type` with `count` outputs. Numbers are JSON
/// numbers or strings (hex float "0x1.8p+0", decimal, "nan", "inf", "-inf"), null means NaN;
/// each finite value must be exactly representable in `type` (never rounded silently).
/// Throws error "protocol.output" naming the line and the entry otherwise.
output_line parse_output_line(std::string_view line, std::size_t line_number, scalar_type type,
                              std::size_t count);

}  // namespace shadowproof
