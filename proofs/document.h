#pragma once
/// The readable document (docs/derivations.md) written from the checked derivations.
#include <string>
#include <vector>

#include "checker.h"

namespace shadowproof::proofs {

/// Markdown with LaTeX math (```math blocks and $...$ inline) for every derivation: each step is
/// a sentence of why and a line of math; each refuted step shows its counterexample and the
/// non-zero difference there. Precondition: results[i] is check(derivations[i]) and all are ok.
std::string markdown_document(const std::vector<derivation>& derivations,
                              const std::vector<derivation_result>& results);

}  // namespace shadowproof::proofs
