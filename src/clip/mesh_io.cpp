// OFF and OBJ mesh readers with exact numbers. The file is read whole (core/io.h, size-capped)
// and scanned in place: no per-line streams, and plain decimals ("-52.9283") go straight to
// an exact rational without the general number parser.
#include <algorithm>
#include <cctype>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "shadowproof/clip/scene.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/io.h"

namespace shadowproof {

namespace {

[[noreturn]] void mesh_fail(errc code, const std::string& what, std::size_t line, const std::string& msg) {
  throw error(code, what + " line " + std::to_string(line) + ": " + msg);
}

// Text from a file shown in a message: at most 40 characters, control and non-ASCII bytes as
// \xNN, so a binary file cannot garble the terminal.
std::string printable(std::string_view text) {
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

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// A plain decimal [-+]digits[.digits] with at most 18 digits, exactly; false for anything
// else (exponents, fractions, hex, f32:, malformed text), which parse_number then reads.
bool plain_decimal(std::string_view t, rational& out) {
  std::size_t i = 0;
  const bool negative = !t.empty() && t[0] == '-';
  if (negative) ++i;
  unsigned long long mantissa = 0, scale = 1;
  std::size_t int_digits = 0, frac_digits = 0;
  for (; i < t.size() && is_digit(t[i]) && int_digits < 19; ++i, ++int_digits)
    mantissa = mantissa * 10 + static_cast<unsigned long long>(t[i] - '0');
  if (int_digits == 0) return false;
  if (i < t.size() && t[i] == '.') {
    ++i;
    for (; i < t.size() && is_digit(t[i]) && int_digits + frac_digits < 19; ++i, ++frac_digits) {
      mantissa = mantissa * 10 + static_cast<unsigned long long>(t[i] - '0');
      scale *= 10;
    }
    if (frac_digits == 0) return false;
  }
  if (i != t.size() || int_digits + frac_digits > 18) return false;
  // Straight into `out` (no temporaries: a million-vertex mesh reads three million of these).
  mpq_set_ui(out.get_mpq_t(), static_cast<unsigned long>(mantissa), static_cast<unsigned long>(scale));
  out.canonicalize();
  if (negative) mpq_neg(out.get_mpq_t(), out.get_mpq_t());
  return true;
}

rational mesh_number(std::string_view text, const std::string& what, std::size_t line, const scene_limits& limits) {
  rational q;
  // 18 decimal digits need at most 60 bits: within every limit of 64 bits or more.
  if (limits.numbers.max_bits >= 64 && plain_decimal(text, q)) return q;
  try {
    return parse_number(text, limits.numbers);
  } catch (const error& e) {
    mesh_fail(errc::scene_bad_number, what, line, "\"" + printable(text) + "\" is not a valid number: " + e.what());
  }
}

std::size_t mesh_count(std::string_view text, const std::string& what, std::size_t line, const char* name) {
  if (text.empty() || text.size() > 12 || !std::all_of(text.begin(), text.end(), is_digit))
    mesh_fail(errc::scene_mesh_malformed, what, line,
              std::string("expected a non-negative ") + name + ", found \"" + printable(text) + "\"");
  std::size_t n = 0;
  for (char c : text) n = n * 10 + static_cast<std::size_t>(c - '0');
  return n;
}

// Words of a text with their line numbers; '#' starts a comment to the end of the line.
class word_scanner {
 public:
  explicit word_scanner(std::string_view text) : text_(text) {}

  /// The next word, or an empty view at the end; `line` is its line number (1-based).
  std::string_view next(std::size_t& line) {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
      } else if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (is_space(c)) {
        ++pos_;
      } else {
        break;
      }
    }
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_]) && text_[pos_] != '#') ++pos_;
    line = line_;
    return text_.substr(start, pos_ - start);
  }
  /// Skips the rest of the current line.
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  /// Number of lines, counting a last line without a newline.
  std::size_t lines() const {
    const std::size_t n = static_cast<std::size_t>(std::count(text_.begin(), text_.end(), '\n'));
    return n + (!text_.empty() && text_.back() != '\n' ? 1 : 0);
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

caster parse_off(std::string_view text, const std::string& what, const scene_limits& limits) {
  word_scanner words(text);
  std::size_t line = 1;
  const auto next = [&](const char* expected) {
    const std::string_view w = words.next(line);
    if (w.empty())
      mesh_fail(errc::scene_mesh_malformed, what, words.lines(), std::string("unexpected end of file, expected ") + expected);
    return w;
  };
  const std::string_view head = next("\"OFF\"");
  if (head != "OFF")
    mesh_fail(errc::scene_mesh_malformed, what, line, "an OFF file starts with \"OFF\", found \"" + printable(head) + "\"");
  // (Each word is read before its line number is used: argument order is unspecified.)
  const std::string_view nv_text = next("the vertex count");
  const std::size_t nv_line = line;
  const std::size_t nv = mesh_count(nv_text, what, nv_line, "vertex count");
  const std::string_view nf_text = next("the face count");
  const std::size_t nf_line = line;
  const std::size_t nf = mesh_count(nf_text, what, nf_line, "face count");
  const std::string_view ne_text = next("the edge count");
  mesh_count(ne_text, what, line, "edge count");
  if (nv > limits.max_vertices)
    mesh_fail(errc::scene_too_large, what, nv_line, std::to_string(nv) + " vertices; at most " + std::to_string(limits.max_vertices) + " (raise it with --max-vertices)");
  if (nf > limits.max_faces)
    mesh_fail(errc::scene_too_large, what, nf_line, std::to_string(nf) + " faces; at most " + std::to_string(limits.max_faces) + " (raise it with --max-faces)");
  caster m;
  m.name = what;
  m.vertices.resize(nv);
  for (std::size_t i = 0; i < nv; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::string_view t = next("a vertex coordinate");
      m.vertices[i][k] = mesh_number(t, what, line, limits);
    }
  m.faces.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::string_view k_text = next("a face");
    const std::size_t face_line = line;
    const std::size_t k = mesh_count(k_text, what, face_line, "face size");
    if (k < 3) mesh_fail(errc::scene_empty_polygon, what, face_line, "face " + std::to_string(f) + " has " + std::to_string(k) + " vertices; at least 3");
    if (k > limits.max_face_vertices)
      mesh_fail(errc::scene_too_large, what, face_line, "face " + std::to_string(f) + " has more than " + std::to_string(limits.max_face_vertices) + " vertices (raise it with --max-face-vertices)");
    auto& face = m.faces[f];
    face.reserve(k);
    for (std::size_t j = 0; j < k; ++j) {
      const std::string_view idx_text = next("a vertex index");
      const std::size_t idx = mesh_count(idx_text, what, line, "vertex index");
      if (idx >= nv)
        mesh_fail(errc::scene_bad_index, what, line, "face " + std::to_string(f) + ": vertex index " + std::to_string(idx) + " is out of range (" + std::to_string(nv) + " vertices)");
      if (std::find(face.begin(), face.end(), idx) != face.end())
        mesh_fail(errc::scene_repeated_index, what, line, "face " + std::to_string(f) + ": vertex index " + std::to_string(idx) + " appears twice");
      face.push_back(idx);
    }
    // Anything left on the face's line (OFF colours) is ignored.
    if (line == face_line) words.skip_line();
  }
  return m;
}

