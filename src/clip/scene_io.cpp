// Scene files: JSON read through nlohmann's SAX interface so that every JSON number keeps its
// literal text and is parsed exactly (0.1 is 1/10, never the double nearest to it).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "shadowproof/clip/scene.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/io.h"

namespace shadowproof {

namespace {

using json = nlohmann::json;

// Numbers are stored in the DOM as strings carrying this prefix, so a JSON number is never
// turned into a double and can still be told apart from a JSON string.
constexpr char number_mark = '\x01';

// Builds a json DOM like nlohmann's own DOM parser, except for numbers (see above).
class exact_sax {
 public:
  exact_sax(json& root, const scene_limits& limits) : root_(root), limits_(limits) {}

  bool null() { return add(json(nullptr)); }
  bool boolean(bool v) { return add(json(v)); }
  bool number_integer(json::number_integer_t v) { return add(json(number_mark + std::to_string(v))); }
  bool number_unsigned(json::number_unsigned_t v) { return add(json(number_mark + std::to_string(v))); }
  bool number_float(json::number_float_t, const json::string_t& text) {
    return add(json(number_mark + text));
  }
  bool string(json::string_t& v) { return add(json(v)); }
  bool binary(json::binary_t&) { return add(json(nullptr)); }
  bool start_object(std::size_t) {
    json* j = place(json::object());
    enter();
    stack_.push_back(j);
    return true;
  }
  bool key(json::string_t& k) {
    // nlohmann keeps the last of duplicate keys silently; a scene with two "light"s is ambiguous.
    if (stack_.back()->contains(k))
      throw error(errc::scene_duplicate_key, current_path(false) + ": the key \"" + k + "\" appears twice");
    key_ = k;
    return true;
  }
  bool end_object() {
    stack_.pop_back();
    return true;
  }
  bool start_array(std::size_t) {
    json* j = place(json::array());
    enter();
    stack_.push_back(j);
    return true;
  }
  bool end_array() {
    stack_.pop_back();
    return true;
  }
  bool parse_error(std::size_t, const std::string& token, const nlohmann::detail::exception& ex) {
    // nlohmann refuses number literals beyond the double range (id 406) before we see their
    // text; a string keeps them exact.
    if (ex.id == 406)
      throw error(errc::scene_json, "the JSON number " + token + " is beyond the range nlohmann/json accepts; "
                  "write it as a string (\"" + token + "\") to read it exactly");
    throw error(errc::scene_json, std::string("the scene is not valid JSON: ") + ex.what());
  }

 private:
  // Depth is capped so a hostile document cannot exhaust memory or the stack later on.
  void enter() {
    if (stack_.size() + 1 > limits_.max_json_depth)
      throw error(errc::scene_too_deep, current_path(true) + ": JSON nested deeper than " +
                                        std::to_string(limits_.max_json_depth) +
                                        " levels (raise it with --max-json-depth)");
  }

  // JSON pointer of the innermost open container, plus its newest child when `with_child`
  // (e.g. "/casters/1/polygon/2").
  std::string current_path(bool with_child) const {
    std::string p;
    for (std::size_t i = 0; i < stack_.size(); ++i) {
      const json& j = *stack_[i];
      if (i + 1 < stack_.size())
        p += "/" + (j.is_array() ? std::to_string(j.size() - 1) : last_key_of(j, *stack_[i + 1]));
      else if (with_child)
        p += "/" + (j.is_array() ? std::to_string(j.size() - 1) : key_);
    }
    return p.empty() ? "/" : p;
  }

  static std::string last_key_of(const json& object, const json& child) {
    for (auto it = object.begin(); it != object.end(); ++it)
      if (&it.value() == &child) return it.key();
    return "?";
  }

  json* place(json v) {
    if (++values_ > limits_.max_json_values)
      throw error(errc::scene_too_large, "the scene has more than " + std::to_string(limits_.max_json_values) +
                                         " JSON values (raise it with --max-json-values)");
    if (stack_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    json& top = *stack_.back();
    if (top.is_array()) {
      top.push_back(std::move(v));
      return &top.back();
    }
    top[key_] = std::move(v);
    return &top[key_];
  }
  bool add(json v) {
    place(std::move(v));
    return true;
  }

  json& root_;
  const scene_limits& limits_;
  std::vector<json*> stack_;
  std::string key_;
  std::size_t values_ = 0;
};

struct reader {
  const scene_limits& limits;
  std::string base_directory;
  std::size_t total_vertices = 0;
  std::size_t total_faces = 0;

  [[noreturn]] static void fail(errc code, const std::string& path, const std::string& what) {
    throw error(code, (path.empty() ? std::string("/") : path) + ": " + what);
  }

