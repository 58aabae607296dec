// The only file of the proofs that includes GiNaC: recorded terms are converted here, after the
// checks that must see them as written (divisions, identical sides) have read them.
#include "checker.h"

#include <ginac/ginac.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace shadowproof::proofs {

using namespace GiNaC;

// =============================================================================================
// Sides and facts

std::vector<term> side::entries() const { return is_matrix_ ? matrix_.entries() : std::vector<term>{scalar_}; }

std::string side::tex() const { return is_matrix_ ? matrix_.tex() : scalar_.tex(); }

std::string signs_tex(unsigned s) {
  switch (s) {
    case positive: return "> 0";
    case negative: return "< 0";
    case zero: return "= 0";
    case nonzero: return "\\neq 0";
    case positive | zero: return "\\geq 0";
    case negative | zero: return "\\leq 0";
    default: return "\\in \\mathbb{R}";
  }
}

std::string fact::tex() const { return expr.tex() + " " + signs_tex(signs); }

void derivation::assume_nonzero(const term& e) { facts.push_back({e, nonzero}); }
void derivation::assume_positive(const term& e) { facts.push_back({e, positive}); }
void derivation::assume_negative(const term& e) { facts.push_back({e, negative}); }

namespace {
step make_step(std::string name, std::string why, side lhs, side rhs, step_kind kind) {
  step s{std::move(name), std::move(why), std::move(lhs), std::move(rhs), kind, {}, {}, {}, {}, {}, verdict::none, {}};
  return s;
}
}  // namespace

void derivation::define(std::string name, std::string why, side lhs, side rhs) {
  step s = make_step(std::move(name), std::move(why), std::move(lhs), std::move(rhs), step_kind::definition);
  steps.push_back(std::move(s));
}

void derivation::show(std::string name, std::string why, side lhs, side rhs) {
  steps.push_back(make_step(std::move(name), std::move(why), std::move(lhs), std::move(rhs), step_kind::derivation));
}

void derivation::code(std::string name, std::string why, std::string header, side lhs, side rhs) {
  step s = make_step(std::move(name), std::move(why), std::move(lhs), std::move(rhs), step_kind::code);
  s.header = std::move(header);
  steps.push_back(std::move(s));
}

void derivation::sign(std::string name, std::string why, std::vector<fact> premises, std::vector<fact> claims) {
  step s = make_step(std::move(name), std::move(why), side(0), side(0), step_kind::sign);
  s.premises = std::move(premises);
  s.claims = std::move(claims);
  steps.push_back(std::move(s));
}

void derivation::refute(std::string name, std::string why, std::string convention, side lhs, side rhs,
                        assignment counterexample) {
  step s = make_step(std::move(name), std::move(why), std::move(lhs), std::move(rhs), step_kind::erratum);
  s.about_source = verdict::mistake;
  s.convention = std::move(convention);
  s.counterexample = std::move(counterexample);
  steps.push_back(std::move(s));
}

void derivation::disprove(std::string name, std::string why, side lhs, side rhs, assignment counterexample) {
  step s = make_step(std::move(name), std::move(why), std::move(lhs), std::move(rhs), step_kind::false_in_general);
  s.counterexample = std::move(counterexample);
  steps.push_back(std::move(s));
}

void derivation::under(std::vector<fact> premises) { steps.back().premises = std::move(premises); }
void derivation::mistake() { steps.back().about_source = verdict::mistake; }
void derivation::not_a_mistake(std::string reason) {
  steps.back().about_source = verdict::not_a_mistake;
  steps.back().reason = std::move(reason);
}

namespace {

// =============================================================================================
// Deterministic LaTeX of GiNaC expressions (residuals, path conditions). GiNaC orders terms by
// hash values, which depend on addresses; this printer sorts terms and factors by their own text.

struct signed_tex {
  bool negative = false;
  std::string body;
};

signed_tex term_tex(const ex& e);
std::string ex_tex(const ex& e);

std::string numeric_tex(const numeric& q) {
  std::ostringstream out;
  if (q.is_integer()) out << q;
  else out << "\\frac{" << q.numer() << "}{" << q.denom() << "}";
  return out.str();
}

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? sep : "") + parts[i];
  return s;
}

// Lower-case names before upper-case ones, so products read "a L_x".
std::string order_key(const std::string& s) {
  std::string k = s;
  for (char& ch : k) {
    const unsigned char u = static_cast<unsigned char>(ch);
    if (std::islower(u)) ch = static_cast<char>(std::toupper(u));
    else if (std::isupper(u)) ch = static_cast<char>(std::tolower(u));
  }
  return k;
}

