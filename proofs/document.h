#pragma once
/// The readable document (docs/derivations.md) written from the checked derivations.
#include <string>
#include <vector>

#include "checker.h"

namespace shadowproof::proofs {

/// Markdown with LaTeX math (```math blocks and $...$ inline) for every derivation: each step is
/// a sentence of why and a line of math generated from the checked expressions; each refuted
/// step shows its convention, its counterexample and the non-zero difference there; each
/// derivation with a figure links figures/<slug>.svg. Precondition: results[i] is
/// check(derivations[i]) and all are ok.
std::string markdown_document(const std::vector<derivation>& derivations,
                              const std::vector<derivation_result>& results);

/// How many steps of each kind, over all derivations.
struct step_counts {
  std::size_t derivations = 0, checked = 0, code = 0, paths = 0, definitions = 0, errata = 0, false_in_general = 0;
  std::size_t mistakes = 0, not_mistakes = 0;
};
step_counts count_steps(const std::vector<derivation>& derivations);

}  // namespace shadowproof::proofs
