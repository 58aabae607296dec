// shadowproof normal-matrix: the exact normal matrix G = (M⁻¹)ᵀ of a 4x4 matrix, its
// division-free adjugate form, and the exact images of normals.
#include <iostream>
#include <memory>

#include "command.h"
#include "print.h"
#include "shadowproof/constructions/normal_matrix.h"

namespace shadowproof::cli {
namespace {

struct normal_matrix_options {
  std::string matrix_text;
  std::vector<std::string> normal_texts;
  bool json = false;
};

int run_normal_matrix(const normal_matrix_options& o, const global_options& g) {
  const auto entries = parse_number_list(o.matrix_text, 16, "--matrix", g.limits);
  mat4<rational> M;
  for (std::size_t i = 0; i < 16; ++i) M(i / 4, i % 4) = entries[i];
  std::vector<vec4<rational>> normals;
  for (const auto& t : o.normal_texts) {
    const auto n = parse_number_list(t, 3, "--normal", g.limits);
    normals.push_back(make_vec4(n[0], n[1], n[2], rational(0)));
  }
  const mat4<rational> G = normal_matrix(M);  // throws matrix.singular
  const mat4<rational> C = normal_matrix_adjugate(M);
  const rational det = determinant(M);

  // The image of the plane (n, 0) through the origin is G (n, 0); its normal is the first three.
  auto image_normal = [&](const vec4<rational>& n) {
    const vec4<rational> P = G * n;
    return std::vector<rational>{P[0], P[1], P[2]};
  };
  if (o.json) {
    nlohmann::json doc;
    doc["matrix"] = exact_json(G);
    doc["input"] = exact_json(M);
    doc["determinant"] = to_string(det);
    doc["adjugate_form"] = exact_json(C);
    doc["normals"] = nlohmann::json::array();
    for (const auto& n : normals)
      doc["normals"].push_back({{"input", exact_json(std::vector<rational>{n[0], n[1], n[2]})},
                                {"image", exact_json(image_normal(n))}});
    std::cout << doc.dump(2) << '\n';
    return 0;
  }
  std::cout << "M (points X map to M X):\n";
  print_matrix(std::cout, M);
  std::cout << "det M = " << to_string(det) << "\n"
            << "normal matrix G = (M⁻¹)ᵀ (planes P map to G P, normals n to the xyz of G (n, 0)):\n";
  print_matrix(std::cout, G);
  std::cout << "division-free form cof(M) = adj(M)ᵀ = det(M) G:\n";
  print_matrix(std::cout, C);
  for (const auto& n : normals)
    std::cout << "normal " << exact_tuple(std::vector<rational>{n[0], n[1], n[2]}) << " -> "
              << exact_tuple(image_normal(n)) << "\n";
  return 0;
}

const command_registration normal_matrix_registration{command{
    "normal-matrix", "exact normal matrix G = (M⁻¹)ᵀ, its adjugate form and the images of normals",
    [](CLI::App& app, const global_options& g) -> std::function<int()> {
      auto o = std::make_shared<normal_matrix_options>();
      app.add_option("--matrix", o->matrix_text, "the 16 entries m00,m01,...,m33 of M, row by row")->required();
      app.add_option("--normal", o->normal_texts, "a normal x,y,z to transform (repeatable)");
      app.add_flag("--json", o->json, "print one JSON object with exact strings");
      return [o, &g] { return run_normal_matrix(*o, g); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