std::string power_tex(const ex& base, const numeric& exponent);

std::string factor_tex(const ex& e) {
  if (is_a<add>(e)) return "\\left(" + term_tex(e).body + "\\right)";
  if (is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1))) return power_tex(e.op(0), ex_to<numeric>(e.op(1)));
  const signed_tex t = term_tex(e);
  return t.negative ? "\\left(-" + t.body + "\\right)" : t.body;
}

std::string power_tex(const ex& base, const numeric& exponent) {
  std::string b = factor_tex(base);
  if (is_a<GiNaC::power>(base) || is_a<mul>(base)) b = "\\left(" + term_tex(base).body + "\\right)";
  if (exponent == 1) return b;
  return b + "^{" + numeric_tex(exponent) + "}";
}

std::vector<signed_tex> sorted_terms(const ex& sum) {
  std::vector<std::pair<bool, signed_tex>> terms;
  for (const auto& t : sum) terms.push_back({is_a<numeric>(t), term_tex(t)});
  std::sort(terms.begin(), terms.end(), [](const auto& x, const auto& y) {
    if (x.first != y.first) return !x.first;
    if (x.second.negative != y.second.negative) return !x.second.negative;
    return order_key(x.second.body) < order_key(y.second.body);
  });
  std::vector<signed_tex> r;
  for (auto& t : terms) r.push_back(std::move(t.second));
  return r;
}

signed_tex term_tex(const ex& e) {
  if (is_a<numeric>(e)) {
    const numeric q = ex_to<numeric>(e);
    return {q < 0, numeric_tex(abs(q))};
  }
  if (is_a<GiNaC::symbol>(e)) return {false, ex_to<GiNaC::symbol>(e).get_TeX_name()};
  if (is_a<add>(e)) {
    std::string s;
    bool first = true;
    for (const auto& t : sorted_terms(e)) {
      if (first) s += t.negative ? "-" + t.body : t.body;
      else s += (t.negative ? " - " : " + ") + t.body;
      first = false;
    }
    return {false, s};
  }
  if (is_a<mul>(e)) {
    numeric c = 1;
    std::vector<std::string> num, den;
    for (const auto& f : e) {
      if (is_a<numeric>(f)) c *= ex_to<numeric>(f);
      else if (is_a<GiNaC::power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)) < 0)
        den.push_back(power_tex(f.op(0), -ex_to<numeric>(f.op(1))));
      else num.push_back(factor_tex(f));
    }
    const auto by_key = [](const std::string& x, const std::string& y) { return order_key(x) < order_key(y); };
    std::sort(num.begin(), num.end(), by_key);
    std::sort(den.begin(), den.end(), by_key);
    const bool negative = c < 0;
    c = abs(c);
    if (c.numer() != 1 || num.empty()) num.insert(num.begin(), numeric_tex(c.numer()));
    if (c.denom() != 1) den.insert(den.begin(), numeric_tex(c.denom()));
    if (den.empty()) return {negative, join(num, " ")};
    return {negative, "\\frac{" + join(num, " ") + "}{" + join(den, " ") + "}"};
  }
  if (is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1))) {
    const numeric n = ex_to<numeric>(e.op(1));
    if (n < 0) return {false, "\\frac{1}{" + power_tex(e.op(0), -n) + "}"};
    return {false, power_tex(e.op(0), n)};
  }
  if (is_a<matrix>(e)) {
    const matrix& m = ex_to<matrix>(e);
    std::vector<std::string> rows;
    for (unsigned i = 0; i < m.rows(); ++i) {
      std::vector<std::string> cells;
      for (unsigned j = 0; j < m.cols(); ++j) cells.push_back(ex_tex(m(i, j)));
      rows.push_back(join(cells, " & "));
    }
    return {false, "\\begin{pmatrix} " + join(rows, " \\\\ ") + " \\end{pmatrix}"};
  }
  std::ostringstream out;
  out << latex << e;
  return {false, out.str()};
}

std::string ex_tex(const ex& e) {
  const signed_tex t = term_tex(e);
  return t.negative ? "-" + t.body : t.body;
}

// A plain-text rendering for messages.
std::string text(const ex& e) { return ex_tex(e); }

// =============================================================================================
// Terms to GiNaC and back

struct ex_less {
  bool operator()(const ex& a, const ex& b) const { return ex_is_less()(a, b); }
};

// One GiNaC symbol per variable for the whole run, so that every conversion agrees.
struct symbol_table {
  std::map<const node*, std::pair<std::shared_ptr<const node>, realsymbol>> forward;
  std::map<ex, term, ex_less> back;

