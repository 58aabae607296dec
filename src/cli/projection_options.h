#pragma once
// Projection flags shared by `shadowproof project` and `shadowproof depth-precision`.
#include <map>
#include <string>
#include <vector>

#include "command.h"
#include "shadowproof/core/homogeneous.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof::cli {

/// The flags describing one projection (kind + numbers + convention), as text until built.
struct projection_options {
  std::string kind;
  std::map<std::string, std::string> numbers;  // "--left" -> text
  std::map<std::string, CLI::Option*> given;   // "--left" -> option (count() > 0 when given)
  std::string convention_text = "gl";
  CLI::Option* convention_option = nullptr;
  bool infinite_far = false;
  std::string handedness_text = "right";  // --handedness: left negates column 2
  CLI::Option* handedness_option = nullptr;
};

/// A built projection: its exact matrix, its depth convention and a one-line description.
struct projection {
  mat4<rational> matrix;
  depth_convention convention = depth_convention::gl;
  std::string description;
};

/// Adds the positional kind (one of `kinds`; `default_kind` when empty means required) and the
/// number flags --left --right --bottom --top --near --far --cot-half-fovy --aspect --cot-theta
/// --cot-phi, --convention, --infinite-far and --handedness.
void add_projection_options(CLI::App& app, projection_options& o, const std::vector<std::string>& kinds,
                            const std::string& default_kind);

/// Builds the exact matrix for the chosen kind, with `convention` in place of --convention.
/// Throws error "cli.missing_option" / "cli.unused_option" naming the flag, and the library's
/// errors for degenerate volumes.
projection build_projection(const projection_options& o, const number_limits& limits,
                            depth_convention convention);

/// The convention named by --convention (default gl).
depth_convention chosen_convention(const projection_options& o);

/// Parses one number of a flag; errors name the flag.
rational parse_flag_number(const std::string& text, const std::string& flag, const number_limits& limits);

}  // namespace shadowproof::cli
