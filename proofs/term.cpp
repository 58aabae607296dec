#include "term.h"

#include <cctype>
#include <map>
#include <stdexcept>

#include "mat.h"

namespace shadowproof::proofs {

// =============================================================================================
// Construction

term::term() : term(rational(0)) {}
term::term(int v) : term(rational(v)) {}
term::term(long v) : term(rational(v)) {}
term::term(const rational& v) {
  auto n = std::make_shared<node>();
  n->kind = node_kind::number;
  n->value = v;
  n_ = std::move(n);
}

term term::variable(const std::string& name, const std::string& tex) {
  auto n = std::make_shared<node>();
  n->kind = node_kind::symbol;
  n->name = name;
  n->tex = tex;
  return term(std::shared_ptr<const node>(std::move(n)));
}

term term::shown(const term& value, const std::string& tex, tex_precedence p) {
  auto n = std::make_shared<node>();
  n->kind = node_kind::shown;
  n->tex = tex;
  n->precedence = p;
  n->args = {value};
  return term(std::shared_ptr<const node>(std::move(n)));
}

term term::make(node_kind k, std::vector<term> args) {
  auto n = std::make_shared<node>();
  n->kind = k;
  n->args = std::move(args);
  return term(std::shared_ptr<const node>(std::move(n)));
}

term operator+(const term& a, const term& b) { return term::make(node_kind::add, {a, b}); }
term operator-(const term& a, const term& b) { return term::make(node_kind::sub, {a, b}); }
term operator*(const term& a, const term& b) { return term::make(node_kind::mul, {a, b}); }
term operator/(const term& a, const term& b) { return term::make(node_kind::div, {a, b}); }
term operator-(const term& a) { return term::make(node_kind::neg, {a}); }
term power(const term& a, unsigned k) {
  term t = term::make(node_kind::pow, {a});
  std::const_pointer_cast<node>(t.n_)->exponent = k;
  return t;
}

term& term::operator+=(const term& b) { return *this = *this + b; }
term& term::operator-=(const term& b) { return *this = *this - b; }
term& term::operator*=(const term& b) { return *this = *this * b; }
term& term::operator/=(const term& b) { return *this = *this / b; }

bool term::is_number() const { return n_->kind == node_kind::number; }
bool term::is_symbol() const { return n_->kind == node_kind::symbol; }
const rational& term::number() const { return n_->value; }

term term::substitute(const std::vector<std::pair<term, term>>& values) const {
  std::map<const node*, term> done;
  const auto walk = [&](const auto& self, const term& t) -> term {
    const auto found = done.find(t.n_.get());
    if (found != done.end()) return found->second;
    term r = t;
    if (t.is_symbol()) {
      for (const auto& [symbol, value] : values)
        if (symbol.n_ == t.n_) r = value;
    } else if (!t.n_->args.empty()) {
      std::vector<term> args;
      bool changed = false;
      for (const auto& a : t.n_->args) {
        args.push_back(self(self, a));
        changed = changed || args.back().n_ != a.n_;
      }
      if (changed) {
        if (t.n_->kind == node_kind::shown) {
          r = args[0];  // the notation no longer names this value
        } else {
          r = make(t.n_->kind, std::move(args));
          std::const_pointer_cast<node>(r.n_)->exponent = t.n_->exponent;
        }
      }
    }
    done.emplace(t.n_.get(), r);
    return r;
  };
  return walk(walk, *this);
}

// =============================================================================================
// Comparisons

namespace {
thread_local comparison_context* current_context = nullptr;

bool compare(const term& a, const term& b, relation r) {
  if (!current_context)
    throw std::logic_error("comparing " + a.tex() + " with " + b.tex() +
                           " needs a proof context (the derivation's facts)");
  return current_context->decide(a - b, r);
}
}  // namespace

scoped_comparisons::scoped_comparisons(comparison_context& c) : previous_(current_context) { current_context = &c; }
scoped_comparisons::~scoped_comparisons() { current_context = previous_; }

bool operator==(const term& a, const term& b) { return compare(a, b, relation::equal); }
bool operator!=(const term& a, const term& b) { return compare(a, b, relation::not_equal); }
bool operator<(const term& a, const term& b) { return compare(a, b, relation::less); }
bool operator<=(const term& a, const term& b) { return compare(a, b, relation::less_equal); }
bool operator>(const term& a, const term& b) { return compare(a, b, relation::greater); }
bool operator>=(const term& a, const term& b) { return compare(a, b, relation::greater_equal); }

// =============================================================================================
// LaTeX, as written

namespace {

std::string bracket(const std::string& s) { return "\\left(" + s + "\\right)"; }

std::string number_tex(const rational& q) {
  const rational a = abs(q);
  std::string body = a.get_den() == 1 ? a.get_num().get_str()
                                      : "\\frac{" + a.get_num().get_str() + "}{" + a.get_den().get_str() + "}";
  return q < 0 ? "-" + body : body;
}

// A term that prints with a leading minus sign: in a sum it is written "a - b" instead of
// "a + -b", and as a later factor of a product it needs brackets.
bool leads_with_minus(const term& t) {
  return t.root().kind == node_kind::neg || (t.is_number() && t.number() < 0);
}

std::string without_minus(const term& t) {
  if (t.root().kind == node_kind::neg) return t.root().args[0].tex(tex_precedence::product);
  return number_tex(abs(t.number()));
}

void flatten(const term& t, node_kind k, std::vector<term>& out) {
  if (t.root().kind == k && k == node_kind::mul) {
    flatten(t.root().args[0], k, out);
    out.push_back(t.root().args[1]);
  } else {
    out.push_back(t);
  }
}

std::string sum_tex(const term& t) {
  // Left-nested chains a + b - c + d print flat.
  std::vector<std::pair<bool, term>> parts;  // (subtracted, operand)
  term left = t;
  while (left.root().kind == node_kind::add || left.root().kind == node_kind::sub) {
    parts.push_back({left.root().kind == node_kind::sub, left.root().args[1]});
    left = left.root().args[0];
  }
  std::string s = left.tex(tex_precedence::sum);
  for (auto it = parts.rbegin(); it != parts.rend(); ++it) {
    const auto& [subtracted, operand] = *it;
    if (!subtracted) {
      s += leads_with_minus(operand) ? " - " + without_minus(operand) : " + " + operand.tex(tex_precedence::sum);
    } else {
      s += " - " + (leads_with_minus(operand) ? bracket(operand.tex()) : operand.tex(tex_precedence::product));
    }
  }
  return s;
}

std::string product_tex(const term& t) {
  std::vector<term> factors;
  flatten(t, node_kind::mul, factors);
  std::string s;
  for (std::size_t i = 0; i < factors.size(); ++i) {
    const bool first = i == 0;
    std::string f = factors[i].tex(first ? tex_precedence::product : tex_precedence::factor);
    // A run of one variable reads as a power: n n is n^{2}.
    std::size_t run = 1;
    while (factors[i].is_symbol() && i + run < factors.size() && factors[i + run].pointer() == factors[i].pointer()) ++run;
    if (run > 1) {
      f += "^{" + std::to_string(run) + "}";
      i += run - 1;
    }
    if (!first) {
      const bool digit = !f.empty() && (std::isdigit(static_cast<unsigned char>(f[0])) || f.rfind("\\frac", 0) == 0);
      s += digit ? " \\cdot " : " ";
    }
    s += f;
  }
  return s;
}

}  // namespace

tex_precedence term::precedence() const {
  switch (n_->kind) {
    case node_kind::number: return n_->value < 0 ? tex_precedence::product : tex_precedence::atom;
    case node_kind::symbol: return tex_precedence::atom;
    case node_kind::add:
    case node_kind::sub: return tex_precedence::sum;
    case node_kind::neg:
    case node_kind::mul: return tex_precedence::product;
    case node_kind::div:
    case node_kind::pow: return tex_precedence::atom;
    case node_kind::shown: return n_->precedence;
  }
  return tex_precedence::atom;
}

std::string term::tex() const {
  const node& n = *n_;
  switch (n.kind) {
    case node_kind::number: return number_tex(n.value);
    case node_kind::symbol: return n.tex;
    case node_kind::add:
    case node_kind::sub: return sum_tex(*this);
    case node_kind::neg: return "-" + n.args[0].tex(tex_precedence::product);
    case node_kind::mul: return product_tex(*this);
    case node_kind::div: return "\\frac{" + n.args[0].tex() + "}{" + n.args[1].tex() + "}";
    case node_kind::pow: return n.args[0].tex(tex_precedence::atom) + "^{" + std::to_string(n.exponent) + "}";
    case node_kind::shown: return n.tex;
  }
  return "?";
}

std::string term::tex(tex_precedence context) const {
  return precedence() < context ? bracket(tex()) : tex();
}

std::ostream& operator<<(std::ostream& out, const term& t) { return out << t.tex(); }

// =============================================================================================
// Matrices

namespace {

std::string index_name(unsigned i, unsigned size) {
  static const char* xyzw[] = {"x", "y", "z", "w"};
  return size <= 4 && size >= 3 ? xyzw[i] : std::to_string(i + 1);
}

std::vector<term> zeros(unsigned n) { return std::vector<term>(n, term(0)); }

}  // namespace

mat::mat(unsigned rows, unsigned cols)
    : rows_(rows), cols_(cols), e_(zeros(rows * cols)), tex_("0"), precedence_(tex_precedence::atom) {}

mat::mat(std::initializer_list<std::initializer_list<term>> rows) {
  rows_ = static_cast<unsigned>(rows.size());
  cols_ = rows_ ? static_cast<unsigned>(rows.begin()->size()) : 0;
  for (const auto& r : rows) {
    if (r.size() != cols_) throw std::logic_error("a written-out matrix has rows of different lengths");
    for (const auto& x : r) e_.push_back(x);
  }
  written_out_ = true;
}

mat::mat(unsigned rows, unsigned cols, std::vector<term> entries, std::string tex, tex_precedence p)
    : rows_(rows), cols_(cols), e_(std::move(entries)), tex_(std::move(tex)), precedence_(p) {
  if (e_.size() != rows_ * cols_) throw std::logic_error("matrix entries do not match its shape");
}

mat mat::named(const std::string& tex, const mat& value) { return value.as(tex, tex_precedence::atom); }

mat mat::column(std::vector<term> entries) {
  const auto size = static_cast<unsigned>(entries.size());
  mat m(size, 1, std::move(entries), "", tex_precedence::atom);
  m.written_out_ = true;
  return m;
}

mat mat::as(const std::string& tex, tex_precedence p) const {
  mat m = *this;
  m.tex_ = tex;
  m.precedence_ = p;
  m.written_out_ = false;
  return m;
}

mat mat::written() const {
  mat m = *this;
  m.written_out_ = true;
  m.precedence_ = tex_precedence::atom;
  return m;
}

std::string mat::tex() const {
  if (!written_out_) return tex_;
  std::string s = "\\begin{pmatrix} ";
  for (unsigned i = 0; i < rows_; ++i) {
    if (i) s += " \\\\ ";
    for (unsigned j = 0; j < cols_; ++j) s += (j ? " & " : "") + (*this)(i, j).tex();
  }
  return s + " \\end{pmatrix}";
}

std::string mat::tex(tex_precedence context) const {
  return precedence() < context ? bracket(tex()) : tex();
}

term mat::entry(unsigned i, unsigned j) const {
  const term& raw = (*this)(i, j);
  if (raw.is_number() || raw.is_symbol() || written_out_) return raw;
  const std::string index = cols_ == 1 ? index_name(i, rows_) : std::to_string(i + 1) + std::to_string(j + 1);
  return term::shown(raw, tex(tex_precedence::atom) + "_{" + index + "}", tex_precedence::atom);
}

term mat::entry(unsigned i) const { return entry(i, 0); }

mat operator*(const mat& a, const mat& b) {
  if (a.cols() != b.rows()) throw std::logic_error("matrix product of incompatible shapes");
  std::vector<term> e;
  for (unsigned i = 0; i < a.rows(); ++i)
    for (unsigned j = 0; j < b.cols(); ++j) {
      term s = a(i, 0) * b(0, j);
      for (unsigned k = 1; k < a.cols(); ++k) s = s + a(i, k) * b(k, j);
      e.push_back(s);
    }
  return mat(a.rows(), b.cols(), std::move(e),
             a.tex(tex_precedence::product) + " " + b.tex(tex_precedence::factor), tex_precedence::product);
}

mat operator*(const term& s, const mat& a) {
  std::vector<term> e;
  for (const auto& x : a.entries()) e.push_back(s * x);
  // -s M reads better than (-s) M.
  const std::string scale = s.root().kind == node_kind::neg ? "-" + s.root().args[0].tex(tex_precedence::factor)
                                                            : s.tex(tex_precedence::factor);
  return mat(a.rows(), a.cols(), std::move(e), scale + " " + a.tex(tex_precedence::factor), tex_precedence::product);
}

mat operator+(const mat& a, const mat& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) throw std::logic_error("matrix sum of different shapes");
  std::vector<term> e;
  for (std::size_t i = 0; i < a.entries().size(); ++i) e.push_back(a.entries()[i] + b.entries()[i]);
  return mat(a.rows(), a.cols(), std::move(e), a.tex(tex_precedence::sum) + " + " + b.tex(tex_precedence::sum),
             tex_precedence::sum);
}