  const realsymbol& of(const term& t) {
    auto it = forward.find(t.pointer().get());
    if (it == forward.end()) {
      realsymbol s(t.root().name, t.root().tex);
      it = forward.emplace(t.pointer().get(), std::make_pair(t.pointer(), s)).first;
      back.emplace(s, t);
    }
    return it->second.second;
  }
};

symbol_table& symbols() {
  static symbol_table table;
  return table;
}

numeric to_numeric(const rational& q) {
  return numeric(q.get_num().get_str().c_str()) / numeric(q.get_den().get_str().c_str());
}

rational to_rational(const numeric& q) {
  std::ostringstream out;
  out << q;
  return rational(out.str());
}

enum class division { evaluate, opaque };

// Converts recorded terms to GiNaC. In `opaque` mode a division by anything but a number becomes
// a fresh symbol for the pair (numerator, denominator), so no cancellation across a division can
// happen: the mode in which "identical before normalisation" is decided.
class converter {
 public:
  explicit converter(division mode) : mode_(mode) {}

  ex operator()(const term& t) {
    const auto found = memo_.find(t.pointer().get());
    if (found != memo_.end()) return found->second.second;
    const ex r = convert(t);
    memo_.emplace(t.pointer().get(), std::make_pair(t.pointer(), r));
    return r;
  }

 private:
  ex convert(const term& t) {
    const node& n = t.root();
    switch (n.kind) {
      case node_kind::number: return to_numeric(n.value);
      case node_kind::symbol: return symbols().of(t);
      case node_kind::add: return (*this)(n.args[0]) + (*this)(n.args[1]);
      case node_kind::sub: return (*this)(n.args[0]) - (*this)(n.args[1]);
      case node_kind::neg: return -(*this)(n.args[0]);
      case node_kind::mul: return (*this)(n.args[0]) * (*this)(n.args[1]);
      case node_kind::pow: return GiNaC::pow((*this)(n.args[0]), n.exponent);
      case node_kind::shown: return (*this)(n.args[0]);
      case node_kind::div: {
        const ex a = (*this)(n.args[0]), b = (*this)(n.args[1]);
        if (mode_ == division::evaluate || is_a<numeric>(b)) {
          if (is_a<numeric>(b) && b.is_zero()) throw std::domain_error("division by the number 0");
          return a / b;
        }
        const auto key = std::make_pair(a, b);
        auto it = quotients_.find(key);
        if (it == quotients_.end()) it = quotients_.emplace(key, symbol("q" + std::to_string(quotients_.size()))).first;
        return it->second;
      }
    }
    return 0;
  }

  struct pair_less {
    bool operator()(const std::pair<ex, ex>& x, const std::pair<ex, ex>& y) const {
      const int c = x.first.compare(y.first);
      return c != 0 ? c < 0 : x.second.compare(y.second) < 0;
    }
  };

  division mode_;
  std::map<const node*, std::pair<std::shared_ptr<const node>, ex>> memo_;
  std::map<std::pair<ex, ex>, ex, pair_less> quotients_;
};

// A polynomial back to a term (for path conditions), terms and factors in a deterministic order.
term from_ex(const ex& e) {
  if (is_a<numeric>(e)) return term(to_rational(ex_to<numeric>(e)));
  if (is_a<GiNaC::symbol>(e)) {
    const auto it = symbols().back.find(e);
    if (it == symbols().back.end()) throw std::logic_error("an unknown symbol " + text(e));
    return it->second;
  }
  if (is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_pos_integer())
    return proofs::power(from_ex(e.op(0)), static_cast<unsigned>(ex_to<numeric>(e.op(1)).to_int()));
  if (is_a<add>(e) || is_a<mul>(e)) {
    std::vector<std::pair<std::string, ex>> parts;
    for (const auto& x : e) parts.push_back({order_key(ex_tex(x)), x});
    if (is_a<add>(e)) {
      // Positive terms first, constants last, as the printer orders them.
      std::stable_sort(parts.begin(), parts.end(), [](const auto& x, const auto& y) {
        const bool nx = is_a<numeric>(x.second), ny = is_a<numeric>(y.second);
        if (nx != ny) return !nx;
        const bool mx = term_tex(x.second).negative, my = term_tex(y.second).negative;
        if (mx != my) return !mx;
        return order_key(term_tex(x.second).body) < order_key(term_tex(y.second).body);
      });
      term s = from_ex(parts[0].second);
      for (std::size_t i = 1; i < parts.size(); ++i) {
        const ex& x = parts[i].second;
        if (term_tex(x).negative) s = s - from_ex(-x);
        else s = s + from_ex(x);
      }
      return s;
    }
    // Numeric factor first.
    std::stable_sort(parts.begin(), parts.end(), [](const auto& x, const auto& y) {
      const bool nx = is_a<numeric>(x.second), ny = is_a<numeric>(y.second);
      if (nx != ny) return nx;
      return x.first < y.first;
    });
    if (is_a<numeric>(parts[0].second) && ex_to<numeric>(parts[0].second) == -1 && parts.size() > 1) {
      term p = from_ex(parts[1].second);
      for (std::size_t i = 2; i < parts.size(); ++i) p = p * from_ex(parts[i].second);
      return -p;
    }
    term p = from_ex(parts[0].second);
    for (std::size_t i = 1; i < parts.size(); ++i) p = p * from_ex(parts[i].second);
    return p;
  }
  throw std::logic_error("cannot read back " + text(e));
}

