#include "print.h"

#include <algorithm>

namespace shadowproof::cli {

nlohmann::json exact_json(const std::vector<rational>& values) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& q : values) a.push_back(to_string(q));
  return a;
}

nlohmann::json exact_json(const vec4<rational>& v) {
  return exact_json(std::vector<rational>(v.v.begin(), v.v.end()));
}

nlohmann::json exact_json(const mat4<rational>& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : m.m) rows.push_back(exact_json(std::vector<rational>(row.begin(), row.end())));
  return rows;
}

void print_matrix(std::ostream& out, const mat4<rational>& m, const std::string& indent) {
  std::size_t width = 0;
  for (const auto& row : m.m)
    for (const auto& x : row) width = std::max(width, to_string(x).size());
  for (const auto& row : m.m) {
    out << indent << "[";
    for (std::size_t j = 0; j < 4; ++j) {
      std::string s = to_string(row[j]);
      out << std::string(width - s.size() + (j == 0 ? 0 : 1), ' ') << s;
    }
    out << " ]\n";
  }
}

std::string exact_tuple(const std::vector<rational>& values) {
  std::string s = "(";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + to_string(values[i]);
  return s + ")";
}

std::string exact_tuple(const vec4<rational>& v) {
  return exact_tuple(std::vector<rational>(v.v.begin(), v.v.end()));
}

std::optional<std::vector<rational>> affine_part(const vec4<rational>& v) {
  if (v[3] == 0) return std::nullopt;
  return std::vector<rational>{v[0] / v[3], v[1] / v[3], v[2] / v[3]};
}

nlohmann::json point_json(const vec4<rational>& V, const vec4<rational>& image, std::string_view cls) {
  const auto affine = affine_part(image);
  return {{"input", exact_json(std::vector<rational>{V[0], V[1], V[2]})},
          {"image", exact_json(image)},
          {"affine", affine ? exact_json(*affine) : nlohmann::json(nullptr)},
          {"class", std::string(cls)}};
}

void print_point(std::ostream& out, const vec4<rational>& V, const vec4<rational>& image, std::string_view cls) {
  const auto affine = affine_part(image);
  out << "point " << exact_tuple(std::vector<rational>{V[0], V[1], V[2]}) << ":\n"
      << "  class  " << cls << "\n"
      << "  image  " << exact_tuple(image) << "\n"
      << "  affine " << (affine ? exact_tuple(*affine) : std::string("none (w = 0)")) << "\n";
}

std::vector<vec4<rational>> parse_points(const std::vector<std::string>& texts, const number_limits& limits) {
  std::vector<vec4<rational>> points;
  for (const auto& t : texts) {
    auto xyz = parse_number_list(t, 3, "--point", limits);
    points.push_back(make_point(xyz[0], xyz[1], xyz[2]));
  }
  return points;
}

}  // namespace shadowproof::cli
