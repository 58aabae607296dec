// shadowproof shadow: the exact planar shadow matrix, images and classes of points.
#include <iostream>

#include "command.h"
#include "print.h"
#include "shadowproof/constructions/classify.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof::cli {
namespace {

struct shadow_options {
  std::string plane_text, light_text;
  std::vector<std::string> point_texts;
  bool json = false;
};

std::string describe_light(const light<rational>& L) {
  if (L.is_directional())
    return "directional light towards " + exact_tuple(std::vector<rational>{L.l[0], L.l[1], L.l[2]});
  return "point light at " + exact_tuple(*affine_part(L.l));
}

int run_shadow(const shadow_options& o, const global_options& g) {
  auto p = parse_number_list(o.plane_text, 4, "--plane", g.limits);
  auto l = parse_number_list(o.light_text, 4, "--light", g.limits);
  const plane<rational> P = make_plane(p[0], p[1], p[2], p[3]);
  const light<rational> L = make_light(l[0], l[1], l[2], l[3]);
  const auto points = parse_points(o.point_texts, g.limits);
  const mat4<rational> M = shadow_matrix(P, L);

  if (o.json) {
    nlohmann::json doc;
    doc["matrix"] = exact_json(M);
    doc["points"] = nlohmann::json::array();
    for (const auto& V : points)
      doc["points"].push_back(point_json(V, M * V, to_string(classify_point(P, L, V))));
    std::cout << doc.dump(2) << '\n';
    return 0;
  }
  std::cout << "plane P = " << exact_tuple(P.p) << ", light L = " << exact_tuple(L.l) << " ("
            << describe_light(L) << ")\n"
            << "P·L = " << to_string(dot(P.p, L.l)) << "\n"
            << "shadow matrix M = (P·L) I - L Pᵀ (image = M V):\n";
  print_matrix(std::cout, M);
  for (const auto& V : points) print_point(std::cout, V, M * V, to_string(classify_point(P, L, V)));
  return 0;
}

const command_registration shadow_registration{command{
    "shadow", "exact planar shadow matrix M = (P·L) I - L Pᵀ and the image and class of points",
    [](CLI::App& app, const global_options& g) -> std::function<int()> {
      auto o = std::make_shared<shadow_options>();
      app.add_option("--plane", o->plane_text, "receiver plane a,b,c,d (a x + b y + c z + d = 0)")->required();
      app.add_option("--light", o->light_text,
                     "light x,y,z,w: w != 0 point light at (x,y,z)/w, w = 0 directional towards (x,y,z)")
          ->required();
      app.add_option("--point", o->point_texts, "a point x,y,z to project (repeatable)");
      app.add_flag("--json", o->json, "print one JSON object with exact strings");
      return [o, &g] { return run_shadow(*o, g); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