// =============================================================================================
// Signs

unsigned sign_of_number(const numeric& q) { return q.is_zero() ? zero : (q < 0 ? negative : positive); }

unsigned negate(unsigned s) {
  return (s & zero) | ((s & negative) ? positive : 0u) | ((s & positive) ? negative : 0u);
}

unsigned multiply(unsigned a, unsigned b) {
  unsigned r = 0;
  for (unsigned x : {negative, zero, positive})
    for (unsigned y : {negative, zero, positive}) {
      if (!(a & x) || !(b & y)) continue;
      if (x == zero || y == zero) r |= zero;
      else r |= (x == y) ? positive : negative;
    }
  return r;
}

unsigned raise(unsigned s, unsigned k) {
  if (k == 0) return positive;
  unsigned r = s;
  for (unsigned i = 1; i < k; ++i) r = multiply(r, s);
  return r;
}

// Signs of rational functions from facts about polynomials: a fact on p/q is kept as a fact on
// p·q (same sign wherever q ≠ 0). A polynomial's signs come from a fact about it (up to a
// constant factor), from exact division by a non-zero fact, or from its factors.
class sign_engine {
 public:
  void add(const ex& e, unsigned signs) {
    const ex v = normal(e);
    const ex nd = numer_denom(v);
    const ex p = expand(nd.op(0) * nd.op(1));
    facts_.push_back({p, signs});
    cache_.clear();
  }

  unsigned of(const ex& e) {
    const ex v = normal(e);
    if (is_a<numeric>(v)) return sign_of_number(ex_to<numeric>(v));
    const ex nd = numer_denom(v);
    const unsigned n = of_polynomial(nd.op(0)), d = of_polynomial(nd.op(1)) & ~unsigned(zero);
    return d ? multiply(n, d) : unsigned(any_sign);
  }

  // The irreducible non-constant factors of the numerator and denominator of e.
  std::vector<ex> factors(const ex& e) {
    const ex nd = numer_denom(normal(e));
    std::vector<ex> r;
    for (int i = 0; i < 2; ++i) collect_factors(factor(expand(nd.op(i))), r);
    return r;
  }

  // A non-zero constant c with p = c·f for a fact f, intersected over all such facts.
  unsigned direct(const ex& p) {
    unsigned r = any_sign;
    for (const auto& [f, s] : facts_) {
      if (is_a<numeric>(f)) continue;
      const ex q = normal(p / f);
      if (is_a<numeric>(q) && !q.is_zero()) r &= ex_to<numeric>(q) < 0 ? negate(s) : s;
    }
    return r;
  }

 private:
  static void collect_factors(const ex& f, std::vector<ex>& out) {
    if (is_a<mul>(f)) {
      for (const auto& x : f) collect_factors(x, out);
    } else if (is_a<GiNaC::power>(f)) {
      collect_factors(f.op(0), out);
    } else if (!is_a<numeric>(f)) {
      for (const auto& o : out)
        if (is_a<numeric>(normal(o / f))) return;
      out.push_back(f);
    }
  }

