// shadowproof reflect: the exact planar reflection matrix and the images of points.
#include <iostream>

#include "command.h"
#include "print.h"
#include "shadowproof/constructions/classify.h"
#include "shadowproof/constructions/reflect.h"

namespace shadowproof::cli {
namespace {

struct reflect_options {
  std::string plane_text;
  std::vector<std::string> point_texts;
  bool json = false;
};

/// Side of the mirror a point is on: "on_plane", "positive_side" (P·V > 0) or "negative_side".
std::string side_of(const plane<rational>& P, const vec4<rational>& V) {
  const int s = sign_of(evaluate(P, V));
  return s == 0 ? "on_plane" : (s > 0 ? "positive_side" : "negative_side");
}

int run_reflect(const reflect_options& o, const global_options& g) {
  auto p = parse_number_list(o.plane_text, 4, "--plane", g.limits);
  const plane<rational> P = make_plane(p[0], p[1], p[2], p[3]);
  const auto points = parse_points(o.point_texts, g.limits);
  const mat4<rational> M = reflection_matrix(P);

  if (o.json) {
    nlohmann::json doc;
    doc["matrix"] = exact_json(M);
    doc["points"] = nlohmann::json::array();
    for (const auto& V : points) doc["points"].push_back(point_json(V, M * V, side_of(P, V)));
    std::cout << doc.dump(2) << '\n';
    return 0;
  }
  std::cout << "mirror plane P = " << exact_tuple(P.p) << "\n"
            << "reflection matrix M = [I - 2nnᵀ/(n·n), -2dn/(n·n); 0 0 0 1] (image = M V):\n";
  print_matrix(std::cout, M);
  for (const auto& V : points) print_point(std::cout, V, M * V, side_of(P, V));
  return 0;
}

const command_registration reflect_registration{command{
    "reflect", "exact planar reflection matrix about a plane and the images of points",
    [](CLI::App& app, const global_options& g) -> std::function<int()> {
      auto o = std::make_shared<reflect_options>();
      app.add_option("--plane", o->plane_text, "mirror plane a,b,c,d (a x + b y + c z + d = 0)")->required();
      app.add_option("--point", o->point_texts, "a point x,y,z to reflect (repeatable)");
      app.add_flag("--json", o->json, "print one JSON object with exact strings");
      return [o, &g] { return run_reflect(*o, g); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
