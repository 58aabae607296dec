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
};

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
                  "unknown --class '" + o.cls + "'; expected regular, near-degenerate or degenerate");
  }
  conventions requirements;
  requirements.directional_only = o.directional;
  for (const auto& c : generate_cases(*op, *type, o.count, o.seed, cls, requirements))
    std::cout << case_json_line(c) << '\n';
  return 0;
}

const command_registration reg{command{
    "cases", "write JSON-lines test cases (hex floats + exact decimals) for an implementation in any language",
    [](CLI::App& app, const global_options&) {
      auto o = std::make_shared<cases_options>();
      app.add_option("--op", o->op, "one of " + operation_names(", "))->capture_default_str();
      app.add_option("--type", o->type, "f32 or f64: every input is exactly representable in it")
          ->capture_default_str();
      app.add_option("--count", o->count, "number of cases")->capture_default_str();
      app.add_option("--seed", o->seed, "generator seed (same seed, byte-identical output)")->capture_default_str();
      app.add_option("--class", o->cls, "only regular, near-degenerate or degenerate cases (default: cycle)");
      app.add_flag("--directional", o->directional, "directional lights only (w = 0)");
      return [o] { return run_cases(*o); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
