#include "checker.h"

#include <sstream>

#include "notation.h"

namespace shadowproof::proofs {

using namespace GiNaC;

void derivation::assume(const ex& e, std::string tex_text) {
  assumptions.push_back({e, std::move(tex_text)});
}

void derivation::show(std::string name, std::string why, side lhs, side rhs) {
  steps.push_back({std::move(name), std::move(why), std::move(lhs), std::move(rhs), claim::holds, {}});
}

void derivation::refute(std::string name, std::string why, side lhs, side rhs, exmap counterexample) {
  steps.push_back({std::move(name), std::move(why), std::move(lhs), std::move(rhs), claim::fails,
                   std::move(counterexample), true});
}

void derivation::disprove(std::string name, std::string why, side lhs, side rhs, exmap counterexample) {
  steps.push_back({std::move(name), std::move(why), std::move(lhs), std::move(rhs), claim::fails,
                   std::move(counterexample), false});
}

namespace {

std::string text(const ex& e) {
  std::ostringstream out;
  out << dflt << e;
  return out.str();
}

std::vector<ex> entries(const ex& e) {
  if (!is_a<matrix>(e)) return {e};
  std::vector<ex> r;
  const matrix& m = ex_to<matrix>(e);
  for (unsigned i = 0; i < m.rows(); ++i)
    for (unsigned j = 0; j < m.cols(); ++j) r.push_back(m(i, j));
  return r;
}

bool is_zero_everywhere(const ex& residual) {
  for (const auto& x : entries(residual))
    if (!x.is_zero()) return false;
  return true;
}

// Divides `den` by the assumptions as long as one divides it exactly; what is left must be a
// constant. Returns the uncovered remainder (1 when covered).
ex uncovered_part(ex den, const std::vector<assumption>& assumptions) {
  den = expand(den);
  bool progress = true;
  while (progress && !is_a<numeric>(den)) {
    progress = false;
    for (const auto& a : assumptions) {
      const ex divisor = expand(numer(normal(a.nonzero)));
      if (is_a<numeric>(divisor)) continue;
      ex q;
      if (divide(den, divisor, q)) {
        den = expand(q);
        progress = true;
        if (is_a<numeric>(den)) break;
      }
    }
  }
  return is_a<numeric>(den) ? ex(1) : den;
}

// Every expression the step divides by, as written (before any cancellation): the base of each
// negative power in the expression tree.
void collect_divisors(const ex& e, std::vector<ex>& out) {
  if (is_a<power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)) < 0 &&
      !is_a<numeric>(e.op(0)))
    out.push_back(e.op(0));
  for (std::size_t i = 0; i < e.nops(); ++i) collect_divisors(e.op(i), out);
}

void collect_symbols(const ex& e, exset& out) {
  if (is_a<GiNaC::symbol>(e)) out.insert(e);
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), out);
}

bool shares_symbol(const ex& e, const exset& symbols) {
  exset own;
  collect_symbols(e, own);
  for (const auto& s : own)
    if (symbols.count(s)) return true;
  return false;
}

}  // namespace

step_result check_step(const derivation& d, const step& s) {
  step_result r;
  const std::string who = "step '" + s.name + "' of '" + d.slug + "'";
  const ex& lhs = s.lhs.value;
  const ex& rhs = s.rhs.value;
  const bool lm = is_a<matrix>(lhs), rm = is_a<matrix>(rhs);
  if (lm != rm) {
    r.message = who + " compares a matrix with a scalar";
    return r;
  }
  if (lm) {
    const matrix &a = ex_to<matrix>(lhs), &b = ex_to<matrix>(rhs);
    if (a.rows() != b.rows() || a.cols() != b.cols()) {
      r.message = who + " compares matrices of different shapes";
      return r;
    }
    r.residual = normalised(a.sub(b));
  } else {
    r.residual = normal(lhs - rhs);
  }

  // Every denominator the two sides have must be one the derivation declared non-zero.
  std::vector<ex> denominators;
  collect_divisors(lhs, denominators);
  collect_divisors(rhs, denominators);
  for (const auto& den : denominators) {
    const ex left = uncovered_part(numer(normal(den)), d.assumptions);
    if (left != 1) {
      r.message = who + " divides by " + text(left) + ", which is not among the assumptions";
      return r;
    }
  }

  if (s.kind == claim::holds) {
    if (!is_zero_everywhere(r.residual)) {
      r.message = who + " does not hold: lhs - rhs = " + text(r.residual) + ", not 0";
      return r;
    }
    r.ok = true;
    return r;
  }

  // claim::fails: false in general, and false at the stated counterexample.
  if (is_zero_everywhere(r.residual)) {
    r.message = who + " is stated to be wrong, but it holds identically";
    return r;
  }
  if (s.counterexample.empty()) {
    r.message = who + " is stated to be wrong but gives no counterexample";
    return r;
  }
  exset step_symbols;
  collect_symbols(lhs, step_symbols);
  collect_symbols(rhs, step_symbols);
  for (const auto& [symbol, value] : s.counterexample) {
    if (!step_symbols.count(symbol)) {
      r.message = who + ": the counterexample sets " + text(symbol) + ", which the step does not use";
      return r;
    }
  }
  for (const auto& a : d.assumptions) {
    if (!shares_symbol(a.nonzero, step_symbols)) continue;  // about other symbols of the derivation
    const ex v = normal(a.nonzero.subs(s.counterexample));
    if (!is_a<numeric>(v) || v.is_zero()) {
      r.message = who + ": the counterexample violates or does not fix the assumption " + a.tex +
                  " (it gives " + text(v) + ")";
      return r;
    }
  }
  for (const auto& den : denominators) {
    const ex v = normal(den.subs(s.counterexample));
    if (!is_a<numeric>(v) || v.is_zero()) {
      r.message = who + ": the counterexample makes the denominator " + text(den) + " equal " + text(v);
      return r;
    }
  }
  ex at_point = r.residual.subs(s.counterexample);
  if (is_a<matrix>(at_point)) at_point = normalised(ex_to<matrix>(at_point));
  else at_point = normal(at_point);
  for (const auto& x : entries(at_point)) {
    if (!is_a<numeric>(x)) {
      r.message = who + ": the counterexample leaves symbols in the residual " + text(at_point);
      return r;
    }
  }
  if (is_zero_everywhere(at_point)) {
    r.message = who + ": the residual vanishes at the counterexample, so it refutes nothing";
    return r;
  }
  r.counterexample_residual = at_point;
  r.ok = true;
  return r;
}

derivation_result check(const derivation& d) {
  derivation_result r;
  for (const auto& s : d.steps) {
    r.steps.push_back(check_step(d, s));
    if (!r.steps.back().ok) r.ok = false;
  }
  return r;
}

}  // namespace shadowproof::proofs
