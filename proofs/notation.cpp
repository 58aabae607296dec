#include "notation.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <utility>
#include <vector>

namespace shadowproof::proofs {

using namespace GiNaC;

GiNaC::realsymbol symbol(const std::string& name, const std::string& tex_name) {
  return GiNaC::realsymbol(name, tex_name);
}

matrix column(const ex& x, const ex& y, const ex& z, const ex& w) {
  return matrix{{x}, {y}, {z}, {w}};
}

matrix column(const ex& x, const ex& y, const ex& z) { return matrix{{x}, {y}, {z}}; }

ex at(const matrix& v, unsigned i) { return v(i, 0); }

ex dot(const matrix& a, const matrix& b) {
  ex s = 0;
  for (unsigned i = 0; i < a.rows(); ++i) s += a(i, 0) * b(i, 0);
  return s;
}

ex dot3(const matrix& a, const matrix& b) {
  ex s = 0;
  for (unsigned i = 0; i < 3; ++i) s += a(i, 0) * b(i, 0);
  return s;
}

matrix identity(unsigned n) { return ex_to<matrix>(unit_matrix(n)); }

matrix outer(const matrix& a, const matrix& b) { return a.mul(b.transpose()); }

matrix translation(const ex& x, const ex& y, const ex& z) {
  return matrix{{1, 0, 0, x}, {0, 1, 0, y}, {0, 0, 1, z}, {0, 0, 0, 1}};
}

matrix scaling(const ex& x, const ex& y, const ex& z) {
  return matrix{{x, 0, 0, 0}, {0, y, 0, 0}, {0, 0, z, 0}, {0, 0, 0, 1}};
}

matrix embed(const matrix& a3) {
  matrix r = ex_to<matrix>(unit_matrix(4));
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j) r(i, j) = a3(i, j);
  return r;
}

matrix quaternion_rotation(const ex& w, const ex& x, const ex& y, const ex& z) {
  const ex n = w * w + x * x + y * y + z * z;
  return matrix{{(w * w + x * x - y * y - z * z) / n, 2 * (x * y - w * z) / n, 2 * (x * z + w * y) / n},
                {2 * (x * y + w * z) / n, (w * w - x * x + y * y - z * z) / n, 2 * (y * z - w * x) / n},
                {2 * (x * z - w * y) / n, 2 * (y * z + w * x) / n, (w * w - x * x - y * y + z * z) / n}};
}

matrix operator*(const matrix& a, const matrix& b) { return a.mul(b); }
matrix operator*(const ex& s, const matrix& a) { return a.mul_scalar(s); }
matrix operator+(const matrix& a, const matrix& b) { return a.add(b); }
matrix operator-(const matrix& a, const matrix& b) { return a.sub(b); }

matrix normalised(const matrix& a) {
  matrix r(a.rows(), a.cols());
  for (unsigned i = 0; i < a.rows(); ++i)
    for (unsigned j = 0; j < a.cols(); ++j) r(i, j) = normal(a(i, j));
  return r;
}

// --- deterministic LaTeX --------------------------------------------------------------------

namespace {

struct signed_tex {
  bool negative = false;
  std::string body;
};

signed_tex term_tex(const ex& e);

std::string numeric_tex(const numeric& q) {
  std::ostringstream out;
  if (q.is_integer()) {
    out << q;
  } else {
    out << "\\frac{" << q.numer() << "}{" << q.denom() << "}";
  }
  return out.str();
}

std::string join(std::vector<std::string> parts, const std::string& sep) {
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? sep : "") + parts[i];
  return s;
}

std::string power_tex(const ex& base, const numeric& exponent);

// Sort key: lower-case names (a, b, n, ...) before upper-case ones (L_x, V_y, ...), so products
// read "a L_x" and sums "a L_x + b L_y".
std::string order_key(const std::string& s) {
  std::string k = s;
  for (char& ch : k) {
    const unsigned char u = static_cast<unsigned char>(ch);
    if (std::islower(u)) ch = static_cast<char>(std::toupper(u));
    else if (std::isupper(u)) ch = static_cast<char>(std::tolower(u));
  }
  return k;
}

// A factor of a product: sums are bracketed, powers print with their exponent.
std::string factor_tex(const ex& e) {
  if (is_a<add>(e)) return "\\left(" + term_tex(e).body + "\\right)";
  if (is_a<power>(e) && is_a<numeric>(e.op(1))) return power_tex(e.op(0), ex_to<numeric>(e.op(1)));
  const signed_tex t = term_tex(e);
  return t.negative ? "\\left(-" + t.body + "\\right)" : t.body;
}

std::string power_tex(const ex& base, const numeric& exponent) {
  std::string b = factor_tex(base);
  if (is_a<power>(base) || is_a<mul>(base)) b = "\\left(" + term_tex(base).body + "\\right)";
  if (exponent == 1) return b;
  return b + "^{" + numeric_tex(exponent) + "}";
}