mat operator-(const mat& a, const mat& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) throw std::logic_error("matrix difference of different shapes");
  std::vector<term> e;
  for (std::size_t i = 0; i < a.entries().size(); ++i) e.push_back(a.entries()[i] - b.entries()[i]);
  return mat(a.rows(), a.cols(), std::move(e), a.tex(tex_precedence::sum) + " - " + b.tex(tex_precedence::product),
             tex_precedence::sum);
}

mat operator-(const mat& a) {
  std::vector<term> e;
  for (const auto& x : a.entries()) e.push_back(-x);
  return mat(a.rows(), a.cols(), std::move(e), "-" + a.tex(tex_precedence::product), tex_precedence::product);
}

mat transpose(const mat& a) {
  std::vector<term> e;
  for (unsigned j = 0; j < a.cols(); ++j)
    for (unsigned i = 0; i < a.rows(); ++i) e.push_back(a(i, j));
  return mat(a.cols(), a.rows(), std::move(e), a.tex(tex_precedence::atom) + "^{\\mathsf T}", tex_precedence::atom);
}

namespace {
term sum_of_products(const mat& a, const mat& b) {
  if (a.cols() != 1 || b.cols() != 1 || a.rows() != b.rows()) throw std::logic_error("dot product of unequal vectors");
  term s = a[0] * b[0];
  for (unsigned i = 1; i < a.rows(); ++i) s = s + a[i] * b[i];
  return s;
}
}  // namespace

