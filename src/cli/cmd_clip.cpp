// shadowproof clip: the exact shadow region of a scene file.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "command.h"
#include "shadowproof/clip/shadow_region.h"
#include "shadowproof/core/io.h"
#include "shadowproof/core/error.h"
#include "shadowproof/clip/svg.h"

namespace shadowproof::cli {

namespace {

nlohmann::json exact2(const point2& p) { return nlohmann::json::array({to_string(p[0]), to_string(p[1])}); }
nlohmann::json exact3(const point3& p) { return nlohmann::json::array({to_string(p[0]), to_string(p[1]), to_string(p[2])}); }

// A progress bar on stderr for runs longer than half a second, when stderr is a terminal;
// redrawn at most ten times a second and erased at the end.
class stage_progress_bar {
 public:
  stage_progress_bar() : enabled_(::isatty(2) != 0), start_(std::chrono::steady_clock::now()) {}
  ~stage_progress_bar() {
    if (drawn_) std::cerr << "\r\033[K" << std::flush;
  }
  void operator()(std::string_view stage, double fraction) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - start_ < std::chrono::milliseconds(500) || now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    drawn_ = true;
    const int width = 30, filled = static_cast<int>(fraction * width + 0.5);
    std::cerr << "\r[" << std::string(static_cast<std::size_t>(std::clamp(filled, 0, width)), '#')
              << std::string(static_cast<std::size_t>(width - std::clamp(filled, 0, width)), '.') << "] "
              << static_cast<int>(fraction * 100 + 0.5) << "% " << stage << "\033[K" << std::flush;
  }

 private:
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_, last_{};
};

template <class P, class F>
nlohmann::json ring_json(const std::vector<P>& ring, F f) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& p : ring) a.push_back(f(p));
  return a;
}

nlohmann::json region_json(const shadow_region& r) {
  nlohmann::json j;
  j["polygons"] = nlohmann::json::array();
  for (const auto& p : r.polygons) {
    nlohmann::json q;
    q["outer"] = ring_json(p.outer_3d, exact3);
    q["holes"] = nlohmann::json::array();
    for (const auto& h : p.holes_3d) q["holes"].push_back(ring_json(h, exact3));
    q["outer_chart"] = ring_json(p.outer, exact2);
    q["holes_chart"] = nlohmann::json::array();
    for (const auto& h : p.holes) q["holes_chart"].push_back(ring_json(h, exact2));
    j["polygons"].push_back(q);
  }
  j["area_squared"] = to_string(r.area_squared);
  j["area_approx"] = approximate_area(r);
  j["chart"] = {{"dropped_axis", std::string(r.chart.axis_name(2))},
                {"axes", {std::string(r.chart.axis_name(0)), std::string(r.chart.axis_name(1))}},
                {"area", to_string(r.chart_area)},
                {"area_scale_squared", to_string(r.chart.area_scale_squared)},
                {"receiver_plane", {to_string(r.chart.receiver_plane.a()), to_string(r.chart.receiver_plane.b()),
                                    to_string(r.chart.receiver_plane.c()), to_string(r.chart.receiver_plane.d())}}};
  nlohmann::json segs = nlohmann::json::array(), pts = nlohmann::json::array();
  nlohmann::json segs2 = nlohmann::json::array(), pts2 = nlohmann::json::array();
  for (const auto& d : r.degenerate) {
    if (d.is_point()) {
      pts.push_back(exact3(d.a_3d));
      pts2.push_back(exact2(d.a));
    } else {
      // json::array: a braced pair of two-element arrays would become a JSON object.
      segs.push_back(nlohmann::json::array({exact3(d.a_3d), exact3(d.b_3d)}));
      segs2.push_back(nlohmann::json::array({exact2(d.a), exact2(d.b)}));
    }
  }
  j["degenerate"] = {{"segments", segs}, {"points", pts}, {"segments_chart", segs2}, {"points_chart", pts2}};
  j["cases"] = nlohmann::json::array();
  for (auto c : r.cases) j["cases"].push_back(std::string(to_string(c)));
  return j;
}

