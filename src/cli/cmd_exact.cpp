// shadowproof exact: the exact answer the grader compares against for one case, output by
// output, with its correct rounding. The reproducer the reports print for inputs that the
// geometric commands reject (a flat view volume, a singular matrix), and for any case.
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "command.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/ulp.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/exact.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/protocol.h"

namespace shadowproof::cli {
namespace {

struct exact_options {
  std::string op, type = "f32", inputs, light = "towards-light", depth = "gl";
  bool clamps = false, symmetric = false, json = false;
  std::vector<std::string> conventions;  // name=value
};

int run_exact(const exact_options& o, const global_options& g) {
  const auto op = operation_from_string(o.op);
  if (!op) throw error(errc::verify_unknown_op, "unknown --op '" + o.op + "'; expected one of " + operation_names(", "));
  const auto type = scalar_type_from_string(o.type);
  if (!type) throw error(errc::verify_unknown_type, "unknown --type '" + o.type + "'; expected f32 or f64");
  conventions conv;
  if (o.light == "along-rays") conv.light = light_sign::along_rays;
  else if (o.light != "towards-light")
    throw error(errc::grade_light, "unknown --light '" + o.light + "'; expected towards-light or along-rays");
  conv.depth = parse_depth_convention(o.depth);
  conv.clamps_behind_receiver = o.clamps;
  conv.symmetric_view = o.symmetric;
  for (const auto& t : o.conventions) {
    const auto eq = t.find('=');
    if (eq == std::string::npos)
      throw error(errc::protocol_convention, "--convention '" + t + "' must read name=value, e.g. handedness=left");
    set_convention(conv, t.substr(0, eq), t.substr(eq + 1));
  }
  test_case c;
  c.op = *op;
  c.type = *type;
  const operation_signature& sig = signature(*op);
  const auto values = parse_number_list(o.inputs, sig.input_count, "--inputs", g.limits);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double x = to_nearest_double(values[i]);
    if (!representable(x, *type) || exact_value(x) != values[i])
      throw error(errc::number_not_finite, "--inputs entry " + std::to_string(i + 1) + " = " + to_string(values[i]) +
                                           " is not exactly a " + std::string(to_string(*type)) + " value");
    c.inputs.push_back(x == 0 ? 0.0 : x);
  }
  if (const std::string why = invalid_inputs_reason(c); !why.empty()) throw error(errc::protocol_case, why);
  const exact_result a = exact_result_of(c, conv);
  const std::vector<double> rounded = correctly_rounded_outputs(c, conv);
  if (o.json) {
    nlohmann::json doc{{"op", o.op}, {"type", o.type}, {"outputs", nlohmann::json::array()}};
    if (a.cls) doc["class"] = std::string(to_string(*a.cls));
    for (std::size_t i = 0; i < a.values.size(); ++i)
      doc["outputs"].push_back({{"name", output_name(*op, i)},
                                {"exact", a.defined[i] ? nlohmann::json(to_string(a.values[i])) : nlohmann::json(nullptr)},
                                {"rounded", a.defined[i] ? nlohmann::json(hex_string(rounded[i])) : nlohmann::json(nullptr)}});
    std::cout << doc.dump(2) << '\n';
    return 0;
  }
  std::cout << o.op << " (" << summary(*op) << "), " << o.type << " inputs:\n";
  std::size_t k = 0;
  for (const auto& group : sig.inputs) {
    std::cout << "  " << group.name << " =";
    for (std::size_t i = 0; i < group.size; ++i, ++k) std::cout << ' ' << to_string(values[k]);
    std::cout << '\n';
  }
  if (a.cls) std::cout << "class " << to_string(*a.cls) << '\n';
  std::cout << "exact outputs (canonical order), correctly rounded to " << o.type << ":\n";
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    std::cout << "  " << output_name(*op, i) << "  ";
    if (a.defined[i]) std::cout << to_string(a.values[i]) << "  ->  " << hex_string(rounded[i]) << '\n';
    else std::cout << "undefined (no value: a division by zero)\n";
  }
  return 0;
}

const command_registration exact_registration{command{
    "exact", "the exact answer of one graded case, output by output, correctly rounded (the reports' reproducer)",
    [](CLI::App& app, const global_options& g) {
      auto o = std::make_shared<exact_options>();
      app.add_option("--op", o->op, "the operation: " + operation_names(", "))->required();
      app.add_option("--type", o->type, "f32 or f64: every input must be exactly a value of it")->capture_default_str();
      app.add_option("--inputs", o->inputs, "the operation's inputs, comma-separated, in the order of its case lines")
          ->required();
      app.add_option("--light", o->light, "directional light vector: towards-light or along-rays")->capture_default_str();
      app.add_option("--depth", o->depth, "projections: NDC depth convention gl, d3d or reverse-z")->capture_default_str();
      app.add_flag("--clamps-behind-receiver", o->clamps, "shadow-point: a point behind the receiver stays in place");
      app.add_flag("--symmetric", o->symmetric, "view volumes are symmetric (l = −r, b = −t)");
      app.add_option("--convention", o->conventions,
                     "name=value, repeatable (docs/protocol.md): handedness=left, angle=degrees, ...");
      app.add_flag("--json", o->json, "print one JSON object");
      return [o, &g] { return run_exact(*o, g); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
