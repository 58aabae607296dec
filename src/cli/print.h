#pragma once
// Exact text and JSON output shared by the subcommands.
#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/core/homogeneous.h"

namespace shadowproof::cli {

/// JSON array of exact strings ["7/3", "-4", ...].
nlohmann::json exact_json(const std::vector<rational>& values);
nlohmann::json exact_json(const vec4<rational>& v);
/// 4 rows of 4 exact strings.
nlohmann::json exact_json(const mat4<rational>& m);

/// Writes the matrix as four aligned rows of exact rationals, each row prefixed by `indent`.
void print_matrix(std::ostream& out, const mat4<rational>& m, const std::string& indent = "  ");

/// "(x, y, z, w)" with exact entries.
std::string exact_tuple(const std::vector<rational>& values);
std::string exact_tuple(const vec4<rational>& v);

/// Affine image (x/w, y/w, z/w) of a homogeneous vector, or nothing when w = 0.
std::optional<std::vector<rational>> affine_part(const vec4<rational>& v);

/// {"input": [x,y,z], "image": [x,y,z,w], "affine": [x,y,z] or null, "class": cls}.
nlohmann::json point_json(const vec4<rational>& V, const vec4<rational>& image, std::string_view cls);

/// The same as text: "point (x, y, z):" then its class, image and affine image.
void print_point(std::ostream& out, const vec4<rational>& V, const vec4<rational>& image, std::string_view cls);

/// Parses every --point "x,y,z" into the finite point (x, y, z, 1).
std::vector<vec4<rational>> parse_points(const std::vector<std::string>& texts, const number_limits& limits);

}  // namespace shadowproof::cli