  unsigned of_polynomial(const ex& poly, int depth = 0) {
    const ex p = expand(poly);
    if (is_a<numeric>(p)) return sign_of_number(ex_to<numeric>(p));
    const auto cached = cache_.find(p);
    if (cached != cache_.end()) return cached->second;
    unsigned r = direct(p);
    if (r == any_sign && depth < 8) {
      for (const auto& entry : facts_) {
        const ex& f = entry.first;
        if (is_a<numeric>(f)) continue;
        const unsigned known = direct(f);  // every fact about f, intersected
        if (known & zero) continue;
        ex q;
        if (divide(p, f, q) && !is_a<numeric>(normal(p / f))) {
          r = multiply(known, of_polynomial(q, depth + 1));
          break;
        }
      }
    }
    if (r == any_sign && depth < 8) {
      const ex fp = factor(p);
      if (is_a<mul>(fp) || (is_a<GiNaC::power>(fp) && !fp.op(1).is_equal(1))) {
        unsigned product = positive;
        bool proper = false;
        const exvector parts = is_a<mul>(fp) ? exvector(fp.begin(), fp.end()) : exvector{fp};
        for (const ex& x : parts) {
          if (is_a<numeric>(x)) {
            product = multiply(product, sign_of_number(ex_to<numeric>(x)));
          } else if (is_a<GiNaC::power>(x) && is_a<numeric>(x.op(1))) {
            proper = true;
            product = multiply(product, raise(of_polynomial(x.op(0), depth + 1), ex_to<numeric>(x.op(1)).to_int()));
          } else {
            proper = proper || !is_a<numeric>(normal(p / x));
            product = multiply(product, of_polynomial(x, depth + 1));
          }
        }
        if (proper) r = product;
      }
    }
    cache_.emplace(p, r);
    return r;
  }

  std::vector<std::pair<ex, unsigned>> facts_;
  std::map<ex, unsigned, ex_less> cache_;
};

unsigned truth_of(relation r) {
  switch (r) {
    case relation::equal: return zero;
    case relation::not_equal: return nonzero;
    case relation::less: return negative;
    case relation::less_equal: return negative | zero;
    case relation::greater: return positive;
    case relation::greater_equal: return positive | zero;
  }
  return any_sign;
}

const char* relation_text(relation r) {
  switch (r) {
    case relation::equal: return "= 0";
    case relation::not_equal: return "!= 0";
    case relation::less: return "< 0";
    case relation::less_equal: return "<= 0";
    case relation::greater: return "> 0";
    case relation::greater_equal: return ">= 0";
  }
  return "?";
}

unsigned add_signs(unsigned a, unsigned b) {
  const auto within = [](unsigned x, unsigned allowed) { return (x & ~allowed) == 0; };
  if (within(a, zero) ) return b;
  if (within(b, zero)) return a;
  if (within(a, positive | zero) && within(b, positive | zero))
    return ((a | b) & positive) && (within(a, positive) || within(b, positive)) ? unsigned(positive) : positive | zero;
  if (within(a, negative | zero) && within(b, negative | zero))
    return within(a, negative) || within(b, negative) ? unsigned(negative) : negative | zero;
  return any_sign;
}

// The signs of a recorded term from its structure (a sum of terms of one sign has that sign, a
// product multiplies signs), each part read by the polynomial engine, intersected with what the
// engine says of the whole. Shared sub-terms are evaluated once.
unsigned term_signs(const term& t, converter& value, sign_engine& engine, std::map<const node*, unsigned>& memo) {
  const auto found = memo.find(t.pointer().get());
  if (found != memo.end()) return found->second;
  const node& n = t.root();
  const auto of = [&](const term& x) { return term_signs(x, value, engine, memo); };
  unsigned structural = any_sign;
  switch (n.kind) {
    case node_kind::number: structural = sign_of_number(to_numeric(n.value)); break;
    case node_kind::add: structural = add_signs(of(n.args[0]), of(n.args[1])); break;
    case node_kind::sub: structural = add_signs(of(n.args[0]), negate(of(n.args[1]))); break;
    case node_kind::neg: structural = negate(of(n.args[0])); break;
    case node_kind::mul: structural = multiply(of(n.args[0]), of(n.args[1])); break;
    case node_kind::div: {
      const unsigned den = of(n.args[1]) & ~unsigned(zero);
      structural = den ? multiply(of(n.args[0]), den) : unsigned(any_sign);
      break;
    }
    case node_kind::pow: structural = raise(of(n.args[0]), n.exponent); break;
    case node_kind::symbol:
    case node_kind::shown: break;
  }
  unsigned r = structural;
  if (n.kind != node_kind::number) {
    const unsigned whole = engine.of(value(t));
    r = (structural & whole) ? structural & whole : whole;
  }
  memo.emplace(t.pointer().get(), r);
  return r;
}

unsigned term_signs(const term& t, converter& value, sign_engine& engine) {
  std::map<const node*, unsigned> memo;
  return term_signs(t, value, engine, memo);
}

// Comparisons decided by declared facts only.
class fact_comparisons : public comparison_context {
 public:
  explicit fact_comparisons(const std::vector<fact>& facts) {
    for (const auto& f : facts) engine_.add(convert_(f.expr), f.signs);
  }
  bool decide(const term& difference, relation r) override {
    const unsigned s = term_signs(difference, convert_, engine_);
    const unsigned truth = truth_of(r);
    if ((s & ~truth) == 0) return true;
    if ((s & truth) == 0) return false;
    throw std::runtime_error("the declared facts do not decide whether " + difference.tex() + " " + relation_text(r));
  }