nlohmann::json comparison_json(const float_comparison& c) {
  return {{"float_polygons", c.float_polygons},
          {"invalid_polygons", c.invalid_polygons},
          {"non_finite_vertices", c.non_finite_vertices},
          {"vertices_outside_receiver", c.vertices_outside_receiver},
          {"receiver_convex", c.receiver_convex},
          {"float_area", to_string(c.float_area)},
          {"exact_area", to_string(c.exact_area)},
          {"false_shadow_area", to_string(c.false_shadow_area)},
          {"missing_shadow_area", to_string(c.missing_shadow_area)},
          {"missing_pieces", c.missing_pieces},
          {"outside_receiver_area", to_string(c.outside_receiver_area)}};
}

struct clip_args {
  std::string scene_file;
  std::string svg_file;
  bool json = false;
  bool compare_float = false;
  std::string method = "automatic";
  scene_limits limits;  ///< every cap a hostile scene could hit, each raised by its own flag
};

}  // namespace

static const command_registration clip_registration{command{
    "clip",
    "exact shadow region of casters (polygons, meshes, OFF/OBJ files) on a finite receiver polygon",
    [](CLI::App& app, const global_options& globals) -> std::function<int()> {
      auto args = std::make_shared<clip_args>();
      app.add_option("scene", args->scene_file, "scene JSON file (see docs: receiver, light, casters)")->required();
      app.add_flag("--json", args->json, "print the region as JSON with exact rational strings");
      app.add_option("--svg", args->svg_file, "write a picture of the region in the receiver's chart");
      app.add_flag("--compare-float", args->compare_float,
                   "also run the float pipeline (float shadow matrix + Sutherland-Hodgman) and report its errors");
      app.add_option("--method", args->method,
                     "how the projected faces are combined: automatic, silhouette (boundary chains and winding "
                     "numbers) or union (the reference: an exact union of every clipped piece); all give the same region")
          ->check(CLI::IsMember({"automatic", "silhouette", "union"}))
          ->capture_default_str();
      auto& lim = args->limits;
      app.add_option("--max-vertices", lim.max_vertices, "most caster vertices in a scene")->capture_default_str();
      app.add_option("--max-faces", lim.max_faces, "most caster faces in a scene")->capture_default_str();
      app.add_option("--max-face-vertices", lim.max_face_vertices, "most vertices of one face or polygon")
          ->capture_default_str();
      app.add_option("--max-json-depth", lim.max_json_depth, "deepest JSON nesting")->capture_default_str();
      app.add_option("--max-json-values", lim.max_json_values, "most values in the scene JSON")->capture_default_str();
      app.add_option("--max-file-bytes", lim.max_file_bytes, "largest scene or mesh file")->capture_default_str();
      return [args, &globals]() -> int {
        scene_limits limits = args->limits;
        limits.numbers = globals.limits;
        const scene s = read_scene_file(args->scene_file, limits);
        clip_options options;
        options.limits = limits;
        options.keep_projected = !args->svg_file.empty();
        options.method = args->method == "union"        ? clip_method::union_of_pieces
                         : args->method == "silhouette" ? clip_method::silhouette
                                                        : clip_method::automatic;
        auto bar = std::make_shared<stage_progress_bar>();
        options.progress = [bar](std::string_view stage, double fraction) { (*bar)(stage, fraction); };
        const shadow_region r = compute_shadow_region(s, options);
        bar.reset();
        if (!args->svg_file.empty()) {
          std::ostringstream svg;
          write_svg(svg, r, "shadow of " + args->scene_file);
          write_file_atomically(args->svg_file, svg.str());
        }
        std::unique_ptr<float_comparison> cmp;
        if (args->compare_float) cmp = std::make_unique<float_comparison>(compare_with_float(s, r));
        if (args->json) {
          nlohmann::json j = region_json(r);
          if (cmp) j["float_comparison"] = comparison_json(*cmp);
          std::cout << j.dump(2) << '\n';
        } else {
          print_region_report(std::cout, r);
          if (cmp) print_float_comparison(std::cout, *cmp);
        }
        return 0;
      };
    }}};

}  // namespace shadowproof::cli