term dot(const mat& a, const mat& b) {
  return term::shown(sum_of_products(a, b), a.tex(tex_precedence::factor) + " \\cdot " + b.tex(tex_precedence::factor),
                     tex_precedence::product);
}

term inner(const mat& a, const mat& b) {
  return term::shown(sum_of_products(a, b), "\\langle " + a.tex() + ", " + b.tex() + " \\rangle", tex_precedence::atom);
}

namespace {
term laplace(const std::vector<std::vector<term>>& m) {
  const std::size_t n = m.size();
  if (n == 1) return m[0][0];
  term s;
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<std::vector<term>> minor;
    for (std::size_t i = 1; i < n; ++i) {
      std::vector<term> row;
      for (std::size_t k = 0; k < n; ++k)
        if (k != j) row.push_back(m[i][k]);
      minor.push_back(row);
    }
    const term product = m[0][j] * laplace(minor);
    s = j == 0 ? product : (j % 2 ? s - product : s + product);
  }
  return s;
}
}  // namespace

term det(const mat& a) {
  if (a.rows() != a.cols()) throw std::logic_error("determinant of a non-square matrix");
  std::vector<std::vector<term>> m(a.rows());
  for (unsigned i = 0; i < a.rows(); ++i)
    for (unsigned j = 0; j < a.cols(); ++j) m[i].push_back(a(i, j));
  return term::shown(laplace(m), "\\det " + a.tex(tex_precedence::atom), tex_precedence::product);
}