  static std::string kind(const json& j) {
    if (j.is_string()) return (!j.get_ref<const std::string&>().empty() &&
                               j.get_ref<const std::string&>()[0] == number_mark) ? "a number" : "a string";
    if (j.is_array()) return "an array";
    if (j.is_object()) return "an object";
    if (j.is_boolean()) return "a boolean";
    return "null";
  }

  static void check_keys(const json& j, const std::string& path, std::initializer_list<const char*> allowed) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || it.key() == a;
      if (!ok) fail(errc::scene_unknown_key, path + "/" + it.key(), "unknown key (allowed here: " + [&] {
                      std::string s;
                      for (const char* a : allowed) s += (s.empty() ? "" : ", ") + std::string(a);
                      return s;
                    }() + ")");
    }
  }

  static const json& member(const json& j, const std::string& path, const char* key) {
    if (!j.is_object()) fail(errc::scene_type, path, "expected an object, found " + kind(j));
    auto it = j.find(key);
    if (it == j.end()) fail(errc::scene_missing, path, std::string("missing key \"") + key + "\"");
    return *it;
  }

  rational number(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(errc::scene_type, path, "expected a number, found " + kind(j));
    std::string text = j.get<std::string>();
    if (!text.empty() && text[0] == number_mark) text.erase(0, 1);
    try {
      return parse_number(text, limits.numbers);
    } catch (const error& e) {
      fail(errc::scene_bad_number, path, std::string("\"") + text + "\" is not a valid number: " + e.what());
    }
  }

  const json& array(const json& j, const std::string& path) const {
    if (!j.is_array()) fail(errc::scene_type, path, "expected an array, found " + kind(j));
    return j;
  }

  point3 point(const json& j, const std::string& path) const {
    array(j, path);
    if (j.size() != 3) fail(errc::scene_type, path, "a point needs 3 coordinates [x, y, z], found " + std::to_string(j.size()));
    return {number(j[0], path + "/0"), number(j[1], path + "/1"), number(j[2], path + "/2")};
  }

  polygon3 polygon(const json& j, const std::string& path) const {
    array(j, path);
    if (j.size() < 3) fail(errc::scene_empty_polygon, path, "a polygon needs at least 3 vertices, found " + std::to_string(j.size()));
    if (j.size() > limits.max_face_vertices)
      fail(errc::scene_too_large, path, "a polygon has at most " + std::to_string(limits.max_face_vertices) + " vertices");
    polygon3 p;
    for (std::size_t i = 0; i < j.size(); ++i) p.vertices.push_back(point(j[i], path + "/" + std::to_string(i)));
    return p;
  }

  void count(std::size_t vertices, std::size_t faces, const std::string& path) {
    total_vertices += vertices;
    total_faces += faces;
    if (total_vertices > limits.max_vertices)
      fail(errc::scene_too_large, path, "the casters have more than " + std::to_string(limits.max_vertices) + " vertices (raise it with --max-vertices)");
    if (total_faces > limits.max_faces)
      fail(errc::scene_too_large, path, "the casters have more than " + std::to_string(limits.max_faces) + " faces (raise it with --max-faces)");
  }

  caster mesh(const json& j, const std::string& path) {
    if (!j.is_object()) fail(errc::scene_type, path, "expected an object, found " + kind(j));
    if (j.contains("file")) {
      check_keys(j, path, {"file"});
      const json& f = j["file"];
      if (!f.is_string() || kind(f) != "a string") fail(errc::scene_type, path + "/file", "expected a file name string, found " + kind(f));
      std::string file = f.get<std::string>();
      if (!file.empty() && file[0] != '/' && !base_directory.empty()) file = base_directory + "/" + file;
      caster c = read_mesh_file(file, path + "/file", limits);
      c.name = path;
      count(c.vertices.size(), c.faces.size(), path);
      return c;
    }
    check_keys(j, path, {"vertices", "faces"});
    caster c;
    c.name = path;
    const json& vs = array(member(j, path, "vertices"), path + "/vertices");
    const json& fs = array(member(j, path, "faces"), path + "/faces");
    count(vs.size(), fs.size(), path);
    for (std::size_t i = 0; i < vs.size(); ++i) c.vertices.push_back(point(vs[i], path + "/vertices/" + std::to_string(i)));
    for (std::size_t f = 0; f < fs.size(); ++f) {
      const std::string fp = path + "/faces/" + std::to_string(f);
      const json& face = array(fs[f], fp);
      if (face.size() < 3) fail(errc::scene_empty_polygon, fp, "a face needs at least 3 vertex indices, found " + std::to_string(face.size()));
      if (face.size() > limits.max_face_vertices)
        fail(errc::scene_too_large, fp, "a face has at most " + std::to_string(limits.max_face_vertices) + " vertices (raise it with --max-face-vertices)");
      std::vector<std::size_t> idx;
      for (std::size_t k = 0; k < face.size(); ++k) {
        const std::string ip = fp + "/" + std::to_string(k);
        const rational q = number(face[k], ip);
        if (q.get_den() != 1 || sgn(q) < 0 || q >= rational(static_cast<unsigned long>(c.vertices.size())))
          fail(errc::scene_bad_index, ip, "vertex index " + to_string(q) + " is not an integer in [0, " +
                                    std::to_string(c.vertices.size()) + ")");
        const std::size_t index = q.get_num().get_ui();
        // A face naming one vertex twice is a broken mesh, not a degenerate shape (coincident
        // vertices with distinct indices are geometry and are reported as a case instead).
        if (std::find(idx.begin(), idx.end(), index) != idx.end())
          fail(errc::scene_repeated_index, ip, "vertex index " + std::to_string(index) + " appears twice in the face");
        idx.push_back(index);
      }
      c.faces.push_back(std::move(idx));
    }
    return c;
  }