// Sum terms and product factors are sorted by their own text, so the order never depends on
// GiNaC's hash-based internal order; constants go last in a sum.
std::vector<signed_tex> sorted_terms(const ex& sum) {
  std::vector<std::pair<bool, signed_tex>> terms;
  for (const auto& t : sum) terms.push_back({is_a<numeric>(t), term_tex(t)});
  // Positive terms first ("n - f", not "-f + n"), constants last.
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
      if (is_a<numeric>(f)) {
        c *= ex_to<numeric>(f);
      } else if (is_a<power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)) < 0) {
        den.push_back(power_tex(f.op(0), -ex_to<numeric>(f.op(1))));
      } else {
        num.push_back(factor_tex(f));
      }
    }
    const auto by_key = [](const std::string& x, const std::string& y) { return order_key(x) < order_key(y); };
    std::sort(num.begin(), num.end(), by_key);
    std::sort(den.begin(), den.end(), by_key);
    // A lone bracketed sum needs no brackets inside \frac{}{}.
    const auto unbracket = [](std::vector<std::string>& parts) {
      const std::string open = "\\left(", close = "\\right)";
      if (parts.size() == 1 && parts[0].rfind(open, 0) == 0 && parts[0].size() > open.size() + close.size() &&
          parts[0].compare(parts[0].size() - close.size(), close.size(), close) == 0 &&
          parts[0].find(open, open.size()) == std::string::npos)
        parts[0] = parts[0].substr(open.size(), parts[0].size() - open.size() - close.size());
    };
    const bool negative = c < 0;
    c = abs(c);
    const numeric cn = c.numer(), cd = c.denom();
    if (cn != 1 || num.empty()) num.insert(num.begin(), numeric_tex(cn));
    if (cd != 1) den.insert(den.begin(), numeric_tex(cd));
    if (den.empty()) return {negative, join(num, " ")};
    unbracket(num);
    unbracket(den);
    return {negative, "\\frac{" + join(num, " ") + "}{" + join(den, " ") + "}"};
  }
  if (is_a<power>(e) && is_a<numeric>(e.op(1))) {
    const numeric n = ex_to<numeric>(e.op(1));
    if (n < 0) return {false, "\\frac{1}{" + power_tex(e.op(0), -n) + "}"};
    return {false, power_tex(e.op(0), n)};
  }
  if (is_a<matrix>(e)) {
    const matrix& m = ex_to<matrix>(e);
    std::vector<std::string> rows;
    for (unsigned i = 0; i < m.rows(); ++i) {
      std::vector<std::string> cells;
      for (unsigned j = 0; j < m.cols(); ++j) cells.push_back(tex(m(i, j)));
      rows.push_back(join(cells, " & "));
    }
    return {false, "\\begin{pmatrix} " + join(rows, " \\\\ ") + " \\end{pmatrix}"};
  }
  std::ostringstream out;
  out << latex << e;
  return {false, out.str()};
}

// The sign rule for a normalised fraction must not depend on display order: the term whose text
// sorts last (ignoring its sign) is made positive in the denominator ("r - l", "t - b", "n - f").
bool last_term_negative(const ex& e) {
  if (!is_a<add>(e)) return term_tex(e).negative;
  const signed_tex* last = nullptr;
  std::vector<signed_tex> terms;
  for (const auto& t : e) terms.push_back(term_tex(t));
  for (const auto& t : terms)
    if (!last || order_key(t.body) > order_key(last->body)) last = &t;
  return last->negative;
}

// More negative than positive terms: print as minus a sum.
bool mostly_negative(const ex& e) {
  if (!is_a<add>(e)) return false;
  int balance = 0;
  for (const auto& t : e) balance += term_tex(t).negative ? 1 : -1;
  return balance > 0;
}

std::string tex_normal_scalar(const ex& e) {
  const ex nd = numer_denom(normal(e));
  ex num = expand(nd.op(0)), den = expand(nd.op(1));
  if (last_term_negative(den)) {
    num = expand(-num);
    den = expand(-den);
  }
  if (den == 1) return tex(num);
  bool minus = false;
  if (mostly_negative(num)) {
    num = expand(-num);
    minus = true;
  }
  const signed_tex n = term_tex(num);
  if (n.negative) minus = !minus;
  return (minus ? "-" : "") + std::string("\\frac{") + n.body + "}{" + term_tex(den).body + "}";
}

}  // namespace

std::string tex(const ex& e) {
  const signed_tex t = term_tex(e);
  return t.negative ? "-" + t.body : t.body;
}

std::string tex_normal(const ex& e) {
  if (!is_a<matrix>(e)) return tex_normal_scalar(e);
  const matrix& m = ex_to<matrix>(e);
  std::vector<std::string> rows;
  for (unsigned i = 0; i < m.rows(); ++i) {
    std::vector<std::string> cells;
    for (unsigned j = 0; j < m.cols(); ++j) cells.push_back(tex_normal_scalar(m(i, j)));
    rows.push_back(join(cells, " & "));
  }
  return "\\begin{pmatrix} " + join(rows, " \\\\ ") + " \\end{pmatrix}";
}

}  // namespace shadowproof::proofs
