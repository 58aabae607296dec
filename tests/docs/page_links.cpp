// Checks every relative link of a Markdown page: the file it names exists, and the heading its
// #anchor names exists in that page (anchors as GitHub derives them from headings: lower case,
// punctuation and symbols dropped, spaces turned into hyphens). Links inside code blocks and
// inline code are not links. Absolute URLs are not followed.
// Usage: page_links <page.md>...   (exit 1 and one line per broken link)
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// The code points of one UTF-8 string (malformed bytes are kept as themselves).
std::vector<std::uint32_t> code_points(const std::string& s) {
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    std::uint32_t cp = extra == 0 ? c : c & (0x3F >> extra);
    for (int k = 1; k <= extra && i + k < s.size(); ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
    out.push_back(cp);
    i += 1 + extra;
  }
  return out;
}

void append_utf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// Letters outside ASCII that a heading may contain (Latin, Greek, Cyrillic); everything else
// outside ASCII (arrows, dots, dashes, primes, mathematical symbols) is punctuation to GitHub.
bool is_letter(std::uint32_t cp) {
  if (cp < 0x80) return (cp >= 'a' && cp <= 'z') || (cp >= 'A' && cp <= 'Z') || (cp >= '0' && cp <= '9') || cp == '_';
  if (cp == 0xD7 || cp == 0xF7) return false;
  return (cp >= 0xC0 && cp <= 0x2AF) || (cp >= 0x370 && cp <= 0x3FF) || (cp >= 0x400 && cp <= 0x4FF);
}

std::string anchor_of(const std::string& heading) {
  std::string out;
  for (const std::uint32_t cp : code_points(heading)) {
    if (cp == ' ' || cp == '-') {
      out += '-';
    } else if (is_letter(cp)) {
      append_utf8(out, cp < 0x80 ? static_cast<std::uint32_t>(std::tolower(static_cast<int>(cp))) : cp);
    }
  }
  return out;
}

// The page's lines outside fenced code blocks.
std::vector<std::string> prose_lines(const fs::path& page) {
  std::ifstream in(page);
  std::vector<std::string> out;
  std::string line;
  bool fenced = false;
  while (std::getline(in, line)) {
    if (line.rfind("```", 0) == 0) {
      fenced = !fenced;
      out.emplace_back();
      continue;
    }
    out.push_back(fenced ? std::string() : line);
  }
  return out;
}

std::set<std::string> anchors_of(const fs::path& page) {
  std::set<std::string> out;
  for (const std::string& line : prose_lines(page)) {
    const std::size_t hashes = line.find_first_not_of('#');
    if (hashes == 0 || hashes == std::string::npos || line[hashes] != ' ') continue;
    out.insert(anchor_of(line.substr(hashes + 1)));
  }
  return out;
}

std::string without_inline_code(const std::string& line) {
  std::string out;
  bool code = false;
  for (const char c : line) {
    if (c == '`') code = !code;
    else if (!code) out += c;
  }
  return out;
}

int check_page(const fs::path& page) {
  int broken = 0;
  const auto lines = prose_lines(page);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::string text = without_inline_code(lines[n]);
    for (std::size_t at = text.find("]("); at != std::string::npos; at = text.find("](", at + 2)) {
      const std::size_t end = text.find(')', at + 2);
      if (end == std::string::npos) break;
      const std::string target = text.substr(at + 2, end - at - 2);
      if (target.empty() || target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0) continue;
      const std::size_t hash = target.find('#');
      const std::string file = target.substr(0, hash);
      const fs::path resolved = file.empty() ? page : page.parent_path() / file;
      const auto report = [&](const std::string& what) {
        std::cout << page.string() << ":" << n + 1 << ": " << what << ": " << target << "\n";
        ++broken;
      };
      if (!fs::exists(resolved)) {
        report("no such file");
        continue;
      }
      if (hash == std::string::npos || resolved.extension() != ".md") continue;
      const std::string anchor = target.substr(hash + 1);
      if (anchors_of(resolved).count(anchor) == 0) report("no such heading");
    }
  }
  return broken;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: page_links <page.md>...\n";
    return 2;
  }
  int broken = 0;
  for (int i = 1; i < argc; ++i) broken += check_page(argv[i]);
  if (broken > 0) std::cout << broken << " broken link(s)\n";
  return broken == 0 ? 0 : 1;
}