caster parse_obj(std::string_view text, const std::string& what, const scene_limits& limits) {
  caster m;
  m.name = what;
  std::size_t n = 0;
  std::vector<std::string_view> w;
  for (std::size_t pos = 0; pos < text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++n;
    line = line.substr(0, line.find('#'));
    w.clear();
    for (std::size_t i = 0; i < line.size();) {
      while (i < line.size() && is_space(line[i])) ++i;
      const std::size_t start = i;
      while (i < line.size() && !is_space(line[i])) ++i;
      if (i > start) w.push_back(line.substr(start, i - start));
    }
    if (w.empty()) continue;
    if (w[0] == "v") {
      if (w.size() != 4 && w.size() != 5) mesh_fail(errc::scene_mesh_malformed, what, n, "a vertex is \"v x y z [w]\"");
      point3 p{mesh_number(w[1], what, n, limits), mesh_number(w[2], what, n, limits), mesh_number(w[3], what, n, limits)};
      if (w.size() == 5) {
        const rational h = mesh_number(w[4], what, n, limits);
        if (sgn(h) == 0) mesh_fail(errc::scene_mesh_malformed, what, n, "a vertex with w = 0 is not a finite point");
        for (auto& x : p) x /= h;
      }
      if (m.vertices.size() >= limits.max_vertices)
        mesh_fail(errc::scene_too_large, what, n, "more than " + std::to_string(limits.max_vertices) + " vertices (raise it with --max-vertices)");
      m.vertices.push_back(std::move(p));
    } else if (w[0] == "f") {
      if (w.size() < 4) mesh_fail(errc::scene_empty_polygon, what, n, "a face needs at least 3 vertices");
      if (w.size() - 1 > limits.max_face_vertices)
        mesh_fail(errc::scene_too_large, what, n, "the face has more than " + std::to_string(limits.max_face_vertices) + " vertices (raise it with --max-face-vertices)");
      std::vector<std::size_t> face;
      face.reserve(w.size() - 1);
      for (std::size_t j = 1; j < w.size(); ++j) {
        const std::string_view idx_text = w[j].substr(0, w[j].find('/'));
        const bool negative = !idx_text.empty() && idx_text[0] == '-';
        const std::size_t v = mesh_count(negative ? idx_text.substr(1) : idx_text, what, n, "vertex index");
        const std::size_t count = m.vertices.size();
        if (v == 0 || v > count)
          mesh_fail(errc::scene_bad_index, what, n, "vertex index " + std::string(idx_text) + " is out of range (" + std::to_string(count) + " vertices so far)");
        const std::size_t index = negative ? count - v : v - 1;
        if (std::find(face.begin(), face.end(), index) != face.end())
          mesh_fail(errc::scene_repeated_index, what, n, "vertex index " + std::string(idx_text) + " appears twice in the face");
        face.push_back(index);
      }
      if (m.faces.size() >= limits.max_faces)
        mesh_fail(errc::scene_too_large, what, n, "more than " + std::to_string(limits.max_faces) + " faces (raise it with --max-faces)");
      m.faces.push_back(std::move(face));
    }
  }
  return m;
}

std::string read_stream(std::istream& in) {
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

caster read_off(std::istream& in, const std::string& what, const scene_limits& limits) {
  return parse_off(read_stream(in), what, limits);
}

caster read_obj(std::istream& in, const std::string& what, const scene_limits& limits) {
  return parse_obj(read_stream(in), what, limits);
}

caster read_mesh_file(const std::string& path, const std::string& what, const scene_limits& limits) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".off" && ext != ".obj")
    throw error(errc::scene_mesh_unreadable, what + ": '" + path + "' is neither an .off nor an .obj file");
  std::string text;
  try {
    text = read_file(path, limits.max_file_bytes);
  } catch (const error& e) {
    if (e.code() != errc::io_cannot_read) throw;  // io.too_large names the limit
    throw error(errc::scene_mesh_unreadable, what + ": cannot open the mesh file '" + path + "'");
  }
  const std::string name = what + " ('" + path + "')";
  return ext == ".off" ? parse_off(text, name, limits) : parse_obj(text, name, limits);
}

}  // namespace shadowproof
