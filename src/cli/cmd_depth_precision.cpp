// shadowproof depth-precision: how many distinct depth-buffer values an eye-depth interval
// gets, and the eye-space gap between consecutive stored depths, exactly, for gl, d3d and
// reverse-z side by side.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "command.h"
#include "shadowproof/core/io.h"
#include "shadowproof/core/svg.h"
#include "print.h"
#include "projection_options.h"
#include "shadowproof/constructions/depth_precision.h"
#include "shadowproof/core/error.h"

namespace shadowproof::cli {
namespace {

struct depth_precision_options {
  projection_options projection;
  std::string from_text, to_text, format_text;
  std::vector<std::string> at_texts;
  bool json = false;
  std::string svg_path;
};

const depth_convention all_conventions[] = {depth_convention::gl, depth_convention::d3d,
                                            depth_convention::reverse_z};

// "≈1.234e-05": an explicitly approximate decimal for the text table (exact values: --json).
std::string approx(const rational& q) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "~%.4g", to_nearest_double(q));
  return buf;
}

// `count` distances from..to in geometric progression, each rounded to `digits` significant
// decimal digits and read back exactly; the ends are exact. They are only where to sample.
std::vector<rational> geometric_samples(const rational& from, const rational& to, int count, int digits) {
  std::vector<rational> s{from};
  const double a = to_nearest_double(from), b = to_nearest_double(to);
  for (int i = 1; i + 1 < count; ++i) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*e", digits - 1, a * std::pow(b / a, double(i) / (count - 1)));
    const rational x = parse_number(buf);
    if (x > s.back() && x < to) s.push_back(x);
  }
  s.push_back(to);
  return s;
}

nlohmann::json sample_json(const depth_sample& s) {
  return {{"distance", to_string(s.distance)},
          {"depth", to_string(s.depth)},
          {"stored", to_string(s.stored)},
          {"stored_distance", s.stored_distance ? nlohmann::json(to_string(*s.stored_distance)) : nlohmann::json(nullptr)},
          {"spacing", s.spacing ? nlohmann::json(to_string(*s.spacing)) : nlohmann::json(nullptr)}};
}

