// shadowproof project: exact projection matrices in every common convention and the exact
// clip-space and NDC images of points.
#include <iostream>
#include <memory>

#include "command.h"
#include "print.h"
#include "projection_options.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof::cli {
namespace {

struct project_options {
  projection_options projection;
  std::vector<std::string> point_texts;
  bool json = false;
};

// Inside the canonical volume: clip-space test for gl/d3d/reverse-z; GAMES101 has w = z_eye < 0
// in front of the eye, so there: w < 0 and NDC in [−1, 1]³.
bool inside(const project_options& o, const projection& p, const vec4<rational>& image) {
  if (o.projection.kind != "games101") return in_clip_volume(image, p.convention);
  if (!(image[3] < 0)) return false;
  const auto ndc = ndc_of(image);
  for (const auto& x : *ndc)
    if (x < -1 || x > 1) return false;
  return true;
}

int run_project(const project_options& o, const global_options& g) {
  const projection p = build_projection(o.projection, g.limits, chosen_convention(o.projection));
  const auto points = parse_points(o.point_texts, g.limits);

  if (o.json) {
    nlohmann::json doc;
    doc["projection"] = o.projection.kind;
    doc["convention"] = o.projection.kind == "games101" ? "games101" : std::string(to_string(p.convention));
    doc["matrix"] = exact_json(p.matrix);
    doc["points"] = nlohmann::json::array();
    for (const auto& V : points) {
      const vec4<rational> image = p.matrix * V;
      const auto ndc = ndc_of(image);
      doc["points"].push_back(
          {{"input", exact_json(std::vector<rational>{V[0], V[1], V[2]})},
           {"image", exact_json(image)},
           {"ndc", ndc ? exact_json(std::vector<rational>(ndc->begin(), ndc->end())) : nlohmann::json(nullptr)},
           {"inside", inside(o, p, image)}});
    }
    std::cout << doc.dump(2) << '\n';
    return 0;
  }
  std::cout << p.description << "\n"
            << "matrix M (clip = M X, NDC = (x, y, z) / w):\n";
  print_matrix(std::cout, p.matrix);
  for (const auto& V : points) {
    const vec4<rational> image = p.matrix * V;
    const auto ndc = ndc_of(image);
    std::cout << "point " << exact_tuple(std::vector<rational>{V[0], V[1], V[2]}) << ":\n"
              << "  image  " << exact_tuple(image) << "\n"
              << "  ndc    "
              << (ndc ? exact_tuple(std::vector<rational>(ndc->begin(), ndc->end())) : std::string("none (w = 0)"))
              << "\n"
              << "  " << (inside(o, p, image) ? "inside" : "outside") << " the canonical view volume\n";
  }
  return 0;
}

const command_registration project_registration{command{
    "project",
    "exact projection matrix (ortho, oblique, frustum, perspective, games101) in the gl, d3d or "
    "reverse-z depth convention, and the exact images of points",
    [](CLI::App& app, const global_options& g) -> std::function<int()> {
      auto o = std::make_shared<project_options>();
      add_projection_options(app, o->projection, {"ortho", "oblique", "frustum", "perspective", "games101"}, "");
      app.add_option("--point", o->point_texts, "an eye-space point x,y,z to project (repeatable)");
      app.add_flag("--json", o->json, "print one JSON object with exact strings");
      return [o, &g] { return run_project(*o, g); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
