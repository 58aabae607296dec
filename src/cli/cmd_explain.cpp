// shadowproof explain: the derivation of a matrix with the user's numbers substituted, each
// step evaluated exactly, ending in the matrix the other subcommands print.
#include <iostream>
#include <memory>

#include "command.h"
#include "print.h"
#include "projection_options.h"
#include "shadowproof/core/error.h"
#include "shadowproof/explain/explain.h"

namespace shadowproof::cli {
namespace {

struct explain_options {
  CLI::App* shadow = nullptr;
  CLI::App* reflect = nullptr;
  CLI::App* perspective = nullptr;
  CLI::App* normal = nullptr;
  std::string plane_text, light_text, matrix_text;
  std::vector<std::string> point_texts;
  // perspective: near/far always; the window flags select the frustum form.
  std::string near_text, far_text, left_text, right_text, bottom_text, top_text;
  std::map<std::string, CLI::Option*> window;
  CLI::Option* far_option = nullptr;
  CLI::Option* convention_option = nullptr;
  std::string convention_text = "gl";
  bool infinite_far = false;
};

plane<rational> parse_plane(const std::string& text, const number_limits& limits) {
  const auto p = parse_number_list(text, 4, "--plane", limits);
  return make_plane(p[0], p[1], p[2], p[3]);
}

explanation explain_perspective_command(const explain_options& o, const number_limits& limits) {
  std::size_t window_given = 0;
  std::string missing;
  for (const auto& [flag, option] : o.window) {
    if (option->count() > 0) ++window_given;
    else missing += (missing.empty() ? "" : ", ") + flag;
  }
  const rational n = parse_flag_number(o.near_text, "--near", limits);
  if (window_given == 0) {
    // Seed 002's N(α, β): the 45° frustum, OpenGL depth.
    if (o.convention_option->count() > 0 || o.infinite_far)
      throw error(errc::cli_unused_option,
                  "--convention and --infinite-far apply to the frustum form: give --left, --right, "
                  "--bottom and --top too, or leave them out for seed 002's N(α, β)");
    if (o.far_option->count() == 0)
      throw error(errc::cli_missing_option, "explain perspective needs --far");
    return explain_perspective_normalization(n, parse_flag_number(o.far_text, "--far", limits));
  }
  if (window_given != o.window.size())
    throw error(errc::cli_missing_option, "the frustum form needs all of --left, --right, --bottom, --top; missing " +
                                          missing);
  const depth_convention c = parse_depth_convention(o.convention_text);
  rational f = 0;
  if (o.infinite_far) {
    if (o.far_option->count() > 0)
      throw error(errc::cli_unused_option, "--far and --infinite-far contradict each other; give one of them");
  } else {
    if (o.far_option->count() == 0)
      throw error(errc::cli_missing_option, "explain perspective needs --far (or --infinite-far)");
    f = parse_flag_number(o.far_text, "--far", limits);
  }
  return explain_frustum(parse_flag_number(o.left_text, "--left", limits),
                         parse_flag_number(o.right_text, "--right", limits),
                         parse_flag_number(o.bottom_text, "--bottom", limits),
                         parse_flag_number(o.top_text, "--top", limits), n, f, c, o.infinite_far);
}

int run_explain(const explain_options& o, const global_options& g) {
  explanation e;
  if (o.shadow->parsed()) {
    const plane<rational> P = parse_plane(o.plane_text, g.limits);
    const auto l = parse_number_list(o.light_text, 4, "--light", g.limits);
    const light<rational> L = make_light(l[0], l[1], l[2], l[3]);
    e = explain_shadow(P, L, parse_points(o.point_texts, g.limits));
  } else if (o.reflect->parsed()) {
    e = explain_reflection(parse_plane(o.plane_text, g.limits));
  } else if (o.perspective->parsed()) {
    e = explain_perspective_command(o, g.limits);
  } else if (o.normal->parsed()) {
    const auto m = parse_number_list(o.matrix_text, 16, "--matrix", g.limits);
    mat4<rational> M;
    for (std::size_t i = 0; i < 16; ++i) M(i / 4, i % 4) = m[i];
    e = explain_normal_matrix(M);
  } else {
    throw error(errc::cli_missing_option, "explain needs a topic: shadow, reflect, perspective or normal-matrix");
  }
  std::cout << to_text(e);
  return 0;
}

const command_registration registration{command{
    "explain", "the derivation of a matrix with your numbers, every step evaluated exactly",
    [](CLI::App& app, const global_options& g) -> std::function<int()> {
      auto o = std::make_shared<explain_options>();
      app.require_subcommand(1);

      o->shadow = app.add_subcommand("shadow", "derive the shadow matrix M = (P·L) I - L Pᵀ");
      o->shadow->add_option("--plane", o->plane_text, "receiver plane a,b,c,d (a x + b y + c z + d = 0)")
          ->required();
      o->shadow->add_option("--light", o->light_text,
                            "light x,y,z,w: w != 0 point light at (x,y,z)/w, w = 0 directional towards (x,y,z)")
          ->required();
      o->shadow->add_option("--point", o->point_texts, "a point x,y,z to follow through (repeatable)");

      o->reflect = app.add_subcommand("reflect", "derive the reflection matrix about a plane");
      o->reflect->add_option("--plane", o->plane_text, "mirror plane a,b,c,d (a x + b y + c z + d = 0)")
          ->required();

      o->perspective = app.add_subcommand(
          "perspective",
          "derive seed 002's N(alpha, beta) from --near/--far, or with --left --right --bottom --top the "
          "frustum matrix in a depth convention");
      o->perspective->add_option("--near", o->near_text, "distance of the near plane along -z")->required();
      o->far_option = o->perspective->add_option("--far", o->far_text, "distance of the far plane along -z");
      o->window["--left"] = o->perspective->add_option("--left", o->left_text, "x of the left edge of the near window");
      o->window["--right"] = o->perspective->add_option("--right", o->right_text, "x of the right edge");
      o->window["--bottom"] = o->perspective->add_option("--bottom", o->bottom_text, "y of the bottom edge");
      o->window["--top"] = o->perspective->add_option("--top", o->top_text, "y of the top edge");
      o->convention_option = o->perspective
                                 ->add_option("--convention", o->convention_text,
                                              "frustum form: NDC depth gl, d3d or reverse-z")
                                 ->capture_default_str();
      o->perspective->add_flag("--infinite-far", o->infinite_far, "frustum form: far plane at infinity");

      o->normal = app.add_subcommand("normal-matrix", "derive the normal matrix G = (M⁻¹)ᵀ");
      o->normal->add_option("--matrix", o->matrix_text, "the 16 entries m00,m01,...,m33 of M, row by row")
          ->required();

      return [o, &g] { return run_explain(*o, g); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
