// The checker must not be fooled: every way a step could pass without proving anything is fed to
// it and must be rejected with a message naming the step and the reason; true steps pass.
#include <iostream>
#include <string>

#include "checker.h"
#include "derivations.h"
#include "library.h"
#include "shadowproof/constructions/project.h"

namespace {

using namespace shadowproof::proofs;

int failures = 0;

void expect(bool condition, const std::string& what) {
  std::cout << (condition ? "ok: " : "FAILED: ") << what << '\n';
  if (!condition) ++failures;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Checks the last step of d; prints the message so the log shows what the checker said.
step_result last(const derivation& d) {
  const step_result r = check_step(d, d.steps.back());
  if (!r.ok) std::cout << "  message: " << r.message << '\n';
  return r;
}

bool rejected_for(const derivation& d, const std::string& reason) {
  const step_result r = last(d);
  return !r.ok && contains(r.message, "'" + d.steps.back().name + "'") && contains(r.message, reason);
}

}  // namespace

int main() {
  const term a = var("a", "a"), b = var("b", "b"), c = var("c", "c"), x = var("x", "x"), y = var("y", "y"),
             z = var("z", "z"), n = var("n", "n"), f = var("f", "f"), A = var("A", "A"), B = var("B", "B");

  // --- True steps pass, false ones are rejected with their residual -------------------------
  {
    derivation d;
    d.slug = "basics";
    d.show("square of a sum", "", power(a + b, 2), a * a + 2 * a * b + b * b);
    expect(last(d).ok, "a true step passes");
    d.show("square of a sum without the cross term", "", power(a + b, 2), a * a + b * b);
    expect(rejected_for(d, "does not hold") && contains(last(d).message, "2 a b"),
           "a false step is rejected, naming the step and the residual 2ab");
    const mat right{{n + f, -(n * f)}}, printed{{n * f, -(n * f)}};
    d.show("persp->ortho third row", "", right, printed);
    expect(rejected_for(d, "does not hold"), "a false matrix step (seed 004's nf for n + f) is rejected");
    d.show("a matrix against a scalar", "", right, a);
    expect(rejected_for(d, "compares a matrix with a scalar"), "a matrix is never equal to a scalar");
  }

  // --- Divisions are read as written, before GiNaC cancels anything --------------------------
  {
    derivation d;
    d.slug = "divisions";
    d.show("(a b)/a = b", "", (a * b) / a, b);
    expect(rejected_for(d, "divides by a, which the derivation does not declare non-zero"),
           "(a·b)/a = b is rejected while a ≠ 0 is not declared");
    d.show("b (a - c)/(a - c) = b", "", b * (a - c) / (a - c), b);
    expect(rejected_for(d, "divides by a - c"), "b(a−c)/(a−c) = b is rejected while a − c ≠ 0 is not declared");
    d.show("a division that cancels out of the sum", "", b + 1 / a - 1 / a, b);
    expect(rejected_for(d, "divides by a"), "b + 1/a − 1/a = b is rejected: the division is there as written");
    d.show("a division inside a product with zero", "", 0 * (1 / a) + b, b);
    expect(rejected_for(d, "divides by a"), "0·(1/a) + b = b is rejected: 1/a is undefined at a = 0");
    d.show("a division by something that is 0", "", x / (y - y), x / (y - y) + 1 - 1);
    expect(rejected_for(d, "which is 0"), "a division by y − y is rejected");
    d.show("a division by a literal 0", "", x / term(0), x / term(0));
    expect(!last(d).ok, "a division by the number 0 is rejected");
    d.show("(x^2 - 1)/(x - 1) = x + 1", "", (x * x - 1) / (x - 1), x + 1);
    expect(rejected_for(d, "divides by x - 1"), "cancelling a common factor needs it declared non-zero");

    // Seed 001's similar-triangles proportion: it divides by G_x − P_x = −L_x (P_y − h)/L_y.
    const term h = var("h", "h"), Lx = var("Lx", "L_x"), Ly = var("Ly", "L_y"), Px = var("Px", "P_x"),
               Py = var("Py", "P_y");
    const term Gx = Px - Lx * (Py - h) / Ly;
    derivation seed;
    seed.slug = "seed001 proportion";
    seed.assume_nonzero(Lx);
    seed.assume_nonzero(Ly);
    seed.show("-L_y/L_x = (P_y - h)/(G_x - P_x)", "", -Ly / Lx, (Py - h) / (Gx - Px));
    expect(rejected_for(seed, "divides by P_x - \\frac{L_x \\left(P_y - h\\right)}{L_y} - P_x"),
           "seed 001's proportion is rejected while P_y ≠ h is not declared");
    seed.assume_nonzero(Py - h);
    expect(last(seed).ok, "and passes once P_y − h ≠ 0 is a fact");

    derivation declared;
    declared.slug = "declared";
    declared.assume_nonzero(a);
    declared.assume_nonzero(a - c);
    declared.show("(a b)/a = b", "", (a * b) / a, b);
    expect(last(declared).ok, "(a·b)/a = b passes with a ≠ 0 declared");
    declared.show("b (a - c)/(a - c) = b", "", b * (a - c) / (a - c), b);
    expect(last(declared).ok, "b(a−c)/(a−c) = b passes with a − c ≠ 0 declared");
    declared.show("a divisor covered by a product of facts", "", (b * a * (a - c)) / (a * a - a * c), b);
    expect(last(declared).ok, "a divisor a² − ac is covered by the facts a ≠ 0 and a − c ≠ 0");
  }

  // --- Facts must be possible -----------------------------------------------------------------
  {
    derivation d;
    d.slug = "false fact";
    d.assume_nonzero(x - x);
    d.show("x x / x = x", "", x * x / x, x);
    const derivation_result r = check(d);
    expect(!r.ok && contains(r.message, "false fact"), "declaring x − x ≠ 0 is rejected");
    derivation e;
    e.slug = "contradiction";
    e.assume_positive(a);
    e.assume_negative(2 * a);
    const derivation_result r2 = check(e);
    expect(!r2.ok && contains(r2.message, "contradictory facts"), "declaring a > 0 and 2a < 0 is rejected");
  }

  // --- Steps whose two sides are the same expression before normalisation -------------------
  {
    derivation d;
    d.slug = "vacuous";
    d.assume_nonzero(n);
    d.assume_nonzero(z);
    const std::string reason = "same expression before normalisation";
    d.show("x = x", "", x, x);
    expect(rejected_for(d, reason), "x = x is rejected");
    d.show("1 = 1", "", term(1), term(1));
    expect(rejected_for(d, reason), "1 = 1 (perspective_normalisation's old step 2) is rejected");
    d.show("x + x = 2 x", "", x + x, 2 * x);
    expect(rejected_for(d, reason), "a step GiNaC decides while building (x + x = 2x) is rejected");
    // GAMES101's old steps 1-2: the third coordinate of M (x, y, n, 1) with row 3 (0, 0, A, B).
    const mat M{{n, 0, 0, 0}, {0, n, 0, 0}, {0, 0, A, B}, {0, 0, 1, 0}};
    d.show("near plane: the third coordinate", "", (M * column(x, y, n, 1)).entry(2), A * n + B);
    expect(rejected_for(d, reason), "GAMES101's 'the third coordinate is An + B' is rejected as a step");
    d.define("near plane: the third coordinate", "", (M * column(x, y, n, 1)).entry(2), A * n + B);
    expect(last(d).ok, "and accepted when marked as a definition");
    // Seed 003's old "Q is r(t0)": both sides built from the same t0.
    const term t0 = -(a + b) / c;
    const mat L = column(x, y, z), V = column(a, b, c);
    d.assume_nonzero(c);
    d.show("Q is r(t0), built from the same pieces", "", L + t0 * (V - L), L + t0 * (V - L));
    expect(rejected_for(d, reason), "seed 003's old 'Q is r(t0)' (both sides the same expression) is rejected");
    d.show("a cancellation through a division is not 'the same expression'", "", (n * z) / n, z);
    expect(last(d).ok, "(n z)/n = z with n ≠ 0 is a real step (divisions stay opaque when comparing)");
    // Orthographic's old step 6, z/((x + z cot θ) − x) = 1/cot θ: a cancellation through a
    // division, so it needs z ≠ 0 and cot θ ≠ 0 declared.
    const term ct = var("ct", "\\cot\\theta");
    derivation o;
    o.slug = "oblique angle";
    o.show("tan theta", "", z / ((x + z * ct) - x), 1 / ct);
    expect(rejected_for(o, "divides by"), "orthographic's old 'z/(x_p − x) = 1/cot θ' is rejected without its facts");
    o.assume_nonzero(z);
    o.assume_nonzero(ct);
    expect(last(o).ok, "and holds once z ≠ 0 and cot θ ≠ 0 are facts");
    // Perspective's old step 2, x/w = (−z)/(−z) = 1 on the side x = −z of the frustum.
    derivation p;
    p.slug = "frustum side";
    p.show("x/w on the side x = -z", "", (-z) / (-z), 1);
    expect(rejected_for(p, "divides by -z"), "perspective's old '(−z)/(−z) = 1' is rejected without z ≠ 0");
    // Seed 003's old "corrected t": <N, L> + t0 <N, V - L> + d = 0 for t0 = -(<N, L> + d)/<N, V - L>
    // (here a, c, b): GiNaC used to cancel <N, V - L> on sight; read as written it is a real step
    // that needs <N, V - L> != 0.
    derivation t;
    t.slug = "corrected t";
    t.show("the plane equation at t0", "", a + (-(a + b) / c) * c + b, 0);
    expect(rejected_for(t, "divides by c"), "seed 003's old 'corrected t' is rejected without <N, V - L> ≠ 0");
    t.assume_nonzero(c);
    expect(last(t).ok, "and holds once <N, V - L> ≠ 0 is a fact");
    d.define("a definition that does not hold", "", x, y);
    expect(rejected_for(d, "does not hold"), "a definition must still hold");
  }

  // --- The printed formula is the checked one ------------------------------------------------
  {
    const mat P = mat::named("P", column(a, b, c, x)), L = mat::named("L", column(n, f, y, z));
    const term PL = dot(P, L);
    expect(side(PL).tex() == "P \\cdot L", "a dot product prints from its operands: P \\cdot L");
    const mat M = mat::named("M", PL * identity(4) - L * transpose(P));
    expect(side(M * L).tex() == "M L", "a product prints from its factors: M L");
    expect(side(PL * identity(4) - L * transpose(P)).tex() == "\\left(P \\cdot L\\right) I - L P^{\\mathsf T}",
           "the shadow matrix prints as (P·L) I − L Pᵀ, generated from the expression");
    expect(side(-(a * b) / (a - c)).tex() == "\\frac{-a b}{a - c}", "a quotient prints as written");
    derivation d;
    d.slug = "printed";
    d.show("G appears", "", M * L, mat(4, 1));
    expect(side(d.steps.back().lhs).tex() == "M L" && last(d).ok, "a step prints what it checks (M L = 0)");
  }

  // --- Refutations must really refute --------------------------------------------------------
  {
    derivation d;
    d.slug = "refutations";
    d.assume_nonzero(b);
    d.refute("refuting a true step", "", "no matrix", power(a + b, 2), a * a + 2 * a * b + b * b, {{a, 1}, {b, 1}});
    expect(rejected_for(d, "holds identically"), "a true step cannot be refuted");
    d.refute("a counterexample on the zero set", "", "no matrix", power(a + b, 2), a * a + b * b, {{a, 0}, {b, 1}});
    expect(rejected_for(d, "refutes nothing"), "a counterexample where the residual vanishes is rejected");
    d.refute("a counterexample breaking a fact", "", "no matrix", power(a + b, 2), a * a + b * b, {{a, 1}, {b, 0}});
    expect(rejected_for(d, "b \\neq 0"), "a counterexample violating a fact is rejected");
    d.refute("a counterexample with a stray symbol", "", "no matrix", power(a + b, 2), a * a + b * b,
             {{a, 1}, {b, 1}, {n, 1}});
    expect(rejected_for(d, "does not use"), "a counterexample setting an unused symbol is rejected");
    d.refute("a counterexample leaving a symbol", "", "no matrix", power(a + b, 2), a * a + b * b, {{b, 1}});
    expect(rejected_for(d, "leaves symbols"), "a counterexample must fix the residual");
    d.refute("a counterexample breaking a premise", "", "no matrix", power(a + b, 2), a * a + b * b, {{a, 1}, {b, 1}});
    d.under({{a, negative}});
    expect(rejected_for(d, "premise"), "a counterexample violating the step's premise is rejected");
    d.refute("a counterexample dividing by zero", "", "no matrix", a / (a - 1), a, {{a, 1}, {b, 1}});
    d.under({{a - 1, nonzero}});
    expect(!last(d).ok, "a counterexample may not make a divisor zero");
    d.refute("a good counterexample", "", "no matrix", power(a + b, 2), a * a + b * b, {{a, 1}, {b, 1}});
    const step_result good = last(d);
    expect(good.ok && good.residual_tex == "2", "a real refutation passes with the residual 2 at (1, 1)");
  }

  // --- Sign claims and the comparisons of the library's templates -----------------------------
  {
    derivation d;
    d.slug = "signs";
    d.sign("a claim that follows", "", {{a, positive}, {b, negative}}, {{a * b, negative}, {a / b, negative}});
    expect(last(d).ok, "a > 0, b < 0 give ab < 0 and a/b < 0");
    d.sign("a claim that does not follow", "", {{a, positive}}, {{a + b, positive}});
    expect(rejected_for(d, "do not show"), "a > 0 does not give a + b > 0");
    d.sign("a claim of nothing", "", {{a, positive}}, {});
    expect(rejected_for(d, "claims nothing"), "a sign step must claim something");

    // A comparison the facts do not decide stops the instantiation instead of guessing.
    bool threw = false;
    try {
      const auto decide = comparisons_from({});
      const shadowproof::proofs::scoped_comparisons installed(*decide);
      (void)shadowproof::frustum(-n, n, -n, n, n, f, shadowproof::depth_convention::gl);
    } catch (const std::exception& e) {
      threw = contains(e.what(), "do not decide");
      std::cout << "  message: " << e.what() << '\n';
    }
    expect(threw, "frustum<term> without the fact n > 0 throws instead of guessing the comparison");
    bool no_context = false;
    try {
      (void)(n < f);
    } catch (const std::exception&) {
      no_context = true;
    }
    expect(no_context, "comparing terms without a proof context throws");
  }

  // --- A real derivation with one sign flipped ---------------------------------------------------
  {
    derivation seed002 = seed002_point_light_ground();
    bool found = false;
    for (auto& s : seed002.steps) {
      if (s.name.find("up to the scale") == std::string::npos) continue;
      found = true;
      expect(check_step(seed002, s).ok, "the real seed 002 scale step holds");
      s.rhs = side(term(-1) * s.rhs.matrix());
      const step_result flipped = check_step(seed002, s);
      expect(!flipped.ok && contains(flipped.message, s.name), "the same step with the sign flipped is rejected");
    }
    expect(found, "seed 002 has its scale step");
  }

  if (failures) std::cerr << failures << " check(s) failed\n";
  return failures ? 1 : 0;
}
