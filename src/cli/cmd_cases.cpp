// shadowproof cases: writes JSON-lines test cases for an implementation in any language.
#include <iostream>

#include "command.h"
#include "shadowproof/core/error.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/protocol.h"

namespace shadowproof::cli {
namespace {

struct cases_options {
  std::string op = "shadow-matrix";
  std::string type = "f32";
  std::string cls;
  std::size_t count = 100;
  std::uint64_t seed = 1;
  bool directional = false;
  bool point_lights = false;
  bool unit_normal = false;
  bool symmetric = false;
  bool clamps = false;
  std::vector<std::string> conventions;  // name=value, written into every line
};

// Applies "name=value" texts (the protocol's convention spellings) to conv.
void apply_conventions(conventions& conv, const std::vector<std::string>& texts) {
  for (const auto& t : texts) {
    const auto eq = t.find('=');
    if (eq == std::string::npos)
      throw error(errc::protocol_convention, "--convention '" + t + "' must read name=value, e.g. depth=d3d");
    set_convention(conv, t.substr(0, eq), t.substr(eq + 1));
  }
}

int run_cases(const cases_options& o) {
  const auto op = operation_from_string(o.op);
  if (!op)
    throw error(errc::verify_unknown_op,
                "unknown --op '" + o.op + "'; expected one of " + operation_names(", "));
  const auto type = scalar_type_from_string(o.type);
  if (!type) throw error(errc::verify_unknown_type, "unknown --type '" + o.type + "'; expected f32 or f64");
  std::optional<input_class> cls;
  if (!o.cls.empty()) {
    cls = input_class_from_string(o.cls);
    if (!cls)
      throw error(errc::verify_unknown_class,
                  "unknown --class '" + o.cls + "'; expected regular, near-degenerate, degenerate or range");
  }
  if (o.directional && o.point_lights)
    throw error(errc::verify_requirements, "--directional and --point-lights exclude each other");
  conventions requirements;
  apply_conventions(requirements, o.conventions);
  requirements.directional_only = o.directional;
  requirements.point_light_only = o.point_lights;
  requirements.unit_normal = o.unit_normal;
  requirements.symmetric_view = requirements.symmetric_view || o.symmetric;
  requirements.clamps_behind_receiver = requirements.clamps_behind_receiver || o.clamps;
  for (const auto& c : generate_cases(*op, *type, o.count, o.seed, cls, requirements))
    std::cout << case_json_line(c, requirements) << '\n';
  return 0;
}

const command_registration cases_registration{command{
    "cases", "write JSON-lines test cases (hex floats + exact decimals) for an implementation in any language",
    [](CLI::App& app, const global_options&) {
      auto o = std::make_shared<cases_options>();
      app.add_option("--op", o->op, "one of " + operation_names(", "))->capture_default_str();
      app.add_option("--type", o->type, "f32 or f64: every input is exactly representable in it")
          ->capture_default_str();
      app.add_option("--count", o->count, "number of cases")->capture_default_str();
      app.add_option("--seed", o->seed, "generator seed (same seed, byte-identical output)")->capture_default_str();
      app.add_option("--class", o->cls, "only regular, near-degenerate, degenerate or range cases (default: cycle)");
      app.add_flag("--directional", o->directional, "directional lights only (w = 0)");
      app.add_flag("--point-lights", o->point_lights, "point lights only (w = 1)");
      app.add_flag("--unit-normal", o->unit_normal, "planes with a unit normal only (±1 on one axis, as y = h)");
      app.add_flag("--symmetric", o->symmetric, "view volumes symmetric only (l = −r, b = −t)");
      app.add_flag("--clamps-behind-receiver", o->clamps,
                   "shadow-point: receivers oriented with the light on their positive side (for routines that "
                   "leave points behind the receiver in place)");
      app.add_option("--convention", o->conventions,
                     "name=value, repeatable: a convention written into every line, in which the inputs "
                     "are written and the outputs read (docs/protocol.md), e.g. depth=d3d, handedness=left, "
                     "angle=degrees, plane=n.x=d, matrix3=mat4, layout=column-major, symmetric=true");
      return [o] { return run_cases(*o); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
