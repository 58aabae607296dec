// shadowproof_proofs: checks the derivations and writes the document.
//   shadowproof_proofs check [slug]      check one derivation (or all); exit 1 if a step fails
//   shadowproof_proofs markdown FILE     check all, then write the Markdown document to FILE
//   shadowproof_proofs list              print the slugs
#include <chrono>
#include <fstream>
#include <iostream>
#include <string>

#include "derivations.h"
#include "document.h"

namespace {

using namespace shadowproof::proofs;

// Prints one line per step; returns true when every step passed.
bool report(const derivation& d, const derivation_result& r) {
  for (std::size_t i = 0; i < d.steps.size(); ++i) {
    const bool refuted = d.steps[i].kind == claim::fails;
    if (r.steps[i].ok)
      std::cout << "  ok   " << (refuted ? (d.steps[i].erratum ? "[erratum refuted] " : "[refuted] ") : "") << d.steps[i].name << '\n';
    else
      std::cout << "  FAIL " << r.steps[i].message << '\n';
  }
  std::cout << (r.ok ? "ok: " : "FAILED: ") << d.slug << " (" << d.steps.size() << " steps)\n";
  return r.ok;
}

int usage() {
  std::cerr << "usage: shadowproof_proofs check [slug] | markdown FILE | list\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string mode = argv[1];
  if (mode == "list") {
    for (const auto& d : all_derivations()) std::cout << d.slug << '\n';
    return 0;
  }
  if (mode == "check") {
    const std::string only = argc > 2 ? argv[2] : "";
    bool ok = true, found = false;
    for (const auto& d : all_derivations()) {
      if (!only.empty() && d.slug != only) continue;
      found = true;
      const auto start = std::chrono::steady_clock::now();
      const derivation_result r = check(d);
      ok = report(d, r) && ok;
      const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
          std::chrono::steady_clock::now() - start).count();
      std::cout << "  (" << ms << " ms)\n";
    }
    if (!found) {
      std::cerr << "shadowproof_proofs: no derivation named '" << only << "'\n";
      return 2;
    }
    return ok ? 0 : 1;
  }
  if (mode == "markdown" && argc == 3) {
    const auto derivations = all_derivations();
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
    std::ofstream file(argv[2], std::ios::binary);
    file << markdown_document(derivations, results);
    if (!file) {
      std::cerr << "shadowproof_proofs: cannot write " << argv[2] << '\n';
      return 2;
    }
    return 0;
  }
  return usage();
}