mat identity(unsigned n) {
  std::vector<term> e;
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j) e.push_back(term(i == j ? 1 : 0));
  return mat(n, n, std::move(e), "I", tex_precedence::atom);
}

mat column(const term& x, const term& y, const term& z, const term& w) { return mat::column({x, y, z, w}); }
mat column(const term& x, const term& y, const term& z) { return mat::column({x, y, z}); }

mat apply(const std::string& name, const mat& arg, const mat& value) {
  return value.as(name + "\\left(" + arg.tex() + "\\right)", tex_precedence::atom);
}

mat affine(const mat& v) {
  if (v.cols() != 1 || v.rows() != 4) throw std::logic_error("affine() of something else than a 4-vector");
  const mat value = column(v[0] / v[3], v[1] / v[3], v[2] / v[3]);
  return apply("\\operatorname{affine}", v, value);
}

mat block(const mat& a, unsigned k) {
  std::vector<term> e;
  for (unsigned i = 0; i < k; ++i)
    for (unsigned j = 0; j < k; ++j) e.push_back(a(i, j));
  return mat(k, k, std::move(e), a.tex(tex_precedence::atom) + "_{" + std::to_string(k) + "\\times" + std::to_string(k) + "}",
             tex_precedence::atom);
}

mat translation(const term& x, const term& y, const term& z, const std::string& tex) {
  return mat::named(tex, mat{{1, 0, 0, x}, {0, 1, 0, y}, {0, 0, 1, z}, {0, 0, 0, 1}});
}

mat scaling(const term& x, const term& y, const term& z, const std::string& tex) {
  return mat::named(tex, mat{{x, 0, 0, 0}, {0, y, 0, 0}, {0, 0, z, 0}, {0, 0, 0, 1}});
}

mat embed(const mat& a3) {
  std::vector<term> e;
  for (unsigned i = 0; i < 4; ++i)
    for (unsigned j = 0; j < 4; ++j) e.push_back(i < 3 && j < 3 ? a3(i, j) : term(i == j ? 1 : 0));
  return mat(4, 4, std::move(e), a3.tex(tex_precedence::atom), tex_precedence::atom);
}

}  // namespace shadowproof::proofs
