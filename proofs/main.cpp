// shadowproof_proofs: checks the derivations and writes the document and its figures.
//   shadowproof_proofs check [slug]              check one derivation (or all); exit 1 if a step fails
//   shadowproof_proofs markdown FILE [FIGURES]   check all, then write the Markdown document to FILE
//                                                and the figures to the directory FIGURES
//   shadowproof_proofs list                      print the slugs
//   shadowproof_proofs count                     print how many steps of each kind there are
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "derivations.h"
#include "document.h"
#include "figures.h"

namespace {

using namespace shadowproof::proofs;

// Prints one line per step; returns true when every step passed.
bool report(const derivation& d, const derivation_result& r) {
  if (!r.message.empty()) std::cout << "  FAIL " << r.message << '\n';
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const step& s = d.steps[i];
    const char* tag = s.kind == step_kind::erratum            ? "[erratum refuted] "
                      : s.kind == step_kind::false_in_general ? "[refuted] "
                      : s.kind == step_kind::definition       ? "[definition] "
                      : s.kind == step_kind::code             ? "[code] "
                      : s.kind == step_kind::sign             ? "[path] "
                                                              : "";
    if (r.steps[i].ok) std::cout << "  ok   " << tag << s.name << '\n';
    else std::cout << "  FAIL " << r.steps[i].message << '\n';
  }
  std::cout << (r.ok ? "ok: " : "FAILED: ") << d.slug << " (" << d.steps.size() << " steps)\n";
  return r.ok;
}

int usage() {
  std::cerr << "usage: shadowproof_proofs check [slug] | markdown FILE [FIGURES_DIR] | list | count\n";
  return 2;
}

bool write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  return static_cast<bool>(file);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string mode = argv[1];
  if (mode == "list") {
    for (const auto& slug : derivation_slugs()) std::cout << slug << '\n';
    return 0;
  }
  if (mode == "count") {
    const step_counts c = count_steps(all_derivations());
    std::cout << "derivations " << c.derivations << "\nchecked " << c.checked << "\ncode " << c.code << "\npaths " << c.paths
              << "\nerrata " << c.errata << "\nfalse_in_general " << c.false_in_general << "\ndefinitions "
              << c.definitions << "\nmistakes " << c.mistakes << "\nnot_mistakes " << c.not_mistakes << '\n';
    return 0;
  }
  if (mode == "check") {
    const std::string only = argc > 2 ? argv[2] : "";
    bool ok = true, found = false;
    for (const auto& slug : derivation_slugs()) {
      if (!only.empty() && slug != only) continue;
      found = true;
      const auto start = std::chrono::steady_clock::now();
      const derivation d = build_derivation(slug);
      const derivation_result r = check(d);
      ok = report(d, r) && ok;
      const auto ms =
          std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start).count();
      std::cout << "  (" << ms << " ms)\n";
    }
    if (!found) {
      std::cerr << "shadowproof_proofs: no derivation named '" << only << "'\n";
      return 2;
    }
    return ok ? 0 : 1;
  }
  if (mode == "markdown" && (argc == 3 || argc == 4)) {
    auto derivations = all_derivations();
    std::vector<derivation_result> results;
    bool ok = true;
    for (const auto& d : derivations) {
      results.push_back(check(d));
      if (!results.back().ok) ok = report(d, results.back()) && ok;
    }
    if (!ok) {
      std::cerr << "shadowproof_proofs: not writing the document: a step failed\n";
      return 1;
    }
    if (argc == 4) {
      const std::filesystem::path dir = argv[3];
      std::error_code ec;
      std::filesystem::create_directories(dir, ec);
      for (auto& d : derivations) {
        const auto figure = figure_for(d.slug);
        if (!figure) continue;
        d.figure = figure->caption;
        if (!write_file(dir / (d.slug + ".svg"), figure->svg)) {
          std::cerr << "shadowproof_proofs: cannot write " << (dir / (d.slug + ".svg")).string() << '\n';
          return 2;
        }
      }
    }
    if (!write_file(argv[2], markdown_document(derivations, results))) {
      std::cerr << "shadowproof_proofs: cannot write " << argv[2] << '\n';
      return 2;
    }
    return 0;
  }
  return usage();
}
