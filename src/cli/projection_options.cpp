#include "projection_options.h"

#include <set>

#include "shadowproof/constructions/handedness.h"
#include "shadowproof/core/error.h"

namespace shadowproof::cli {
namespace {

const std::vector<std::pair<std::string, std::string>> number_flags = {
    {"--left", "x of the left plane (ortho, oblique, frustum: on the near plane)"},
    {"--right", "x of the right plane"},
    {"--bottom", "y of the bottom plane"},
    {"--top", "y of the top plane"},
    {"--near", "near plane: distance along -z (> 0 for frustum/perspective); games101: its z (< 0)"},
    {"--far", "far plane: distance along -z; games101: its z (< 0)"},
    {"--cot-half-fovy", "exact focal scale cot(fovy/2) (perspective, games101)"},
    {"--aspect", "width/height (perspective, games101)"},
    {"--cot-theta", "cot θ of the oblique projector direction (cot θ, cot φ, 1)"},
    {"--cot-phi", "cot φ of the oblique projector direction"},
};

// The number flags each kind needs; any other given number flag is an error, so a typo such as
// `perspective --left 1` is reported instead of ignored.
std::vector<std::string> needed_flags(const std::string& kind, bool infinite_far) {
  const std::vector<std::string> box = {"--left", "--right", "--bottom", "--top", "--near", "--far"};
  if (kind == "ortho") return box;
  if (kind == "oblique") {
    auto v = box;
    v.push_back("--cot-theta");
    v.push_back("--cot-phi");
    return v;
  }
  if (kind == "frustum") {
    auto v = box;
    if (infinite_far) v.pop_back();
    return v;
  }
  if (kind == "perspective") {
    std::vector<std::string> v = {"--cot-half-fovy", "--aspect", "--near"};
    if (!infinite_far) v.push_back("--far");
    return v;
  }
  return {"--near", "--far", "--cot-half-fovy", "--aspect"};  // games101
}

std::string without_prefix(const error& e) {
  const std::string what = e.what();
  const std::string prefix = "[shadowproof." + e.id() + "] ";
  return what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
}

}  // namespace

rational parse_flag_number(const std::string& text, const std::string& flag, const number_limits& limits) {
  try {
    return parse_number(text, limits);
  } catch (const error& e) {
    throw error(e.code(), flag + ": " + without_prefix(e));
  }
}

void add_projection_options(CLI::App& app, projection_options& o, const std::vector<std::string>& kinds,
                            const std::string& default_kind) {
  std::string kind_list;
  for (const auto& k : kinds) kind_list += (kind_list.empty() ? "" : "|") + k;
  auto* kind = app.add_option("kind", o.kind, "projection: " + kind_list)->check(CLI::IsMember(kinds));
  if (default_kind.empty()) {
    kind->required();
  } else {
    o.kind = default_kind;
    kind->capture_default_str();
  }
  for (const auto& [flag, help] : number_flags) o.given[flag] = app.add_option(flag, o.numbers[flag], help);
  o.convention_option =
      app.add_option("--convention", o.convention_text,
                     "NDC depth: gl (near -1, far 1), d3d (near 0, far 1), reverse-z (near 1, far 0)")
          ->capture_default_str();
  app.add_flag("--infinite-far", o.infinite_far, "the far plane at infinity (frustum, perspective)");
  o.handedness_option =
      app.add_option("--handedness", o.handedness_text,
                     "eye space: right (looking down -z, OpenGL) or left (looking down +z: column 2 negated)")
          ->capture_default_str();
}

depth_convention chosen_convention(const projection_options& o) {
  return parse_depth_convention(o.convention_text);
}

projection build_projection(const projection_options& o, const number_limits& limits,
                            depth_convention convention) {
  const std::string& kind = o.kind;
  const bool games101 = kind == "games101";
  const handedness hand = parse_handedness(o.handedness_text);
  if (games101 && o.handedness_option && o.handedness_option->count() > 0)
    throw error(errc::cli_unused_option, "--handedness does not apply to games101, which looks down -z");
  if (games101 && o.convention_option->count() > 0)
    throw error(errc::cli_unused_option,
                "--convention does not apply to games101, whose NDC depth is fixed (near +1, far -1)");
  if (o.infinite_far && kind != "frustum" && kind != "perspective")
    throw error(errc::cli_unused_option, "--infinite-far applies to frustum and perspective only, not " + kind);
  if (o.infinite_far && o.given.at("--far")->count() > 0)
    throw error(errc::cli_unused_option, "--far and --infinite-far exclude each other");

  const auto needed = needed_flags(kind, o.infinite_far);
  const std::set<std::string> needed_set(needed.begin(), needed.end());
  for (const auto& [flag, option] : o.given)
    if (option->count() > 0 && needed_set.count(flag) == 0)
      throw error(errc::cli_unused_option, flag + " does not apply to " + kind);
  std::map<std::string, rational> x;
  for (const auto& flag : needed) {
    if (o.given.at(flag)->count() == 0) throw error(errc::cli_missing_option, kind + " needs " + flag);
    x[flag] = parse_flag_number(o.numbers.at(flag), flag, limits);
  }
  auto v = [&](const char* flag) -> const rational& { return x.at(flag); };
  auto box_text = [&] {
    return "left = " + to_string(v("--left")) + ", right = " + to_string(v("--right")) +
           ", bottom = " + to_string(v("--bottom")) + ", top = " + to_string(v("--top")) +
           ", near = " + to_string(v("--near"));
  };
  const std::string far_text = o.infinite_far ? "far = infinity" : "far = " + to_string(v("--far"));
  const std::string conv_text = ", convention " + std::string(to_string(convention));
  const rational unused_far = 0;  // frustum/perspective ignore f when the far plane is infinite
  const rational& f = o.infinite_far ? unused_far : v("--far");

  projection p;
  p.convention = convention;
  if (kind == "ortho") {
    p.matrix = orthographic(v("--left"), v("--right"), v("--bottom"), v("--top"), v("--near"), f, convention);
    p.description = "orthographic: " + box_text() + ", " + far_text + conv_text;
  } else if (kind == "oblique") {
    p.matrix = oblique(v("--left"), v("--right"), v("--bottom"), v("--top"), v("--near"), f,
                       v("--cot-theta"), v("--cot-phi"), convention);
    p.description = "oblique orthographic(box) H(θ, φ): " + box_text() + ", " + far_text + ", cot θ = " +
                    to_string(v("--cot-theta")) + ", cot φ = " + to_string(v("--cot-phi")) + conv_text;
  } else if (kind == "frustum") {
    p.matrix = frustum(v("--left"), v("--right"), v("--bottom"), v("--top"), v("--near"), f, convention,
                       o.infinite_far);
    p.description = "frustum: " + box_text() + ", " + far_text + conv_text;
  } else if (kind == "perspective") {
    p.matrix = perspective(v("--cot-half-fovy"), v("--aspect"), v("--near"), f, convention, o.infinite_far);
    p.description = "perspective: cot(fovy/2) = " + to_string(v("--cot-half-fovy")) + ", aspect = " +
                    to_string(v("--aspect")) + ", near = " + to_string(v("--near")) + ", " + far_text +
                    conv_text;
  } else {
    p.matrix = games101_projection(v("--near"), v("--far"), v("--cot-half-fovy"), v("--aspect"));
    p.description = "games101 ortho·translate·persp: near z = " + to_string(v("--near")) + ", far z = " +
                    to_string(v("--far")) + ", cot(fovy/2) = " + to_string(v("--cot-half-fovy")) +
                    ", aspect = " + to_string(v("--aspect")) + " (NDC depth: near +1, far -1)";
  }
  if (hand == handedness::left) {
    p.matrix = with_handedness(p.matrix, hand);
    p.description += ", left-handed (looking down +z)";
  }
  return p;
}

}  // namespace shadowproof::cli
