// OFF and OBJ mesh readers with exact numbers.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "shadowproof/core/error.h"
#include "shadowproof/clip/scene.h"

namespace shadowproof {

namespace {

[[noreturn]] void mesh_fail(errc code, const std::string& what, std::size_t line, const std::string& msg) {
  throw error(code, what + " line " + std::to_string(line) + ": " + msg);
}

// Text from a file shown in a message: at most 40 characters, control and non-ASCII bytes as
// \xNN, so a binary file cannot garble the terminal.
std::string printable(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < 40; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (text.size() > 40) out += "...";
  return out;
}

rational mesh_number(const std::string& text, const std::string& what, std::size_t line, const scene_limits& limits) {
  try {
    return parse_number(text, limits.numbers);
  } catch (const error& e) {
    mesh_fail(errc::scene_bad_number, what, line, "\"" + printable(text) + "\" is not a valid number: " + e.what());
  }
}

std::size_t mesh_count(const std::string& text, const std::string& what, std::size_t line, const char* name) {
  if (text.empty() || !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }) ||
      text.size() > 12)
    mesh_fail(errc::scene_mesh_malformed, what, line, std::string("expected a non-negative ") + name + ", found \"" + printable(text) + "\"");
  return std::stoull(text);
}

// Splits a line into whitespace-separated words, dropping a '#' comment.
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> w;
  std::istringstream in(line.substr(0, line.find('#')));
  std::string s;
  while (in >> s) w.push_back(s);
  return w;
}

}  // namespace

caster read_off(std::istream& in, const std::string& what, const scene_limits& limits) {
  // Collect the words of every line with their line numbers (OFF is free-form).
  std::vector<std::pair<std::string, std::size_t>> tokens;
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    for (auto& w : words(line)) tokens.emplace_back(std::move(w), n);
  }
  std::size_t pos = 0;
  const auto next = [&](const char* expected) -> const std::pair<std::string, std::size_t>& {
    if (pos >= tokens.size()) mesh_fail(errc::scene_mesh_malformed, what, n, std::string("unexpected end of file, expected ") + expected);
    return tokens[pos++];
  };
  const auto& head = next("\"OFF\"");
  if (head.first != "OFF") mesh_fail(errc::scene_mesh_malformed, what, head.second, "an OFF file starts with \"OFF\", found \"" + printable(head.first) + "\"");
  const auto& a = next("the vertex count");
  const std::size_t nv = mesh_count(a.first, what, a.second, "vertex count");
  const auto& b = next("the face count");
  const std::size_t nf = mesh_count(b.first, what, b.second, "face count");
  const auto& c = next("the edge count");
  mesh_count(c.first, what, c.second, "edge count");
  if (nv > limits.max_vertices) mesh_fail(errc::scene_too_large, what, a.second, std::to_string(nv) + " vertices; at most " + std::to_string(limits.max_vertices) + " (raise it with --max-vertices)");
  if (nf > limits.max_faces) mesh_fail(errc::scene_too_large, what, b.second, std::to_string(nf) + " faces; at most " + std::to_string(limits.max_faces) + " (raise it with --max-faces)");
  caster m;
  m.name = what;
  m.vertices.reserve(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    point3 p;
    for (int k = 0; k < 3; ++k) {
      const auto& t = next("a vertex coordinate");
      p[static_cast<std::size_t>(k)] = mesh_number(t.first, what, t.second, limits);
    }
    m.vertices.push_back(p);
  }
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& t = next("a face");
    const std::size_t line_no = t.second;
    const std::size_t k = mesh_count(t.first, what, line_no, "face size");
    if (k < 3) mesh_fail(errc::scene_empty_polygon, what, line_no, "face " + std::to_string(f) + " has " + std::to_string(k) + " vertices; at least 3");
    if (k > limits.max_face_vertices) mesh_fail(errc::scene_too_large, what, line_no, "face " + std::to_string(f) + " has more than " + std::to_string(limits.max_face_vertices) + " vertices (raise it with --max-face-vertices)");
    std::vector<std::size_t> face;
    for (std::size_t j = 0; j < k; ++j) {
      const auto& v = next("a vertex index");
      const std::size_t idx = mesh_count(v.first, what, v.second, "vertex index");
      if (idx >= nv) mesh_fail(errc::scene_bad_index, what, v.second, "face " + std::to_string(f) + ": vertex index " + std::to_string(idx) + " is out of range (" + std::to_string(nv) + " vertices)");
      if (std::find(face.begin(), face.end(), idx) != face.end())
        mesh_fail(errc::scene_repeated_index, what, v.second, "face " + std::to_string(f) + ": vertex index " + std::to_string(idx) + " appears twice");
      face.push_back(idx);
    }
    m.faces.push_back(std::move(face));
    // Anything left on the face's line (OFF colours) is ignored.
    while (pos < tokens.size() && tokens[pos].second == line_no) ++pos;
  }
  return m;
}

