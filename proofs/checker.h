#pragma once
/// The step checker. A derivation is a list of named steps between recorded expressions (term.h,
/// mat.h); each is checked symbolically, for every value of its symbols, by GiNaC (only
/// checker.cpp includes it). A step is accepted only when
///   - every division written in it (read off the recorded tree before GiNaC simplifies anything)
///     is by an expression the derivation's declared facts make non-zero;
///   - its two sides are not the same expression before normalisation (GiNaC's automatic
///     evaluation, with every division kept opaque), unless the step is a definition. Code steps
///     are exempt: their left side is what the library computes, which may agree with the
///     derivation by construction and still fails the step when the library changes;
///   - lhs − rhs normalises to 0 as a rational function, entry by entry (a refuted step: it does
///     not, and its counterexample makes it a non-zero number while every fact holds).
/// The LaTeX the document prints for a step is generated from the same trees.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mat.h"
#include "term.h"

namespace shadowproof::proofs {

/// One side of a step: a scalar or a matrix.
class side {
 public:
  side(const term& t) : scalar_(t) {}          // NOLINT(google-explicit-constructor)
  side(int v) : scalar_(term(v)) {}            // NOLINT(google-explicit-constructor)
  side(const mat& m) : is_matrix_(true), matrix_(m) {}  // NOLINT(google-explicit-constructor)
  bool is_matrix() const { return is_matrix_; }
  const term& scalar() const { return scalar_; }
  const mat& matrix() const { return matrix_; }
  /// Every entry (one for a scalar).
  std::vector<term> entries() const;
  std::string tex() const;

 private:
  bool is_matrix_ = false;
  term scalar_;
  mat matrix_{1, 1};
};

/// Values of variables: {{n, 1}, {f, 2}}.
using assignment = std::vector<std::pair<term, term>>;

/// A set of signs, as bits: negative, zero, positive.
enum sign_bits : unsigned { negative = 1, zero = 2, positive = 4, nonzero = 5, any_sign = 7 };

/// A declared fact: `expr` takes only the signs in `signs` (nonzero, positive or negative).
struct fact {
  term expr;
  unsigned signs = nonzero;
  std::string tex() const;  ///< "P \cdot L \neq 0", "n > 0", ...
};

enum class step_kind {
  definition,         ///< notation unfolded; may have identical sides (not counted as checked)
  derivation,         ///< a step of the derivation: must hold
  code,               ///< the library's template, instantiated with terms, equals the derived form
  sign,               ///< under its premises, every claim holds (each expression has its signs)
  erratum,            ///< printed in a reference derivation and false: refuted by a counterexample
  false_in_general,   ///< a tempting shortcut, refuted the same way
};

/// What a step says about a reference derivation: a mistake it makes, or a candidate mistake
/// that turns out not to be one. The document lists both at the top.
enum class verdict { none, mistake, not_a_mistake };

/// A named step with the sentence that says why it holds (or where the source went wrong).
struct step {
  std::string name;
  std::string why;
  side lhs;
  side rhs;
  step_kind kind = step_kind::derivation;
  /// Refuted steps: values of the variables that make lhs − rhs a non-zero number.
  assignment counterexample;
  /// Errata: the vector convention under which the printed equation is read and is false.
  std::string convention;
  /// Code steps: the header that holds the template.
  std::string header;
  /// Extra facts the step rests on (printed with it; a counterexample must satisfy them too).
  /// Sign steps: the conditions of one path of the code.
  std::vector<fact> premises;
  /// Sign steps: what must follow from the facts and premises (each expression's signs).
  std::vector<fact> claims;
  /// Errata are mistakes; other steps may settle a candidate either way.
  verdict about_source = verdict::none;
  /// For verdict::not_a_mistake: why the candidate is not one, in a few words.
  std::string reason;
};

/// A derivation: one file under proofs/derivations/ builds one.
struct derivation {
  std::string slug;    ///< File name without extension; the ctest name is "proof: <slug>".
  std::string title;
  std::string source;  ///< Which reference derivation it follows ("seed 002"), or empty.
  std::string intro;   ///< Markdown: the setting, the symbols, the conventions.
  std::vector<fact> facts;
  std::vector<step> steps;
  std::string conclusion;
  /// Caption of the figure docs/figures/<slug>.svg (drawn from exact numbers by figures.cpp).
  std::string figure;
  /// When building it failed (e.g. the library threw): why. Checking reports it as a failure.
  std::string build_error;

  void assume_nonzero(const term& e);
  void assume_positive(const term& e);
  void assume_negative(const term& e);
  /// Unfolds notation: lhs is by definition rhs (the two may be the same expression).
  void define(std::string name, std::string why, side lhs, side rhs);
  /// A step that must hold identically.
  void show(std::string name, std::string why, side lhs, side rhs);
  /// The library's code (lhs, computed by a template of `header` instantiated with terms) equals
  /// the derived form (rhs).
  void code(std::string name, std::string why, std::string header, side lhs, side rhs);
  /// Under the derivation's facts and `premises`, every claim holds.
  void sign(std::string name, std::string why, std::vector<fact> premises, std::vector<fact> claims);
  /// An equation a reference derivation prints, false when read with `convention`, refuted by
  /// `counterexample`.
  void refute(std::string name, std::string why, std::string convention, side lhs, side rhs,
              assignment counterexample);
  /// A tempting but false equation (no source prints it), with its counterexample.
  void disprove(std::string name, std::string why, side lhs, side rhs, assignment counterexample);
  /// Makes the last step rest on `premises` as well (e.g. "P_y - h > 0" for one branch of code).
  void under(std::vector<fact> premises);
  /// Marks the last step as settling a candidate mistake of the source: it is one, or it is not.
  void mistake();
  void not_a_mistake(std::string reason);
};

/// Decides comparisons from `facts` (for instantiating the library's templates with terms): a
/// comparison the facts do not decide throws, naming it.
std::unique_ptr<comparison_context> comparisons_from(const std::vector<fact>& facts);

/// The outcome of checking one step.
struct step_result {
  bool ok = false;
  std::string message;  ///< Empty when ok; otherwise names the step and says what is wrong.
  /// lhs − rhs normalised, as LaTeX (entry by entry for matrices), for refuted steps at the
  /// counterexample; empty otherwise.
  std::string residual_tex;
  bool residual_zero = false;
};

/// Checks one step of `d` (its facts apply).
step_result check_step(const derivation& d, const step& s);

struct derivation_result {
  bool ok = true;
  std::string message;  ///< A derivation-level failure (build error, contradictory facts).
  std::vector<step_result> steps;
};
/// Checks the facts and every step.
derivation_result check(const derivation& d);

// ---------------------------------------------------------------------------------------------
// Exploring every path of a function whose comparisons depend on signs

/// One path: the sign of each expression the comparisons asked about, and what `f` returned.
struct explored_path {
  std::vector<fact> conditions;
  int outcome = 0;
};

/// Runs `f` once for every combination of answers its comparisons can get: a comparison the
/// facts and the path's conditions decide is answered; otherwise the path splits on the sign of
/// an irreducible factor of the compared difference. Every path is returned with its conditions
/// (on those factors, each written as the first of `names` it is a constant multiple of, if any)
/// and its outcome. Throws when there are more than `max_paths`.
std::vector<explored_path> explore(const std::vector<fact>& facts, const std::function<int()>& f,
                                   const std::vector<term>& names = {}, std::size_t max_paths = 512);

/// LaTeX of a sign set: "> 0", "< 0", "= 0", "\neq 0", "\geq 0", "\leq 0".
std::string signs_tex(unsigned signs);

}  // namespace shadowproof::proofs