 private:
  converter convert_{division::evaluate};
  sign_engine engine_;
};

// =============================================================================================
// Reading the recorded trees

void walk(const term& t, std::set<const node*>& seen, const std::function<void(const term&)>& visit) {
  if (!seen.insert(t.pointer().get()).second) return;
  visit(t);
  for (const auto& a : t.root().args) walk(a, seen, visit);
}

// Every divisor written in the side, in the order met.
void collect_divisors(const side& s, std::set<const node*>& seen, std::vector<term>& out) {
  for (const auto& e : s.entries())
    walk(e, seen, [&](const term& t) {
      if (t.root().kind == node_kind::div) out.push_back(t.root().args[1]);
    });
}

void collect_symbols(const side& s, std::vector<term>& out) {
  std::set<const node*> seen;
  for (const auto& e : s.entries())
    walk(e, seen, [&](const term& t) {
      if (t.is_symbol()) out.push_back(t);
    });
}

bool same_symbol(const term& a, const term& b) { return a.pointer() == b.pointer(); }

std::string residual_tex(const std::vector<ex>& entries, const side& shape) {
  if (!shape.is_matrix()) return ex_tex(entries[0]);
  const mat& m = shape.matrix();
  std::string s = "\\begin{pmatrix} ";
  for (unsigned i = 0; i < m.rows(); ++i) {
    if (i) s += " \\\\ ";
    for (unsigned j = 0; j < m.cols(); ++j) s += (j ? " & " : "") + ex_tex(entries[i * m.cols() + j]);
  }
  return s + " \\end{pmatrix}";
}

}  // namespace

std::unique_ptr<comparison_context> comparisons_from(const std::vector<fact>& facts) {
  return std::make_unique<fact_comparisons>(facts);
}

// =============================================================================================
// Checking a step

