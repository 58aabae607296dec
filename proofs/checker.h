#pragma once
/// A small step checker on GiNaC: a derivation is a list of named steps, each an equation (or a
/// matrix equation) between symbolic expressions, checked symbolically for every value of its
/// symbols, not sampled. Only this directory links GiNaC; the library and the CLI never do.
#include <ginac/ginac.h>

#include <string>
#include <type_traits>
#include <vector>

namespace shadowproof::proofs {

/// One side of a step: the expression that is checked and, optionally, the LaTeX shown for it
/// (a name such as "T(\ell)\,N\,T(-\ell)" for a product that would print as a wall of entries).
/// An empty `tex` shows the expression itself (see `tex` in notation.h).
struct side {
  // Implicit on purpose, so that steps read as math: any matrix, symbol or number is a side.
  template <class E, class = std::enable_if_t<std::is_convertible_v<const E&, GiNaC::ex>>>
  side(const E& v) : value(v) {}  // NOLINT(google-explicit-constructor)
  side(GiNaC::ex v, std::string t) : value(std::move(v)), tex(std::move(t)) {}
  GiNaC::ex value;
  std::string tex;
};

/// What a step claims about lhs = rhs.
enum class claim {
  holds,  ///< lhs − rhs normalises to 0 as a rational function, entry by entry.
  fails,  ///< The printed equation is false: lhs − rhs is not identically 0, and the step's
          ///< counterexample makes it a non-zero number while every assumption stays non-zero.
};

/// A named step with the sentence that says why it is true (or where the source went wrong).
struct step {
  std::string name;
  std::string why;
  side lhs;
  side rhs;
  claim kind = claim::holds;
  /// For claim::fails: values of the symbols (all of them that occur) that refute the step.
  GiNaC::exmap counterexample;
  /// For claim::fails: true when a reference derivation prints the false equation (an erratum),
  /// false for a tempting shortcut shown wrong.
  bool erratum = false;
};

/// An expression the derivation may divide by: it is assumed non-zero. A step whose sides have a
/// denominator that is not a product of powers of assumptions (times a constant) is rejected,
/// so every division a derivation makes is one it declared. A counterexample must keep every
/// assumption that shares a symbol with its step non-zero.
struct assumption {
  GiNaC::ex nonzero;
  std::string tex;  ///< How the assumption reads, e.g. "P\cdot L \neq 0".
};

/// A derivation: one file under proofs/derivations/ builds one of these.
struct derivation {
  std::string slug;    ///< File name without extension; the ctest name is "proof: <slug>".
  std::string title;
  std::string source;  ///< Which reference derivation it follows ("seed 002"), or empty.
  std::string intro;   ///< Markdown paragraph: the setting, the symbols, the conventions.
  std::vector<assumption> assumptions;
  std::vector<step> steps;
  std::string conclusion;  ///< Markdown paragraph after the last step.

  /// Declares `e ≠ 0` (shown as `tex`).
  void assume(const GiNaC::ex& e, std::string tex);
  /// Adds a step that must hold identically.
  void show(std::string name, std::string why, side lhs, side rhs);
  /// Adds an erratum: an equation a reference derivation prints that must be false, with the
  /// counterexample that refutes it.
  void refute(std::string name, std::string why, side lhs, side rhs, GiNaC::exmap counterexample);
  /// Adds a tempting but false equation (no source prints it), with its counterexample.
  void disprove(std::string name, std::string why, side lhs, side rhs, GiNaC::exmap counterexample);
};

/// The outcome of checking one step. `residual` is lhs − rhs normalised (a matrix when the step
/// is a matrix equation); for claim::fails, `counterexample_residual` is its value at the
/// counterexample.
struct step_result {
  bool ok = false;
  std::string message;  ///< Empty when ok; otherwise names the step and says what is wrong.
  GiNaC::ex residual;
  GiNaC::ex counterexample_residual;
};

/// Checks one step of `d` (its assumptions apply).
step_result check_step(const derivation& d, const step& s);

/// Checks every step; `ok` is true when all of them pass.
struct derivation_result {
  bool ok = true;
  std::vector<step_result> steps;
};
derivation_result check(const derivation& d);

}  // namespace shadowproof::proofs
