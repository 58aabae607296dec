// shadowproof demo: a bundled scene, its exact shadow matrices, classes and on-plane check.
#include <iostream>
#include <sstream>

#include "command.h"
#include "print.h"
#include "shadowproof/constructions/classify.h"
#include "shadowproof/clip/shadow_region.h"
#include "shadowproof/core/io.h"
#include "shadowproof/clip/svg.h"
#include "shadowproof/constructions/reflect.h"
#include "shadowproof/constructions/shadow.h"

namespace shadowproof::cli {
namespace {

struct demo_light {
  const char* name;
  light<rational> L;
};

// A caster (a tilted quad between heights 1 and 2) plus probe points chosen to reach every
// class: below the ground, on it, at and beyond the point light's height, and the light itself.
std::vector<vec4<rational>> demo_points() {
  auto pt = [](rational x, rational y, rational z) { return make_point(x, y, z); };
  return {pt(0, 1, 0),        pt(1, 1, 0),  pt(1, 2, 1),  pt(0, 2, 1),   // the caster
          pt(rational(1, 2), 0, 3), pt(1, -1, 1),                         // on and below the ground
          pt(-1, 5, 0),       pt(0, 7, 0),  pt(2, 5, 1)};                 // light height, beyond, light
}

int run_demo() {
  const plane<rational> ground = make_plane<rational>(0, 1, 0, 0);
  const std::vector<demo_light> lights = {
      {"point light at (2, 5, 1)", make_light<rational>(2, 5, 1, 1)},
      {"directional light towards (1, 2, 1)", make_light<rational>(1, 2, 1, 0)},
      {"degenerate: directional light parallel to the ground, towards (1, 0, 0)",
       make_light<rational>(1, 0, 0, 0)},
  };
  std::cout << "shadowproof demo: receiver = ground plane y = 0, P = " << exact_tuple(ground.p) << "\n"
            << "caster = quad (0,1,0) (1,1,0) (1,2,1) (0,2,1); extra probe points reach every class\n";
  std::size_t shadows = 0, on_plane = 0, images = 0;
  for (const auto& [name, L] : lights) {
    const mat4<rational> M = shadow_matrix(ground, L);
    std::cout << "\n== " << name << ", L = " << exact_tuple(L.l) << ", P·L = " << to_string(dot(ground.p, L.l))
              << "\nM = (P·L) I - L Pᵀ =\n";
    print_matrix(std::cout, M);
    for (const auto& V : demo_points()) {
      const vec4<rational> image = M * V;
      const point_class c = classify_point(ground, L, V);
      const auto affine = affine_part(image);
      std::cout << "  " << exact_tuple(std::vector<rational>{V[0], V[1], V[2]}) << " -> "
                << (affine ? exact_tuple(*affine) : exact_tuple(image) + " (homogeneous)") << "  "
                << to_string(c) << "\n";
      ++images;
      if (!is_zero(image) && evaluate(ground, image) == 0) ++on_plane;
      if (c == point_class::shadow) ++shadows;
    }
  }
  // The exact check: P·(M V) = 0 for every image that is a point (not the zero vector).
  std::size_t zero_images = 0;
  for (const auto& [name, L] : lights)
    for (const auto& V : demo_points()) zero_images += is_zero(shadow_matrix(ground, L) * V) ? 1 : 0;
  const bool ok = on_plane + zero_images == images;
  std::cout << "\nexact check: " << on_plane << " of " << images - zero_images
            << " non-zero images satisfy P·(M V) = 0 exactly (" << shadows << " real shadows, "
            << zero_images << " zero images: the light itself or a line in the plane) -> "
            << (ok ? "OK" : "FAILED") << "\n";

  const plane<rational> mirror = make_plane<rational>(1, 2, 2, -3);
  const mat4<rational> R = reflection_matrix(mirror);
  const bool involution = R * R == identity4<rational>();
  std::cout << "\nreflection about x + 2y + 2z - 3 = 0:\n";
  print_matrix(std::cout, R);
  std::cout << "exact check: M² = I -> " << (involution ? "OK" : "FAILED")
            << ", det M = " << to_string(determinant(R)) << "\n";
  return ok && involution ? 0 : 1;
}

// The exact shadow region of the bundled clipping scene (examples/scenes/demo.json), with its
// picture when asked for one.
void run_clip_demo(const std::string& svg_path) {
  std::cout << "\n== exact shadow region on a finite receiver (examples/scenes/demo.json)\n";
  clip_options options;
  options.keep_projected = !svg_path.empty();
  const shadow_region region = compute_shadow_region(make_demo_scene(), options);
  print_region_report(std::cout, region);
  if (!svg_path.empty()) {
    std::ostringstream svg;
    write_svg(svg, region, "shadowproof demo: exact shadow on the receiver");
    write_file_atomically(svg_path, svg.str());
    std::cout << "picture written to " << svg_path << "\n";
  }
}

const command_registration demo_registration{command{
    "demo", "run the bundled example scene: matrices, classes and exact checks",
    [](CLI::App& app, const global_options&) -> std::function<int()> {
      auto svg_path = std::make_shared<std::string>();
      app.add_option("--svg", *svg_path, "also draw the clipping example's exact shadow region to this SVG file");
      return [svg_path] {
        const int code = run_demo();
        run_clip_demo(*svg_path);
        return code;
      };
    }}};

}  // namespace
}  // namespace shadowproof::cli