step_result check_step(const derivation& d, const step& s) {
  step_result r;
  const std::string who = "step '" + s.name + "' of '" + d.slug + "'";
  try {
    if (s.lhs.is_matrix() != s.rhs.is_matrix() && s.kind != step_kind::sign) {
      r.message = who + " compares a matrix with a scalar";
      return r;
    }
    if (s.lhs.is_matrix() && (s.lhs.matrix().rows() != s.rhs.matrix().rows() ||
                              s.lhs.matrix().cols() != s.rhs.matrix().cols())) {
      r.message = who + " compares matrices of different shapes";
      return r;
    }
    converter value(division::evaluate);
    sign_engine engine;
    for (const auto& f : d.facts) engine.add(value(f.expr), f.signs);
    for (const auto& f : s.premises) engine.add(value(f.expr), f.signs);

    // Every division as written: its divisor must be non-zero by the declared facts.
    std::vector<term> divisors;
    std::set<const node*> seen;
    collect_divisors(s.lhs, seen, divisors);
    collect_divisors(s.rhs, seen, divisors);
    for (const auto& c : s.claims) collect_divisors(side(c.expr), seen, divisors);
    for (const auto& den : divisors) {
      const ex v = normal(value(den));
      if (v.is_zero()) {
        r.message = who + " divides by " + den.tex() + ", which is 0";
        return r;
      }
      if (term_signs(den, value, engine) & zero) {
        r.message = who + " divides by " + den.tex() + ", which the derivation does not declare non-zero";
        return r;
      }
    }

    if (s.kind == step_kind::sign) {
      if (s.claims.empty()) {
        r.message = who + " claims nothing";
        return r;
      }
      for (const auto& c : s.claims) {
        const unsigned got = term_signs(c.expr, value, engine);
        if (got & ~c.signs) {
          r.message = who + ": the facts do not show " + c.tex() + " (they allow " + signs_tex(got) + ")";
          return r;
        }
      }
      r.ok = true;
      return r;
    }

    const std::vector<term> left = s.lhs.entries(), right = s.rhs.entries();
    // The two sides as built, divisions opaque: identical means the step claims nothing.
    if (s.kind == step_kind::derivation) {
      converter built(division::opaque);
      bool identical = true;
      for (std::size_t i = 0; i < left.size() && identical; ++i)
        identical = built(left[i]).is_equal(built(right[i]));
      if (identical) {
        r.message = who + " has two sides that are the same expression before normalisation; a step must "
                          "show something (or be marked as a definition)";
        return r;
      }
    }

    std::vector<ex> residual;
    bool all_zero = true;
    for (std::size_t i = 0; i < left.size(); ++i) {
      residual.push_back(normal(value(left[i]) - value(right[i])));
      all_zero = all_zero && residual.back().is_zero();
    }

    if (s.kind == step_kind::definition || s.kind == step_kind::derivation || s.kind == step_kind::code) {
      if (!all_zero) {
        r.message = who + " does not hold: lhs - rhs = " + residual_tex(residual, s.lhs) + ", not 0";
        return r;
      }
      r.residual_zero = true;
      r.ok = true;
      return r;
    }

    // Refuted: false in general, and a non-zero number at the counterexample.
    if (all_zero) {
      r.message = who + " is stated to be wrong, but it holds identically";
      return r;
    }
    if (s.counterexample.empty()) {
      r.message = who + " is stated to be wrong but gives no counterexample";
      return r;
    }
    std::vector<term> used;
    collect_symbols(s.lhs, used);
    collect_symbols(s.rhs, used);
    exmap at;
    for (const auto& [symbol, number] : s.counterexample) {
      if (!symbol.is_symbol() || !number.is_number()) {
        r.message = who + ": a counterexample assigns numbers to variables";
        return r;
      }
      if (std::none_of(used.begin(), used.end(), [&](const term& u) { return same_symbol(u, symbol); })) {
        r.message = who + ": the counterexample sets " + symbol.tex() + ", which the step does not use";
        return r;
      }
      at[value(symbol)] = value(number);
    }
    std::vector<ex> used_ex;
    for (const auto& u : used) used_ex.push_back(value(u));
    const auto shares_symbol = [&](const ex& e) {
      return std::any_of(used_ex.begin(), used_ex.end(), [&](const ex& u) { return e.has(u); });
    };
    for (const auto& f : d.facts) {
      const ex fe = value(f.expr);
      if (!shares_symbol(fe)) continue;  // about other symbols of the derivation
      const ex v = normal(fe.subs(at));
      if (!is_a<numeric>(v) || !(sign_of_number(ex_to<numeric>(v)) & f.signs)) {
        r.message = who + ": the counterexample violates or does not fix the fact " + f.tex() + " (it gives " +
                    text(v) + ")";
        return r;
      }
    }
    for (const auto& f : s.premises) {
      const ex v = normal(value(f.expr).subs(at));
      if (!is_a<numeric>(v) || !(sign_of_number(ex_to<numeric>(v)) & f.signs)) {
        r.message = who + ": the counterexample violates or does not fix the premise " + f.tex();
        return r;
      }
    }
    for (const auto& den : divisors) {
      const ex v = normal(value(den).subs(at));
      if (!is_a<numeric>(v) || v.is_zero()) {
        r.message = who + ": the counterexample makes the divisor " + den.tex() + " equal " + text(v);
        return r;
      }
    }
    std::vector<ex> at_point;
    bool zero_there = true;
    for (const auto& x : residual) {
      at_point.push_back(normal(x.subs(at)));
      if (!is_a<numeric>(at_point.back())) {
        r.message = who + ": the counterexample leaves symbols in the residual " + text(at_point.back());
        return r;
      }
      zero_there = zero_there && at_point.back().is_zero();
    }
    if (zero_there) {
      r.message = who + ": the residual vanishes at the counterexample, so it refutes nothing";
      return r;
    }
    r.residual_tex = residual_tex(at_point, s.lhs);
    r.ok = true;
    return r;
  } catch (const std::exception& e) {
    r.ok = false;
    r.message = who + ": " + e.what();
    return r;
  }
}

derivation_result check(const derivation& d) {
  derivation_result r;
  if (!d.build_error.empty()) {
    r.ok = false;
    r.message = "'" + d.slug + "' could not be built: " + d.build_error;
    return r;
  }
  // Facts must be satisfiable one by one and must not contradict each other on one expression.
  converter value(division::evaluate);
  sign_engine engine;
  for (const auto& f : d.facts) {
    const ex v = normal(value(f.expr));
    if (is_a<numeric>(v) && !(sign_of_number(ex_to<numeric>(v)) & f.signs)) {
      r.ok = false;
      r.message = "'" + d.slug + "' declares the false fact " + f.tex();
      return r;
    }
    engine.add(v, f.signs);
    if (!is_a<numeric>(v) && engine.direct(expand(numer(v) * denom(v))) == 0) {
      r.ok = false;
      r.message = "'" + d.slug + "' declares contradictory facts about " + f.expr.tex();
      return r;
    }
  }
  for (const auto& s : d.steps) {
    r.steps.push_back(check_step(d, s));
    if (!r.steps.back().ok) r.ok = false;
  }
  return r;
}

// =============================================================================================
// Exploring every path

