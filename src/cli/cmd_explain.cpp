// shadowproof explain: the derivation of a matrix with the user's numbers substituted, each
// step evaluated exactly, ending in the matrix the other subcommands print; --svg draws the case.
#include <iostream>
#include <map>
#include <memory>

#include "command.h"
#include "print.h"
#include "projection_options.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/io.h"
#include "shadowproof/explain/explain.h"

namespace shadowproof::cli {
namespace {

struct explain_options {
  CLI::App *shadow = nullptr, *reflect = nullptr, *reflect_frames = nullptr, *perspective = nullptr, *ortho = nullptr,
           *oblique = nullptr, *games101 = nullptr, *normal = nullptr, *basis = nullptr;
  std::string plane_text, light_text, matrix_text, quaternion_text, d_text;
  std::vector<std::string> point_texts, normal_texts;
  std::string svg_file;
  // Projections: the numbers by flag, and which of them were given.
  std::map<std::string, std::string> numbers;
  std::map<const CLI::App*, std::map<std::string, CLI::Option*>> given;  // per topic
  const CLI::App* topic = nullptr;                                        // the one chosen
  std::string convention_text = "gl", cot_sign_text = "minus";
  bool infinite_far = false;
  // Change of basis.
  std::string x_axis_text, y_axis_text, z_axis_text, origin_text;
};

const std::vector<std::string> window_flags = {"--left", "--right", "--bottom", "--top"};

plane<rational> parse_plane(const std::string& text, const number_limits& limits) {
  const auto p = parse_number_list(text, 4, "--plane", limits);
  return make_plane(p[0], p[1], p[2], p[3]);
}

std::array<rational, 3> parse_triple(const std::string& text, const char* flag, const number_limits& limits) {
  const auto v = parse_number_list(text, 3, flag, limits);
  return {v[0], v[1], v[2]};
}

bool has(const explain_options& o, const std::string& flag) {
  const auto& flags = o.given.at(o.topic);
  const auto it = flags.find(flag);
  return it != flags.end() && it->second->count() > 0;
}

rational number(const explain_options& o, const std::string& flag, const std::string& topic, const number_limits& limits) {
  if (!has(o, flag)) throw error(errc::cli_missing_option, "explain " + topic + " needs " + flag);
  return parse_flag_number(o.numbers.at(flag), flag, limits);
}

// How many of the window flags were given; names the missing ones.
std::size_t window_given(const explain_options& o, std::string& missing) {
  std::size_t count = 0;
  for (const auto& flag : window_flags) {
    if (has(o, flag)) ++count;
    else missing += (missing.empty() ? "" : ", ") + flag;
  }
  return count;
}

explanation perspective_command(const explain_options& o, const std::vector<vec4<rational>>& points, const number_limits& limits) {
  std::string missing;
  const std::size_t window = window_given(o, missing);
  const rational n = number(o, "--near", "perspective", limits);
  if (window == 0) {
    // Seed 002's N(α, β): the 45° frustum, OpenGL depth.
    if (has(o, "--convention") || o.infinite_far)
      throw error(errc::cli_unused_option,
                  "--convention and --infinite-far apply to the frustum form: give --left, --right, "
                  "--bottom and --top too, or leave them out for seed 002's N(α, β)");
    return explain_perspective_normalization(n, number(o, "--far", "perspective", limits), points);
  }
  if (window != window_flags.size())
    throw error(errc::cli_missing_option, "the frustum form needs all of --left, --right, --bottom, --top; missing " + missing);
  const depth_convention c = parse_depth_convention(o.convention_text);
  rational f = 0;
  if (o.infinite_far) {
    if (has(o, "--far")) throw error(errc::cli_unused_option, "--far and --infinite-far contradict each other; give one of them");
  } else {
    if (!has(o, "--far")) throw error(errc::cli_missing_option, "explain perspective needs --far (or --infinite-far)");
    f = number(o, "--far", "perspective", limits);
  }
  return explain_frustum(number(o, "--left", "perspective", limits), number(o, "--right", "perspective", limits),
                         number(o, "--bottom", "perspective", limits), number(o, "--top", "perspective", limits), n, f, c,
                         o.infinite_far, points);
}

explanation oblique_command(const explain_options& o, const std::vector<vec4<rational>>& points, const number_limits& limits) {
  const cot_sign sign = parse_cot_sign(o.cot_sign_text);
  const rational ct = number(o, "--cot-theta", "oblique", limits), cp = number(o, "--cot-phi", "oblique", limits);
  std::string missing;
  const std::size_t window = window_given(o, missing);
  const bool depth = has(o, "--near") || has(o, "--far");
  if (window == 0 && !depth) {
    if (has(o, "--convention"))
      throw error(errc::cli_unused_option, "--convention applies to a box: give --left ... --far too");
    return explain_oblique(ct, cp, sign, std::nullopt, points);
  }
  if (window != window_flags.size())
    throw error(errc::cli_missing_option, "a box needs all of --left, --right, --bottom, --top, --near, --far; missing " + missing);
  view_box box{number(o, "--left", "oblique", limits), number(o, "--right", "oblique", limits),
               number(o, "--bottom", "oblique", limits), number(o, "--top", "oblique", limits),
               number(o, "--near", "oblique", limits), number(o, "--far", "oblique", limits),
               parse_depth_convention(o.convention_text)};
  return explain_oblique(ct, cp, sign, box, points);
}

int run_explain(explain_options& o, const global_options& g) {
  for (const CLI::App* topic : {o.shadow, o.reflect, o.reflect_frames, o.perspective, o.ortho, o.oblique, o.games101,
                                o.normal, o.basis})
    if (topic->parsed()) o.topic = topic;
  o.given[o.topic];  // topics without number flags have an empty map
  const auto points = parse_points(o.point_texts, g.limits);
  explanation e;
  if (o.shadow->parsed()) {
    const plane<rational> P = parse_plane(o.plane_text, g.limits);
    const auto l = parse_number_list(o.light_text, 4, "--light", g.limits);
    e = explain_shadow(P, make_light(l[0], l[1], l[2], l[3]), points);
  } else if (o.reflect->parsed()) {
    e = explain_reflection(parse_plane(o.plane_text, g.limits), points);
  } else if (o.reflect_frames->parsed()) {
    const auto q = parse_number_list(o.quaternion_text, 4, "--quaternion", g.limits);
    e = explain_reflection_by_frames({q[0], q[1], q[2], q[3]}, parse_flag_number(o.d_text, "--d", g.limits), points);
  } else if (o.perspective->parsed()) {
    e = perspective_command(o, points, g.limits);
  } else if (o.ortho->parsed()) {
    e = explain_orthographic(number(o, "--left", "ortho", g.limits), number(o, "--right", "ortho", g.limits),
                             number(o, "--bottom", "ortho", g.limits), number(o, "--top", "ortho", g.limits),
                             number(o, "--near", "ortho", g.limits), number(o, "--far", "ortho", g.limits),
                             parse_depth_convention(o.convention_text), points);
  } else if (o.oblique->parsed()) {
    e = oblique_command(o, points, g.limits);
  } else if (o.games101->parsed()) {
    e = explain_games101(number(o, "--near", "games101", g.limits), number(o, "--far", "games101", g.limits),
                         number(o, "--cot-half-fovy", "games101", g.limits), number(o, "--aspect", "games101", g.limits),
                         points);
  } else if (o.normal->parsed()) {
    const auto m = parse_number_list(o.matrix_text, 16, "--matrix", g.limits);
    mat4<rational> M;
    for (std::size_t i = 0; i < 16; ++i) M(i / 4, i % 4) = m[i];
    std::vector<vec4<rational>> normals;
    for (const auto& text : o.normal_texts) {
      const auto v = parse_number_list(text, 3, "--normal", g.limits);
      normals.push_back(make_vec4<rational>(v[0], v[1], v[2], 0));
    }
    e = explain_normal_matrix(M, normals);
  } else if (o.basis->parsed()) {
    e = explain_change_of_basis(parse_triple(o.x_axis_text, "--x-axis", g.limits), parse_triple(o.y_axis_text, "--y-axis", g.limits),
                                parse_triple(o.z_axis_text, "--z-axis", g.limits), parse_triple(o.origin_text, "--origin", g.limits),
                                points);
  } else {
    throw error(errc::cli_missing_option, "explain needs a topic");
  }
  // The picture first: a failure to write it is an error (exit 2) before anything is printed.
  if (!o.svg_file.empty()) write_file_atomically(o.svg_file, to_svg(e.picture));
  std::cout << to_text(e);
  return 0;
}

void add_number(CLI::App* app, explain_options& o, const std::string& flag, const std::string& help) {
  o.given[app][flag] = app->add_option(flag, o.numbers[flag], help);
}

void add_common(CLI::App* app, explain_options& o, const char* point_help) {
  app->add_option("--point", o.point_texts, point_help);
  app->add_option("--svg", o.svg_file, "write a figure of this case (SVG, written atomically)");
}

void add_window(CLI::App* app, explain_options& o) {
  add_number(app, o, "--left", "x of the left edge of the window");
  add_number(app, o, "--right", "x of the right edge");
  add_number(app, o, "--bottom", "y of the bottom edge");
  add_number(app, o, "--top", "y of the top edge");
}

const command_registration explain_registration{command{
    "explain", "the derivation of a matrix with your numbers, every step evaluated exactly, and its figure (--svg)",
    [](CLI::App& app, const global_options& g) -> std::function<int()> {
      auto o = std::make_shared<explain_options>();
      app.require_subcommand(1);

      o->shadow = app.add_subcommand("shadow", "derive the shadow matrix M = (P·L) I - L Pᵀ and classify points");
      o->shadow->add_option("--plane", o->plane_text, "receiver plane a,b,c,d (a x + b y + c z + d = 0)")->required();
      o->shadow->add_option("--light", o->light_text,
                            "light x,y,z,w: w != 0 point light at (x,y,z)/w, w = 0 directional towards (x,y,z)")
          ->required();
      add_common(o->shadow, *o, "a point x,y,z to follow to its image and class (repeatable)");

      o->reflect = app.add_subcommand("reflect", "derive the reflection matrix about a plane");
      o->reflect->add_option("--plane", o->plane_text, "mirror plane a,b,c,d (a x + b y + c z + d = 0)")->required();
      add_common(o->reflect, *o, "a point x,y,z to reflect (repeatable)");

      o->reflect_frames = app.add_subcommand(
          "reflect-frames", "seed 003's reflection by a change of frame: T(-dN) Rᵀ S(1,-1,1) R T(dN) for a rational rotation");
      o->reflect_frames->add_option("--quaternion", o->quaternion_text,
                                    "the rotation R as a quaternion w,x,y,z (not all 0); N is R's second row")
          ->required();
      o->reflect_frames->add_option("--d", o->d_text, "the mirror is <N, X> + d = 0")->required();
      add_common(o->reflect_frames, *o, "a point x,y,z to follow through the factors (repeatable)");

      o->perspective = app.add_subcommand(
          "perspective",
          "derive seed 002's N(alpha, beta) from --near/--far, or with --left --right --bottom --top the "
          "frustum matrix in a depth convention");
      add_number(o->perspective, *o, "--near", "distance of the near plane along -z (> 0)");
      add_number(o->perspective, *o, "--far", "distance of the far plane along -z (> 0)");
      add_window(o->perspective, *o);
      CLI::Option* convention = o->perspective
                                 ->add_option("--convention", o->convention_text, "frustum form: NDC depth gl, d3d or reverse-z")
                                 ->capture_default_str();
      o->given[o->perspective]["--convention"] = convention;
      o->perspective->add_flag("--infinite-far", o->infinite_far, "frustum form: far plane at infinity");
      add_common(o->perspective, *o, "an eye-space point x,y,z to project (repeatable)");

      o->ortho = app.add_subcommand("ortho", "derive the orthographic projection of a box in a depth convention");
      add_window(o->ortho, *o);
      add_number(o->ortho, *o, "--near", "the box's near side is z = -near");
      add_number(o->ortho, *o, "--far", "the box's far side is z = -far");
      o->ortho->add_option("--convention", o->convention_text, "NDC depth gl, d3d or reverse-z")->capture_default_str();
      add_common(o->ortho, *o, "an eye-space point x,y,z to project (repeatable)");

      o->oblique = app.add_subcommand(
          "oblique", "derive the oblique projection H(theta, phi) with either sign of cot; with a box, keeping depth");
      add_number(o->oblique, *o, "--cot-theta", "cot(theta), exactly");
      add_number(o->oblique, *o, "--cot-phi", "cot(phi), exactly");
      o->oblique->add_option("--cot-sign", o->cot_sign_text,
                             "minus: H has -cot, projector (cot t, cot p, 1) (Angel, the library); plus: H has +cot, "
                             "tan(theta) = z/(x_p - x), projector (cot t, cot p, -1) (seed 002's first slide)")
          ->capture_default_str();
      add_window(o->oblique, *o);
      add_number(o->oblique, *o, "--near", "box: near side z = -near");
      add_number(o->oblique, *o, "--far", "box: far side z = -far");
      o->given[o->oblique]["--convention"] =
          o->oblique->add_option("--convention", o->convention_text, "box: NDC depth gl, d3d or reverse-z")->capture_default_str();
      add_common(o->oblique, *o, "a point x,y,z to project (repeatable)");

      o->games101 = app.add_subcommand("games101", "derive GAMES101's perspective: squeeze, centre, scale (seed 004)");
      add_number(o->games101, *o, "--near", "z of the near plane (< 0)");
      add_number(o->games101, *o, "--far", "z of the far plane (< near)");
      add_number(o->games101, *o, "--cot-half-fovy", "cot(fovy/2) > 0, exactly");
      add_number(o->games101, *o, "--aspect", "width/height > 0");
      add_common(o->games101, *o, "an eye-space point x,y,z to project (repeatable)");

      o->normal = app.add_subcommand("normal-matrix", "derive the normal matrix G = (M⁻¹)ᵀ");
      o->normal->add_option("--matrix", o->matrix_text, "the 16 entries m00,m01,...,m33 of M, row by row")->required();
      o->normal->add_option("--normal", o->normal_texts, "a normal x,y,z to follow (repeatable)");
      o->normal->add_option("--svg", o->svg_file, "write a figure of this case (SVG, written atomically)");

      o->basis = app.add_subcommand("change-of-basis", "derive the child-to-parent matrix of a frame and its inverse");
      o->basis->add_option("--x-axis", o->x_axis_text, "the child's X axis in parent coordinates, x,y,z")->required();
      o->basis->add_option("--y-axis", o->y_axis_text, "the child's Y axis")->required();
      o->basis->add_option("--z-axis", o->z_axis_text, "the child's Z axis")->required();
      o->basis->add_option("--origin", o->origin_text, "the child's origin in parent coordinates")->required();
      add_common(o->basis, *o, "a point a,b,c in child coordinates (repeatable)");

      return [o, &g] { return run_explain(*o, g); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