void write_svg(const std::string& path, const std::string& title, const std::vector<rational>& distances,
               const std::vector<depth_precision_report>& reports) {
  const double width = 800, height = 480, left = 80, right = 240, top = 40, bottom = 60;
  double x0 = std::log10(to_nearest_double(distances.front())), x1 = std::log10(to_nearest_double(distances.back()));
  double y0 = 1e300, y1 = -1e300;
  for (const auto& r : reports)
    for (const auto& s : r.samples)
      if (s.spacing && *s.spacing > 0) {
        const double y = std::log10(to_nearest_double(*s.spacing));
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
  if (y0 > y1) y0 = y1 = 0;
  y0 = std::floor(y0);
  y1 = std::ceil(y1);
  if (y1 <= y0) y1 = y0 + 1;
  x0 = std::floor(x0 * 10) / 10;
  x1 = std::ceil(x1 * 10) / 10;
  if (x1 <= x0) x1 = x0 + 1;
  auto px = [&](double lx) { return left + (lx - x0) / (x1 - x0) * (width - left - right); };
  auto py = [&](double ly) { return height - bottom - (ly - y0) / (y1 - y0) * (height - top - bottom); };
  svg_document out(width, height, 12, 2);
  out.text(left, 20, title);
  // Axes and decade grid lines (log scale on both axes), at most about 10 labelled decades each.
  const int y_step = std::max(1, static_cast<int>(std::ceil((y1 - y0) / 10)));
  const int x_step = std::max(1, static_cast<int>(std::ceil((x1 - x0) / 10)));
  for (int e = static_cast<int>(std::ceil(y0)); e <= static_cast<int>(y1); e += y_step) {
    out.line(left, py(e), width - right, py(e), "#ddd");
    out.text(left - 6, py(e) + 4, "1e" + std::to_string(e), "end");
  }
  for (int e = static_cast<int>(std::ceil(x0)); e <= static_cast<int>(std::floor(x1)); e += x_step) {
    out.line(px(e), top, px(e), height - bottom, "#ddd");
    out.text(px(e), height - bottom + 16, "1e" + std::to_string(e), "middle");
  }
  out.rect(left, top, width - left - right, height - top - bottom, "none", "black");
  out.text((left + width - right) / 2, height - 20, "eye distance (log scale)", "middle");
  out.text(20, (top + height - bottom) / 2, "gap between consecutive stored depths (log scale)", "middle", "", 0, -90);
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c"};
  for (std::size_t k = 0; k < reports.size(); ++k) {
    std::vector<std::pair<double, double>> points;
    for (const auto& s : reports[k].samples)
      if (s.spacing && *s.spacing > 0)
        points.emplace_back(px(std::log10(to_nearest_double(s.distance))), py(std::log10(to_nearest_double(*s.spacing))));
    out.polyline(points, colours[k % 3], 1.5);
    out.text(width - right + 10, top + 20 + 18 * k,
             std::string(to_string(reports[k].convention)) + " (" + std::to_string(reports[k].distinct_values) + " values)",
             "start", colours[k % 3]);
  }
  write_file_atomically(path, out.str());
}

int run_depth_precision(const depth_precision_options& o, const global_options& g) {
  const depth_convention chosen = chosen_convention(o.projection);
  if (o.projection.handedness_option->count() > 0)
    throw error(errc::cli_unused_option, "--handedness does not apply to depth-precision, which measures eye "
                                         "distances along -z");
  const depth_format format = parse_depth_format(o.format_text);
  const rational from = parse_flag_number(o.from_text, "--from", g.limits);
  const rational to = parse_flag_number(o.to_text, "--to", g.limits);
  std::vector<rational> at;
  for (const auto& t : o.at_texts) at.push_back(parse_flag_number(t, "--at", g.limits));
  if (at.empty() && from > 0 && from < to) at = geometric_samples(from, to, 7, 3);

  std::vector<depth_precision_report> reports;
  projection chosen_projection;
  for (const depth_convention c : all_conventions) {
    const projection p = build_projection(o.projection, g.limits, c);
    if (c == chosen) chosen_projection = p;
    reports.push_back(depth_precision(p.matrix, c, format, from, to, at));
  }
  const depth_precision_report& main_report = reports[static_cast<std::size_t>(chosen)];

  if (!o.svg_path.empty()) {
    // The plot samples [from, to): at exactly the far plane a reverse-z depth is 0, where the
    // gap to the nearest subnormal is ~1e-38 and would flatten every other curve.
    auto dense = geometric_samples(from, to, 121, 6);
    dense.pop_back();
    std::vector<depth_precision_report> plot;
    for (const depth_convention c : all_conventions)
      plot.push_back(depth_precision(build_projection(o.projection, g.limits, c).matrix, c, format, from, to, dense));
    write_svg(o.svg_path, "depth-buffer precision, " + std::string(to_string(format)) + ", " + o.projection.kind +
                                  ", eye distances [" + to_string(from) + ", " + to_string(to) + "]",
              dense, plot);
  }

  if (o.json) {
    nlohmann::json doc;
    doc["projection"] = o.projection.kind;
    doc["matrix"] = exact_json(chosen_projection.matrix);
    doc["convention"] = std::string(to_string(chosen));
    doc["format"] = std::string(to_string(format));
    doc["from"] = to_string(from);
    doc["to"] = to_string(to);
    doc["distinct_values"] = main_report.distinct_values;
    doc["samples"] = nlohmann::json::array();
    for (const auto& s : main_report.samples) doc["samples"].push_back(sample_json(s));
    doc["comparison"] = nlohmann::json::array();
    for (const auto& r : reports) {
      nlohmann::json c{{"convention", std::string(to_string(r.convention))},
                       {"depth_from", to_string(r.depth_from)},
                       {"depth_to", to_string(r.depth_to)},
                       {"distinct_values", r.distinct_values},
                       {"samples", nlohmann::json::array()}};
      for (const auto& s : r.samples) c["samples"].push_back(sample_json(s));
      doc["comparison"].push_back(c);
    }
    std::cout << doc.dump(2) << '\n';
    return 0;
  }

  std::cout << chosen_projection.description << "\n"
            << (format == depth_format::f32
                    ? "format f32: the NDC depth z_ndc rounded to the nearest binary32\n"
                    : "format unorm24: the window depth (gl: (z_ndc + 1)/2; d3d, reverse-z: z_ndc) rounded "
                      "to the nearest k/(2^24 - 1)\n")
            << "eye distances [" << to_string(from) << ", " << to_string(to) << "]\n\n"
            << "  convention   distinct stored depth values\n";
  for (const auto& r : reports)
    std::cout << "  " << std::left << std::setw(12) << to_string(r.convention) << " " << r.distinct_values << "\n";
  std::cout << "\ngap between consecutive stored depths at each distance, in eye units\n"
            << "(decimal approximations marked ~; the exact rationals are in --json)\n"
            << "  " << std::setw(14) << "distance";
  for (const auto& r : reports) std::cout << std::setw(14) << to_string(r.convention);
  std::cout << "\n";
  for (std::size_t i = 0; i < at.size(); ++i) {
    std::cout << "  " << std::setw(14) << to_string(at[i]);
    for (const auto& r : reports) {
      const auto& s = r.samples[i].spacing;
      std::cout << std::setw(14) << (s ? approx(*s) : std::string("none"));
    }
    std::cout << "\n";
  }
  if (!o.svg_path.empty()) std::cout << "\nplot written to " << o.svg_path << "\n";
  return 0;
}

const command_registration depth_precision_registration{command{
    "depth-precision",
    "exact depth-buffer precision of a projection over an eye-depth interval: distinct stored "
    "values and eye-space gaps, gl vs d3d vs reverse-z",
    [](CLI::App& app, const global_options& g) -> std::function<int()> {
      auto o = std::make_shared<depth_precision_options>();
      add_projection_options(app, o->projection, {"ortho", "frustum", "perspective"}, "perspective");
      app.add_option("--from", o->from_text, "nearest eye distance of the interval (> 0)")->required();
      app.add_option("--to", o->to_text, "farthest eye distance of the interval")->required();
      app.add_option("--format", o->format_text, "depth buffer: f32 (binary32) or unorm24 (24-bit fixed)")
          ->required();
      app.add_option("--at", o->at_texts, "an eye distance where to report the gap (repeatable; default: 7 "
                                          "distances in geometric progression)");
      app.add_flag("--json", o->json, "print one JSON object with exact strings");
      app.add_option("--svg", o->svg_path, "write a plot of gap vs distance (log-log) to this SVG file");
      return [o, &g] { return run_depth_precision(*o, g); };
    }}};

}  // namespace
}  // namespace shadowproof::cli