caster read_obj(std::istream& in, const std::string& what, const scene_limits& limits) {
  caster m;
  m.name = what;
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    const auto w = words(line);
    if (w.empty()) continue;
    if (w[0] == "v") {
      if (w.size() != 4 && w.size() != 5) mesh_fail(errc::scene_mesh_malformed, what, n, "a vertex is \"v x y z [w]\"");
      point3 p{mesh_number(w[1], what, n, limits), mesh_number(w[2], what, n, limits), mesh_number(w[3], what, n, limits)};
      if (w.size() == 5) {
        const rational h = mesh_number(w[4], what, n, limits);
        if (sgn(h) == 0) mesh_fail(errc::scene_mesh_malformed, what, n, "a vertex with w = 0 is not a finite point");
        for (auto& x : p) x /= h;
      }
      if (m.vertices.size() >= limits.max_vertices) mesh_fail(errc::scene_too_large, what, n, "more than " + std::to_string(limits.max_vertices) + " vertices (raise it with --max-vertices)");
      m.vertices.push_back(p);
    } else if (w[0] == "f") {
      if (w.size() < 4) mesh_fail(errc::scene_empty_polygon, what, n, "a face needs at least 3 vertices");
      if (w.size() - 1 > limits.max_face_vertices) mesh_fail(errc::scene_too_large, what, n, "the face has more than " + std::to_string(limits.max_face_vertices) + " vertices (raise it with --max-face-vertices)");
      std::vector<std::size_t> face;
      for (std::size_t j = 1; j < w.size(); ++j) {
        const std::string idx_text = w[j].substr(0, w[j].find('/'));
        const bool negative = !idx_text.empty() && idx_text[0] == '-';
        const std::size_t v = mesh_count(negative ? idx_text.substr(1) : idx_text, what, n, "vertex index");
        const std::size_t count = m.vertices.size();
        if (v == 0 || v > count)
          mesh_fail(errc::scene_bad_index, what, n, "vertex index " + idx_text + " is out of range (" + std::to_string(count) + " vertices so far)");
        const std::size_t index = negative ? count - v : v - 1;
        if (std::find(face.begin(), face.end(), index) != face.end())
          mesh_fail(errc::scene_repeated_index, what, n, "vertex index " + idx_text + " appears twice in the face");
        face.push_back(index);
      }
      if (m.faces.size() >= limits.max_faces) mesh_fail(errc::scene_too_large, what, n, "more than " + std::to_string(limits.max_faces) + " faces (raise it with --max-faces)");
      m.faces.push_back(std::move(face));
    }
  }
  return m;
}

caster read_mesh_file(const std::string& path, const std::string& what, const scene_limits& limits) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".off" && ext != ".obj")
    throw error(errc::scene_mesh_unreadable, what + ": '" + path + "' is neither an .off nor an .obj file");
  std::ifstream in(path);
  if (!in || std::filesystem::is_directory(path))
    throw error(errc::scene_mesh_unreadable, what + ": cannot open the mesh file '" + path + "'");
  check_file_size(path, limits);
  const std::string name = what + " ('" + path + "')";
  return ext == ".off" ? read_off(in, name, limits) : read_obj(in, name, limits);
}

}  // namespace shadowproof
