#pragma once
/// The case-file protocol through which a program in any language is graded: one JSON object
/// per line for each case (`shadowproof cases`) and for each set of outputs (`shadowproof grade`).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof {

/// Writes the case as the JSON object of the case-file protocol (one line, no newline):
/// {"id": 0, "op": "shadow-matrix", "type": "f32", "class": "regular", "closeness": -1.25,
///  "plane": [hex...], "light": [hex...], "exact": {"plane": [decimal...], ...}, "numbers":
///  {"plane": [JSON numbers...], ...}}; closeness is log2 of the relative distance to the
/// degeneracy (two decimals, "-inf" exactly on it). Each input three times: bit-exact hex
/// floats, exact decimals, and JSON numbers in the shortest form that reads back as the same
/// double (any JSON library that rounds correctly to double, JavaScript's JSON.parse included,
/// gets the input exactly; an f32 input is that float's exact double value). docs/protocol.md
/// describes the protocol.
std::string case_json_line(const test_case& c);

/// The same line for an implementation with `declared` conventions: they are written as a
/// "conventions" object (only those that differ from the defaults; none, no object), and the
/// inputs are written in them: a plane in the declared plane_form, a 3x3 matrix input in the
/// declared storage, vector side and matrix3_input layout (outputs are read in matrix3).
std::string case_json_line(const test_case& c, const conventions& declared);

/// The conventions a case line or a command line can declare, as (name, value) pairs in their
/// protocol spelling, only those that differ from the defaults:
///   layout: row-major | column-major          vectors: column | row
///   light: towards-light | along-rays         depth: gl | d3d | reverse-z
///   handedness: right | left                   angle: radians | degrees
///   plane: n.x+d=0 | n.x=d                     matrix3, matrix3-input: packed | padded | mat4
///   homogeneous, symmetric, clamps-behind-receiver: true | false
///   sentinel: none | zero | identity
std::vector<std::pair<std::string, std::string>> declared_conventions(const conventions& conv);

/// Sets one convention by its protocol name and value (the spellings above). Throws error
/// "protocol.convention" naming the convention for an unknown name or value.
void set_convention(conventions& conv, std::string_view name, std::string_view value);

/// Number of outputs a line carries for c under conv: the operation's output count, except
/// for 3x3 matrices laid out padded (12) or in a mat4 (16).
std::size_t output_count(const test_case& c, const conventions& conv);

/// Exact decimal expansion of a finite double ("0.100000001490116119384765625").
std::string exact_decimal(double x);

/// Reads one line of a case file (case_json_line's format; "class", "closeness" and "exact"
/// optional).
/// Every input must be a hex-float or exact string (or a JSON number) exactly representable
/// in the case's type. Throws error "protocol.case" naming the line and field otherwise, and
/// for a plane with a zero normal or an all-zero light.
test_case parse_case_line(std::string_view line, std::size_t line_number);

/// Reads one line of a case file as above, starting from the conventions `conv` (the caller's
/// defaults): a "conventions" object in the line overrides them, and the line's inputs are read
/// in the result (a plane written as n·x = d gets d negated, a laid-out 3x3 matrix is taken
/// back to 9 numbers row by row), so the returned case is always in canonical form. Errors as
/// above, and "protocol.convention" for an unknown convention.
test_case parse_case_line(std::string_view line, std::size_t line_number, conventions& conv);

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

/// Reads one line of outputs for case c under conv: output_count(c, conv) numbers, read as
/// above; a 3x3 matrix laid out padded or in a mat4 is taken back to its 9 numbers (in the
/// declared storage order, as grade_case expects). Padding is ignored; the entries a mat4
/// embedding fixes (0 off the block, 1 in the corner) must be exactly those, or the line is
/// rejected with "protocol.output".
output_line parse_output_line(std::string_view line, std::size_t line_number, const test_case& c,
                              const conventions& conv);

}  // namespace shadowproof