namespace {

class exploring_comparisons : public comparison_context {
 public:
  exploring_comparisons(const std::vector<fact>& facts, std::vector<unsigned> script)
      : script_(std::move(script)) {
    for (const auto& f : facts) engine_.add(convert_(f.expr), f.signs);
  }

  bool decide(const term& difference, relation r) override {
    const ex d = convert_(difference);
    const unsigned truth = truth_of(r);
    for (;;) {
      const unsigned s = engine_.of(d);
      if ((s & ~truth) == 0) return true;
      if ((s & truth) == 0) return false;
      split(d, r);
    }
  }

  const std::vector<fact>& conditions() const { return conditions_; }
  // (branch point index, number of options) for the branch points past the script.
  const std::vector<std::pair<std::size_t, std::size_t>>& new_branches() const { return new_branches_; }
  const std::vector<unsigned>& choices() const { return choices_; }

 private:
  // Splits on the sign of the first factor (in a fixed order) whose sign is still open.
  void split(const ex& d, relation r) {
    std::vector<std::pair<std::string, ex>> candidates;
    for (const auto& f : engine_.factors(d)) {
      const unsigned s = engine_.direct(f);
      if (s != negative && s != zero && s != positive) candidates.push_back({ex_tex(f), f});
    }
    if (candidates.empty()) {
      std::string why;
      for (const auto& f : engine_.factors(d)) why += " [" + ex_tex(f) + ": " + std::to_string(engine_.direct(f)) + "]";
      throw std::logic_error("cannot split the comparison of " + ex_tex(d) + " (its factors:" + why + ")");
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const auto& x, const auto& y) { return x.first.size() != y.first.size() ? x.first.size() < y.first.size() : x.first < y.first; });
    const ex atom = candidates.front().second;
    const unsigned open = engine_.direct(atom);
    std::vector<unsigned> options;
    if ((r == relation::equal || r == relation::not_equal) && (open & zero) && (open & nonzero)) {
      options = {zero, open & nonzero};
    } else {
      for (unsigned x : {negative, zero, positive})
        if (open & x) options.push_back(x);
    }
    const std::size_t point = choices_.size();
    unsigned pick = 0;
    if (point < script_.size()) pick = script_[point];
    else new_branches_.push_back({point, options.size()});
    choices_.push_back(pick);
    engine_.add(atom, options[pick]);
    conditions_.push_back({from_ex(atom), options[pick]});
  }

  converter convert_{division::evaluate};
  sign_engine engine_;
  std::vector<unsigned> script_;
  std::vector<unsigned> choices_;
  std::vector<std::pair<std::size_t, std::size_t>> new_branches_;
  std::vector<fact> conditions_;
};

}  // namespace

std::vector<explored_path> explore(const std::vector<fact>& facts, const std::function<int()>& f,
                                   const std::vector<term>& names, std::size_t max_paths) {
  converter value(division::evaluate);
  // A condition on a constant multiple of a named expression is written on the name.
  const auto rename = [&](fact c) {
    const ex e = value(c.expr);
    for (const auto& n : names) {
      const ex q = normal(e / value(n));
      if (is_a<numeric>(q) && !q.is_zero()) {
        if (ex_to<numeric>(q) < 0) c.signs = negate(c.signs);
        c.expr = n;
        return c;
      }
    }
    return c;
  };
  std::vector<explored_path> paths;
  std::vector<std::vector<unsigned>> pending{{}};
  while (!pending.empty()) {
    const std::vector<unsigned> script = pending.back();
    pending.pop_back();
    exploring_comparisons context(facts, script);
    int outcome = 0;
    {
      scoped_comparisons installed(context);
      outcome = f();
    }
    // Merge conditions on the same factor (the last narrowing wins: it is the intersection).
    std::vector<fact> merged;
    for (const auto& raw : context.conditions()) {
      const fact c = rename(raw);
      const std::string key = c.expr.tex();
      auto it = std::find_if(merged.begin(), merged.end(), [&](const fact& m) { return m.expr.tex() == key; });
      if (it == merged.end()) merged.push_back(c);
      else it->signs &= c.signs;
    }
    paths.push_back({merged, outcome});
    if (paths.size() > max_paths) throw std::runtime_error("more than " + std::to_string(max_paths) + " paths");
    for (const auto& [point, count] : context.new_branches())
      for (std::size_t k = 1; k < count; ++k) {
        std::vector<unsigned> next(context.choices().begin(), context.choices().begin() + static_cast<long>(point));
        next.push_back(static_cast<unsigned>(k));
        pending.push_back(next);
      }
  }
  return paths;
}

}  // namespace shadowproof::proofs
