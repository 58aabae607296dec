// Runs the ```console blocks of a Markdown page and compares what each command prints with
// what the page shows, so that a page cannot go on showing output the tool no longer prints.
//
// A block:
//   ```console
//   $ shadowproof shadow --plane 0,1,0,0 --light 2,5,1,1    <- a command ("$ " prefix; a line
//   plane P = (0, 1, 0, 0), ...                                ending in \ continues it)
//   ...                                                     <- any number of lines
//   Graded 3 cases in {{*}}                                 <- {{*}}: any text within a line
//   [exit 2]                                                <- the exit code, when not 0
//   ```
// Each command runs in /bin/sh with stderr merged into stdout, in a scratch directory whose
// entries link to the source tree's top-level entries (so examples/... paths resolve and
// written files stay out of the tree), with the build directory first on PATH.
// Usage: console_blocks <page.md> <source dir> <bin dir> <scratch dir>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct command_example {
  std::size_t line = 0;  // 1-based line of the command in the page
  std::string command;
  std::vector<std::string> expected;
  int exit_code = 0;
};

std::string rstrip(std::string s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.pop_back();
  return s;
}

std::vector<command_example> console_examples(const std::string& path) {
  std::ifstream in(path);
  std::vector<command_example> out;
  std::string line;
  bool inside = false;
  std::size_t n = 0;
  bool continuing = false;
  while (std::getline(in, line)) {
    ++n;
    const std::string trimmed = rstrip(line);
    if (!inside) {
      inside = trimmed == "```console";
      continue;
    }
    if (trimmed == "```") {
      inside = false;
      continue;
    }
    if (continuing) {
      std::string more = trimmed;
      continuing = !more.empty() && more.back() == '\\';
      if (continuing) more.pop_back();
      out.back().command += " " + more;
    } else if (trimmed.rfind("$ ", 0) == 0) {
      command_example e;
      e.line = n;
      e.command = trimmed.substr(2);
      continuing = !e.command.empty() && e.command.back() == '\\';
      if (continuing) e.command.pop_back();
      out.push_back(e);
    } else if (!out.empty()) {
      if (trimmed.rfind("[exit ", 0) == 0 && trimmed.back() == ']')
        out.back().exit_code = std::stoi(trimmed.substr(6));
      else
        out.back().expected.push_back(trimmed);
    }
  }
  return out;
}

// One expected line against one actual line; {{*}} matches any text.
bool line_matches(const std::string& pattern, const std::string& text) {
  const std::string wild = "{{*}}";
  const std::size_t star = pattern.find(wild);
  if (star == std::string::npos) return pattern == text;
  const std::string head = pattern.substr(0, star);
  const std::string tail = pattern.substr(star + wild.size());
  if (text.compare(0, head.size(), head) != 0) return false;
  for (std::size_t i = head.size(); i <= text.size(); ++i)
    if (line_matches(tail, text.substr(i))) return true;
  return false;
}

// Expected lines (with "..." for any run of lines) against the actual output.
bool lines_match(const std::vector<std::string>& want, std::size_t w, const std::vector<std::string>& got, std::size_t g) {
  if (w == want.size()) return g == got.size();
  if (want[w] == "...") {
    for (std::size_t k = g; k <= got.size(); ++k)
      if (lines_match(want, w + 1, got, k)) return true;
    return false;
  }
  return g < got.size() && line_matches(want[w], got[g]) && lines_match(want, w + 1, got, g + 1);
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> lines;
  std::istringstream in(s);
  std::string line;
  while (std::getline(in, line)) lines.push_back(rstrip(line));
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  return lines;
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: console_blocks <page.md> <source dir> <bin dir> <scratch dir>\n";
    return 2;
  }
  const std::string page = argv[1];
  const fs::path source = argv[2], bin = argv[3], scratch = argv[4];
  fs::create_directories(scratch);
  for (const auto& entry : fs::directory_iterator(source)) {
    const fs::path link = scratch / entry.path().filename();
    if (entry.path().filename().string().rfind(".", 0) == 0 || fs::exists(fs::symlink_status(link))) continue;
    fs::create_symlink(entry.path(), link);
  }
  const auto examples = console_examples(page);
  if (examples.empty()) {
    std::cerr << page << ": no ```console block to check\n";
    return 1;
  }
  int failures = 0;
  for (const auto& e : examples) {
    const std::string shell = "cd " + quote(scratch.string()) + " && PATH=" + quote(bin.string()) +
                              ":\"$PATH\" timeout 300 /bin/sh -c " + quote(e.command) + " 2>&1";
    FILE* pipe = popen(shell.c_str(), "r");
    std::string output;
    char buf[4096];
    std::size_t got;
    while ((got = fread(buf, 1, sizeof buf, pipe)) > 0) output.append(buf, got);
    const int status = pclose(pipe);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    const auto actual = split_lines(output);
    std::vector<std::string> want = e.expected;
    while (!want.empty() && want.back().empty()) want.pop_back();
    if (code != e.exit_code || !lines_match(want, 0, actual, 0)) {
      ++failures;
      std::cerr << page << ":" << e.line << ": $ " << e.command << "\n  exit " << code << " (page says " << e.exit_code
                << ")\n--- the page shows\n";
      for (const auto& l : want) std::cerr << l << '\n';
      std::cerr << "--- the command printed\n" << output << "---\n";
    }
  }
  std::cout << page << ": " << examples.size() - failures << " of " << examples.size() << " commands print what the page shows\n";
  return failures == 0 ? 0 : 1;
}
