#include "document.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <utility>

namespace shadowproof::proofs {

namespace {

// "n = 1,\; f = 2", ordered by the variables' LaTeX.
std::string counterexample_tex(const assignment& values) {
  std::vector<std::pair<std::string, std::string>> items;
  for (const auto& [variable, value] : values) items.push_back({variable.tex(), value.tex()});
  std::sort(items.begin(), items.end());
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ",\\; " : "") + items[i].first + " = " + items[i].second;
  return s;
}

std::string facts_tex(const std::vector<fact>& facts) {
  std::string s;
  for (std::size_t i = 0; i < facts.size(); ++i) s += (i ? ",\\; " : "") + facts[i].tex();
  return s;
}

std::string anchor(const std::string& title) {
  std::string a;
  for (char ch : title) {
    if (std::isalnum(static_cast<unsigned char>(ch))) a += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    else if (ch == ' ' || ch == '-') a += '-';
  }
  return a;
}

// Text for a Markdown table cell: a bare | would end the cell.
std::string cell(const std::string& text) {
  std::string s;
  for (char ch : text) s += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return s;
}

void math_block(std::ostringstream& out, const std::string& math) { out << "```math\n" << math << "\n```\n\n"; }

// " (for $P_y - h > 0$)" after a step's name, when it rests on premises.
std::string premises_note(const step& s) {
  return s.premises.empty() ? "" : " (for $" + facts_tex(s.premises) + "$)";
}

}  // namespace

step_counts count_steps(const std::vector<derivation>& derivations) {
  step_counts c;
  c.derivations = derivations.size();
  for (const auto& d : derivations)
    for (const auto& s : d.steps) {
      if (s.about_source == verdict::mistake) ++c.mistakes;
      if (s.about_source == verdict::not_a_mistake) ++c.not_mistakes;
      switch (s.kind) {
        case step_kind::definition: ++c.definitions; continue;
        case step_kind::code: ++c.code; break;
        case step_kind::erratum: ++c.errata; break;
        case step_kind::false_in_general: ++c.false_in_general; break;
        case step_kind::sign: ++c.paths; break;
        default: break;
      }
      ++c.checked;
    }
  return c;
}

