#include "document.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <utility>

#include "notation.h"

namespace shadowproof::proofs {

namespace {

// A side without its own LaTeX is shown normalised: GiNaC's unnormalised form may differ in
// sign arrangement from run to run, the normal form with our sign rule does not.
std::string side_tex(const side& s) { return s.tex.empty() ? tex_normal(s.value) : s.tex; }

// The counterexample as "n = 1,\; f = 2", in alphabetical order of the symbols' names (the map's
// own order follows GiNaC hash values).
std::string counterexample_tex(const GiNaC::exmap& values) {
  std::vector<std::pair<std::string, std::string>> items;
  for (const auto& [sym, value] : values) items.push_back({tex(sym), tex(value)});
  std::sort(items.begin(), items.end());
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i)
    s += (i ? ",\\; " : "") + items[i].first + " = " + items[i].second;
  return s;
}

std::string anchor(const std::string& title) {
  std::string a;
  for (char ch : title) {
    if (std::isalnum(static_cast<unsigned char>(ch))) a += static_cast<char>(std::tolower(ch));
    else if (ch == ' ' || ch == '-') a += '-';
  }
  return a;
}

}  // namespace

std::string markdown_document(const std::vector<derivation>& derivations,
                              const std::vector<derivation_result>& results) {
  std::ostringstream out;
  out << "# Derivations, checked step by step\n\n"
         "Each derivation below is a sequence of equations between symbolic expressions. Every step was "
         "checked by a computer algebra system (GiNaC): the difference of its two sides, put over a "
         "common denominator, is identically zero for all values of the symbols, not just for samples. "
         "A step may only divide by expressions its derivation assumes non-zero. A step marked "
         "**erratum** is an equation printed in one of the reference derivations that is false: the "
         "check confirms that the difference is not identically zero and shows an exact counterexample; "
         "the corrected step follows it. A step marked **false in general** is a tempting shortcut, "
         "refuted the same way.\n\n"
         "The source of every step is in `proofs/derivations/`; this file is the output of "
         "`shadowproof_proofs markdown docs/derivations.md` and a test fails when it is out of date.\n\n"
         "Conventions: vectors are columns and a matrix $M$ maps $V$ to $M V$; a plane is "
         "$P = (a, b, c, d)$ with $P \\cdot (x, y, z, 1) = 0$; a light is $L = (L_x, L_y, L_z, L_w)$, "
         "directional when $L_w = 0$.\n\n";
  out << "## Contents\n\n";
  for (std::size_t i = 0; i < derivations.size(); ++i) {
    const std::string heading = std::to_string(i + 1) + ". " + derivations[i].title;
    out << "- [" << heading << "](#" << anchor(heading) << ")\n";
  }
  out << "\n";

  for (std::size_t i = 0; i < derivations.size(); ++i) {
    const derivation& d = derivations[i];
    const derivation_result& r = results[i];
    out << "## " << i + 1 << ". " << d.title << "\n\n";
    if (!d.source.empty()) out << "*Follows " << d.source << ".*\n\n";
    out << d.intro << "\n\n";
    if (!d.assumptions.empty()) {
      out << "Assumed non-zero: ";
      for (std::size_t j = 0; j < d.assumptions.size(); ++j)
        out << (j ? ", " : "") << "$" << d.assumptions[j].tex << "$";
      out << ".\n\n";
    }
    int number = 0;
    for (std::size_t j = 0; j < d.steps.size(); ++j) {
      const step& s = d.steps[j];
      if (s.kind == claim::holds) {
        out << "**Step " << ++number << ": " << s.name << ".** " << s.why << "\n\n";
        out << "```math\n" << side_tex(s.lhs) << " = " << side_tex(s.rhs) << "\n```\n\n";
      } else {
        out << (s.erratum ? "**Erratum: " : "**False in general: ") << s.name << ".** " << s.why << "\n\n";
        out << "```math\n" << side_tex(s.lhs) << " \\neq " << side_tex(s.rhs) << "\n```\n\n";
        out << "Counterexample: at $" << counterexample_tex(s.counterexample)
            << "$ the left side minus the right side is\n\n```math\n"
            << tex(r.steps[j].counterexample_residual) << "\n```\n\n";
      }
    }
    if (!d.conclusion.empty()) out << d.conclusion << "\n\n";
  }
  std::string text = out.str();
  while (text.size() >= 2 && text[text.size() - 1] == '\n' && text[text.size() - 2] == '\n') text.pop_back();
  return text;
}

}  // namespace shadowproof::proofs