  scene read(const json& root) {
    if (!root.is_object()) fail(errc::scene_type, "", "the scene must be a JSON object, found " + kind(root));
    check_keys(root, "", {"receiver", "light", "casters"});
    scene s;
    const json& rec = member(root, "", "receiver");
    if (!rec.is_object()) fail(errc::scene_type, "/receiver", "expected an object, found " + kind(rec));
    check_keys(rec, "/receiver", {"polygon", "holes"});
    s.receiver.outer = polygon(member(rec, "/receiver", "polygon"), "/receiver/polygon");
    if (rec.contains("holes")) {
      const json& hs = array(rec["holes"], "/receiver/holes");
      for (std::size_t h = 0; h < hs.size(); ++h)
        s.receiver.holes.push_back(polygon(hs[h], "/receiver/holes/" + std::to_string(h)));
    }
    const json& l = array(member(root, "", "light"), "/light");
    if (l.size() != 4) fail(errc::scene_type, "/light", "the light needs 4 numbers [x, y, z, w], found " + std::to_string(l.size()));
    try {
      s.light_source = make_light(number(l[0], "/light/0"), number(l[1], "/light/1"), number(l[2], "/light/2"),
                                  number(l[3], "/light/3"));
    } catch (const error& e) {
      if (e.code() != errc::geometry_zero_light) throw;
      fail(errc::scene_zero_light, "/light", "(0, 0, 0, 0) is neither a point nor a direction");
    }
    const json& cs = array(member(root, "", "casters"), "/casters");
    for (std::size_t i = 0; i < cs.size(); ++i) {
      const std::string cp = "/casters/" + std::to_string(i);
      const json& c = cs[i];
      if (!c.is_object()) fail(errc::scene_type, cp, "expected an object, found " + kind(c));
      check_keys(c, cp, {"polygon", "mesh"});
      if (c.contains("polygon") == c.contains("mesh"))
        fail(errc::scene_type, cp, "a caster has exactly one of \"polygon\" or \"mesh\"");
      if (c.contains("polygon")) {
        caster k;
        k.name = cp + "/polygon";
        k.is_polygon = true;
        k.vertices = polygon(c["polygon"], k.name).vertices;
        count(k.vertices.size(), 1, k.name);
        k.faces.emplace_back();
        for (std::size_t v = 0; v < k.vertices.size(); ++v) k.faces.back().push_back(v);
        s.casters.push_back(std::move(k));
      } else {
        s.casters.push_back(mesh(c["mesh"], cp + "/mesh"));
      }
    }
    return s;
  }
};

}  // namespace

scene parse_scene(const std::string& json_text, const std::string& base_directory, const scene_limits& limits) {
  json root;
  exact_sax sax(root, limits);
  json::sax_parse(json_text, &sax);
  reader r{limits, base_directory};
  return r.read(root);
}

scene read_scene_file(const std::string& path, const scene_limits& limits) {
  std::string text;
  try {
    text = read_file(path, limits.max_file_bytes);
  } catch (const error& e) {
    if (e.code() != errc::io_cannot_read) throw;  // io.too_large names the limit
    throw error(errc::scene_unreadable, "cannot open the scene file '" + path + "'");
  }
  const auto slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string(".") : path.substr(0, slash == 0 ? 1 : slash);
  return parse_scene(text, dir, limits);
}

}  // namespace shadowproof
