// The checker must be able to fail: deliberately wrong steps are rejected with a message that
// names the step and a residual that is not zero.
#include <iostream>
#include <string>

#include "checker.h"
#include "derivations.h"
#include "notation.h"

namespace {

using namespace shadowproof::proofs;
using GiNaC::ex;

int failures = 0;

void expect(bool condition, const std::string& what) {
  if (!condition) {
    std::cerr << "FAILED: " << what << '\n';
    ++failures;
  } else {
    std::cout << "ok: " << what << '\n';
  }
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

matrix ex_to_matrix(const ex& e) { return GiNaC::ex_to<matrix>(e); }

}  // namespace

int main() {
  const auto a = symbol("a", "a"), b = symbol("b", "b"), n = symbol("n", "n"), f = symbol("f", "f");

  derivation d;
  d.slug = "checker_self_test";
  d.assume(b, "b \\neq 0");

  // A true step passes.
  d.show("square of a sum", "Expand.", GiNaC::pow(a + b, 2), a * a + 2 * a * b + b * b);
  const step_result good = check_step(d, d.steps.back());
  expect(good.ok && good.message.empty(), "a true step passes");

  // A false step (the classic missing cross term) is rejected; the message names the step and
  // the residual is exactly the missing 2ab.
  d.show("square of a sum without the cross term", "Wrong on purpose.", GiNaC::pow(a + b, 2), a * a + b * b);
  const step_result bad = check_step(d, d.steps.back());
  expect(!bad.ok, "a false step is rejected");
  expect(contains(bad.message, "square of a sum without the cross term"), "the rejection names the step");
  expect(contains(bad.message, "does not hold"), "the rejection says the step does not hold");
  expect((bad.residual - 2 * a * b).expand().is_zero(), "the residual is lhs - rhs = 2ab");
  std::cout << "  message: " << bad.message << '\n';

  // A false matrix step: one wrong entry (seed 004's third row, nf in place of n + f).
  const matrix right{{n + f, -n * f}}, printed{{n * f, -n * f}};
  d.show("persp->ortho third row", "Wrong on purpose.", right, printed);
  const step_result bad_matrix = check_step(d, d.steps.back());
  expect(!bad_matrix.ok, "a false matrix step is rejected");
  expect(contains(bad_matrix.message, "persp->ortho third row"), "the matrix rejection names the step");
  expect(GiNaC::is_a<matrix>(bad_matrix.residual) &&
             (GiNaC::ex_to<matrix>(bad_matrix.residual)(0, 0) - (n + f - n * f)).expand().is_zero() &&
             GiNaC::ex_to<matrix>(bad_matrix.residual)(0, 1).is_zero(),
         "the matrix residual is (n + f - nf, 0)");

  // Dividing by something that is not assumed non-zero is rejected even when the identity holds.
  d.show("cancel a", "a is not assumed non-zero.", (a * b + a) / a, b + 1);
  const step_result undeclared = check_step(d, d.steps.back());
  expect(!undeclared.ok && contains(undeclared.message, "not among the assumptions"),
         "a division by an undeclared expression is rejected");
  d.show("cancel b", "b is assumed non-zero.", (a * b + b) / b, a + 1);
  expect(check_step(d, d.steps.back()).ok, "a division by a declared expression passes");

  // A refutation must really refute: a true equation cannot be "refuted" ...
  d.refute("refuting a true step", "Wrong on purpose.", GiNaC::pow(a + b, 2), a * a + 2 * a * b + b * b,
           {{a, 1}, {b, 1}});
  const step_result not_refuted = check_step(d, d.steps.back());
  expect(!not_refuted.ok && contains(not_refuted.message, "holds identically"),
         "a true step cannot be refuted");
  // ... a counterexample where the residual vanishes refutes nothing ...
  d.refute("a counterexample on the zero set", "Wrong on purpose.", GiNaC::pow(a + b, 2), a * a + b * b,
           {{a, 0}, {b, 1}});
  const step_result weak = check_step(d, d.steps.back());
  expect(!weak.ok && contains(weak.message, "refutes nothing"), "a counterexample with zero residual is rejected");
  // ... a counterexample may not break an assumption ...
  d.refute("a counterexample breaking an assumption", "Wrong on purpose.", GiNaC::pow(a + b, 2),
           a * a + b * b, {{a, 1}, {b, 0}});
  const step_result breaks = check_step(d, d.steps.back());
  expect(!breaks.ok && contains(breaks.message, "b \\neq 0"), "a counterexample violating an assumption is rejected");
  // ... and a good one is accepted with its non-zero residual.
  d.refute("a good counterexample", "The cross term is missing.", GiNaC::pow(a + b, 2), a * a + b * b,
           {{a, 1}, {b, 1}});
  const step_result refuted = check_step(d, d.steps.back());
  expect(refuted.ok && refuted.counterexample_residual == 2, "a real refutation passes with residual 2");

  // ... and it may only set symbols the step uses.
  d.refute("a counterexample with a stray symbol", "Wrong on purpose.", GiNaC::pow(a + b, 2), a * a + b * b,
           {{a, 1}, {b, 1}, {n, 1}});
  const step_result stray = check_step(d, d.steps.back());
  expect(!stray.ok && contains(stray.message, "does not use"), "a counterexample setting an unused symbol is rejected");

  // A real derivation with one sign flipped: seed 002's T(l) N T(-l) is +1/y_l times the shadow
  // matrix; claiming -1/y_l must be rejected with a non-zero residual.
  derivation seed002 = seed002_point_light_ground();
  bool found = false;
  for (auto& s : seed002.steps) {
    if (s.name.find("up to the scale") == std::string::npos) continue;
    found = true;
    expect(check_step(seed002, s).ok, "the real seed 002 scale step holds");
    s.rhs = side(ex_to_matrix(s.rhs.value).mul_scalar(-1), "-" + s.rhs.tex);
    const step_result flipped = check_step(seed002, s);
    expect(!flipped.ok && contains(flipped.message, s.name), "the same step with the sign flipped is rejected");
    expect(!flipped.residual.is_zero() && GiNaC::is_a<matrix>(flipped.residual) &&
               !GiNaC::ex_to<matrix>(flipped.residual)(0, 0).is_zero(),
           "its residual is a non-zero matrix");
    std::cout << "  message: " << flipped.message << '\n';
  }
  expect(found, "seed 002 has its scale step");

  // check() reports the derivation as failed when any step fails.
  expect(!check(d).ok, "a derivation with a false step fails as a whole");

  if (failures) std::cerr << failures << " check(s) failed\n";
  return failures ? 1 : 0;
}