std::string markdown_document(const std::vector<derivation>& derivations,
                              const std::vector<derivation_result>& results) {
  const step_counts counts = count_steps(derivations);
  std::ostringstream out;
  out << "# Derivations, checked step by step\n\n"
         "Each derivation below is a sequence of equations between symbolic expressions, and every step is "
         "checked by a computer algebra system (GiNaC) for all values of its symbols, not for samples. "
         "The checker (`proofs/checker.h`) accepts a step only when\n\n"
         "- every division written in it is by an expression the derivation's facts make non-zero. The "
         "divisions are read off the expression as it was written, before GiNaC simplifies anything, so "
         "$(a b)/a = b$ needs the fact $a \\neq 0$;\n"
         "- its two sides are not the same expression before normalisation, that is after GiNaC's automatic "
         "evaluation with every division kept opaque (a step must show something); notation that is merely "
         "unfolded, or a product evaluated entry by entry, is marked *definition* and not counted as a checked "
         "step. Code steps are exempt: their left side is what the library computes, which may agree with the "
         "derivation by construction and still fails the step when the library changes;\n"
         "- the difference of its two sides, put over a common denominator, is identically zero (entry by "
         "entry for matrices).\n\n"
         "Every formula below is printed from the very expression that is checked. Steps marked **code** "
         "instantiate the library's own templates (`include/shadowproof/constructions/`) with a symbolic "
         "number type and compare what they compute with the derivation, so a change to a formula in the "
         "library makes its proof fail (a test checks exactly that on a copy of the headers, changing the formulas one at a time). "
         "A step marked **erratum** is an equation printed in one of the reference derivations that is "
         "false when read with the vector convention it names: the check confirms that the difference is "
         "not identically zero and evaluates it at an exact counterexample that respects every fact; the "
         "corrected step follows. A step marked **false in general** is a tempting shortcut, refuted the "
         "same way.\n\n"
         "The source of every step is in `proofs/derivations/`; this file and the figures in "
         "`docs/figures/` are the output of `shadowproof_proofs markdown docs/derivations.md docs/figures`, "
         "and a test fails when either is out of date. The figures are drawn from exact numbers by the "
         "same code as `shadowproof explain ... --svg`.\n\n"
         "Conventions: vectors are columns and a matrix $M$ maps $V$ to $M V$ (an erratum that depends on "
         "the convention says which one it assumes); a plane is $P = (a, b, c, d)$ with "
         "$P \\cdot (x, y, z, 1) = 0$; a light is $L = (L_x, L_y, L_z, L_w)$, directional when $L_w = 0$.\n\n"
      << "In all: " << counts.derivations << " derivations, " << counts.checked << " checked steps (" << counts.code
      << " of them on the library's code, " << counts.paths << " on the paths of `classify_point`, " << counts.errata
      << " errata and " << counts.false_in_general << " false shortcuts refuted) and " << counts.definitions
      << " definitions. The reference derivations make " << counts.mistakes << " mistakes (" << counts.errata
      << " refuted by an exact counterexample, the others shown wrong by a checked step) and " << counts.not_mistakes
      << " more candidates turn out not to be mistakes:\n\n";
  // The mistakes of the reference derivations, and the candidates that are none, at a glance.
  for (const verdict v : {verdict::mistake, verdict::not_a_mistake}) {
    out << (v == verdict::mistake ? "### What the reference derivations get wrong\n\n"
                                  : "### Checked, and not a mistake\n\n");
    out << "| source | statement | " << (v == verdict::mistake ? "read with" : "why not") << " | derivation |\n"
        << "| --- | --- | --- | --- |\n";
    for (std::size_t i = 0; i < derivations.size(); ++i)
      for (const auto& s : derivations[i].steps) {
        if (s.about_source != v) continue;
        const std::string heading = std::to_string(i + 1) + ". " + derivations[i].title;
        out << "| " << derivations[i].source << " | " << cell(s.name) << " | "
            << cell(v == verdict::mistake ? (s.convention.empty() ? std::string("any convention") : s.convention)
                                          : s.reason)
            << " | [" << heading << "](#" << anchor(heading) << ") |\n";
      }
    out << "\n";
  }
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
    if (!d.figure.empty())
      out << "![" << d.title << "](figures/" << d.slug << ".svg)\n\n*Figure: " << d.figure << "*\n\n";
    if (!d.facts.empty()) out << "Facts: $" << facts_tex(d.facts) << "$.\n\n";
    int number = 0;
    for (std::size_t j = 0; j < d.steps.size(); ++j) {
      const step& s = d.steps[j];
      switch (s.kind) {
        case step_kind::definition:
          out << "**Definition: " << s.name << premises_note(s) << ".** " << s.why << "\n\n";
          math_block(out, s.lhs.tex() + " \\overset{\\text{def}}{=} " + s.rhs.tex());
          break;
        case step_kind::derivation:
          out << "**Step " << ++number << ": " << s.name << premises_note(s) << ".** " << s.why << "\n\n";
          math_block(out, s.lhs.tex() + " = " + s.rhs.tex());
          break;
        case step_kind::code:
          out << "**Step " << ++number << " (code, `" << s.header << "`): " << s.name << premises_note(s) << ".** " << s.why << "\n\n";
          math_block(out, s.lhs.tex() + " = " + s.rhs.tex());
          break;
        case step_kind::sign: {
          // A run of sign steps is one table: what the code returns, under which conditions, and
          // the sign that was checked.
          if (j == 0 || d.steps[j - 1].kind != step_kind::sign) {
            out << "**Steps " << number + 1 << "–";
            std::size_t last = j;
            while (last + 1 < d.steps.size() && d.steps[last + 1].kind == step_kind::sign) ++last;
            out << number + 1 + static_cast<int>(last - j) << ".** " << s.why << "\n\n"
                << "| | conditions | checked |\n| --- | --- | --- |\n";
          }
          ++number;
          out << "| " << s.name << " | $" << facts_tex(s.premises) << "$ | $" << facts_tex(s.claims) << "$ |\n";
          if (j + 1 == d.steps.size() || d.steps[j + 1].kind != step_kind::sign) out << "\n";
          break;
        }
        case step_kind::erratum:
        case step_kind::false_in_general:
          out << (s.kind == step_kind::erratum ? "**Erratum" : "**False in general")
              << (s.convention.empty() ? "" : " (" + s.convention + ")") << ": " << s.name << premises_note(s) << ".** " << s.why << "\n\n";
          math_block(out, s.lhs.tex() + " \\neq " + s.rhs.tex());
          out << "Counterexample: at $" << counterexample_tex(s.counterexample)
              << "$ the left side minus the right side is\n\n";
          math_block(out, r.steps[j].residual_tex);
          break;
      }
    }
    if (!d.conclusion.empty()) out << d.conclusion << "\n\n";
  }
  std::string text = out.str();
  while (text.size() >= 2 && text[text.size() - 1] == '\n' && text[text.size() - 2] == '\n') text.pop_back();
  return text;
}

}  // namespace shadowproof::proofs
