#pragma once
/// The figures of docs/derivations.md: each drawn from exact numbers by the library's explain code
/// (the same code as `shadowproof explain ... --svg`), with a caption that states those numbers.
#include <optional>
#include <string>

namespace shadowproof::proofs {

struct derivation_figure {
  std::string svg;
  std::string caption;  ///< Markdown.
};

/// The figure of the derivation `slug`, or nothing when it has none.
std::optional<derivation_figure> figure_for(const std::string& slug);

}  // namespace shadowproof::proofs
