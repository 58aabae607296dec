#pragma once
/// The number type of the proofs: an expression recorded exactly as it is written, before any
/// computer algebra sees it. GiNaC simplifies while it builds ((a·b)/a is b before a checker can
/// see the division), so the proofs never build GiNaC expressions themselves: a `term` keeps every
/// operation as a node, every division included, and the checker (checker.cpp, the only file that
/// includes GiNaC) reads the divisions off the tree before it hands the expression to GiNaC.
///
/// `term` is also a number type for the library's templates: shadow_matrix<term>(P, L) records
/// what the library computes. Comparisons (==, <, ...) are decided by the proof context installed
/// with `scoped_comparisons` (the derivation's declared facts); without one they throw.
///
/// The LaTeX of a term is generated from the same tree, so the formula a reader sees is the
/// formula that is checked.
#include <initializer_list>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "shadowproof/core/number.h"

namespace shadowproof::proofs {

class term;

/// Node kinds. `shown` is a value displayed under a notation generated from other notation (a dot
/// product "P \cdot L", an entry "M_{12}", a determinant): transparent to the checker.
enum class node_kind { number, symbol, add, sub, neg, mul, div, pow, shown };

/// LaTeX precedence: a sub-expression of lower precedence than its context needs brackets.
enum class tex_precedence { sum = 0, product = 1, factor = 2, atom = 3 };

struct node;

/// An immutable recorded expression (shared, so common sub-expressions are stored once).
class term {
 public:
  /// 0.
  term();
  term(int v);                 // NOLINT(google-explicit-constructor): numbers read as numbers.
  term(long v);                // NOLINT(google-explicit-constructor)
  term(const rational& v);     // NOLINT(google-explicit-constructor)

  /// A new variable: `name` is its identifier in messages, `tex` how it prints. Two calls make
  /// two different variables even with the same name.
  static term variable(const std::string& name, const std::string& tex);
  /// `value` displayed as `tex` (precedence `p`): notation derived from other notation.
  static term shown(const term& value, const std::string& tex, tex_precedence p);

  term& operator+=(const term& b);
  term& operator-=(const term& b);
  term& operator*=(const term& b);
  term& operator/=(const term& b);

  friend term operator+(const term& a, const term& b);
  friend term operator-(const term& a, const term& b);
  friend term operator*(const term& a, const term& b);
  friend term operator/(const term& a, const term& b);
  friend term operator-(const term& a);
  /// a^k for k ≥ 0 (a division is always written with /, so that it is recorded).
  friend term power(const term& a, unsigned k);

  // Decided by the installed comparison context (see scoped_comparisons).
  friend bool operator==(const term& a, const term& b);
  friend bool operator!=(const term& a, const term& b);
  friend bool operator<(const term& a, const term& b);
  friend bool operator<=(const term& a, const term& b);
  friend bool operator>(const term& a, const term& b);
  friend bool operator>=(const term& a, const term& b);

  /// The LaTeX of the expression as written.
  std::string tex() const;
  /// Same, bracketed when its precedence is below `context`.
  std::string tex(tex_precedence context) const;
  tex_precedence precedence() const;

  const node& root() const { return *n_; }
  const std::shared_ptr<const node>& pointer() const { return n_; }
  bool is_number() const;
  bool is_symbol() const;
  /// The value of a number node (precondition: is_number()).
  const rational& number() const;
  /// The same tree with every variable in `values` replaced (shown notation is dropped where a
  /// replacement happens below it).
  term substitute(const std::vector<std::pair<term, term>>& values) const;

 private:
  explicit term(std::shared_ptr<const node> n) : n_(std::move(n)) {}
  static term make(node_kind k, std::vector<term> args);
  std::shared_ptr<const node> n_;
  friend struct node;
};

struct node {
  node_kind kind = node_kind::number;
  rational value;                  // number
  unsigned exponent = 0;           // pow
  std::string name;                // symbol: identifier
  std::string tex;                 // symbol, shown: notation
  tex_precedence precedence = tex_precedence::atom;  // shown
  std::vector<term> args;          // operands
};

/// a^k for k ≥ 0.
term power(const term& a, unsigned k);

/// Prints the LaTeX (for messages and for the library's error texts).
std::ostream& operator<<(std::ostream& out, const term& t);

/// The relation a comparison asks about `difference` = lhs − rhs.
enum class relation { equal, not_equal, less, less_equal, greater, greater_equal };

/// Decides comparisons of terms. Installed for a scope with scoped_comparisons; the proofs
/// install one built from a derivation's declared facts (checker.h).
class comparison_context {
 public:
  virtual ~comparison_context() = default;
  /// Whether `difference` (lhs − rhs) stands in relation `r` to 0. Throws when it cannot tell.
  virtual bool decide(const term& difference, relation r) = 0;
};

/// Installs `c` for the lifetime of this object (restoring the previous one after).
class scoped_comparisons {
 public:
  explicit scoped_comparisons(comparison_context& c);
  ~scoped_comparisons();
  scoped_comparisons(const scoped_comparisons&) = delete;
  scoped_comparisons& operator=(const scoped_comparisons&) = delete;

 private:
  comparison_context* previous_;
};

}  // namespace shadowproof::proofs
