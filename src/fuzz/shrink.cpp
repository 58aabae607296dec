#include "shadowproof/fuzz/shrink.h"

#include <cmath>
#include <limits>

#include "shadowproof/core/number.h"

namespace shadowproof {
namespace {

std::size_t bits_of(double x) {
  if (x == 0) return 0;
  const rational q = exact_value(x);
  return mpz_sizeinbase(q.get_num_mpz_t(), 2) + mpz_sizeinbase(q.get_den_mpz_t(), 2);
}

bool representable(double x, bool single_precision) {
  return single_precision ? representable_in_float(x) : std::isfinite(x);
}

// x rounded to `bits` significant bits, to nearest (ties away from zero are fine here: any
// simpler value is a candidate; the predicate decides).
double round_to_bits(double x, int bits) {
  int e = 0;
  const double m = std::frexp(x, &e);  // x = m · 2^e, 1/2 ≤ |m| < 1
  return std::ldexp(std::round(std::ldexp(m, bits)), e - bits);
}

std::vector<double> candidates(double x) {
  std::vector<double> c{0.0};
  const double sign = std::signbit(x) ? -1.0 : 1.0;
  for (int k = 1; k <= 16; ++k) {
    c.push_back(sign * k);
    c.push_back(-sign * k);
  }
  if (x != 0 && std::isfinite(x)) {
    int e = 0;
    std::frexp(x, &e);  // 2^(e-1) ≤ |x| < 2^e
    const int top = e - 1;
    for (int p = 0; p != top; p += (top > 0 ? 1 : -1)) c.push_back(sign * std::ldexp(1.0, p));
    c.push_back(sign * std::ldexp(1.0, top));
    for (int bits = 1; bits < 53; ++bits) c.push_back(round_to_bits(x, bits));
  }
  return c;
}

}  // namespace

std::size_t input_bits(const std::vector<double>& inputs) {
  std::size_t total = 0;
  for (double x : inputs) total += bits_of(x);
  return total;
}

shrink_result shrink_inputs(const std::vector<double>& inputs, bool single_precision,
                            const std::function<bool(const std::vector<double>&)>& still_fails,
                            const std::vector<bool>& keep, std::size_t max_evaluations) {
  shrink_result r;
  r.inputs = inputs;
  r.bits_before = input_bits(inputs);
  bool changed = true;
  while (changed && r.evaluations < max_evaluations) {
    changed = false;
    for (std::size_t i = 0; i < r.inputs.size() && r.evaluations < max_evaluations; ++i) {
      if (i < keep.size() && keep[i]) continue;
      const double current = r.inputs[i];
      const std::size_t current_bits = bits_of(current);
      for (double candidate : candidates(current)) {
        if (r.evaluations >= max_evaluations) break;
        if (!representable(candidate, single_precision) || bits_of(candidate) >= current_bits) continue;
        std::vector<double> trial = r.inputs;
        trial[i] = candidate;
        ++r.evaluations;
        if (still_fails(trial)) {
          r.inputs = std::move(trial);
          changed = true;
          break;  // candidates are simplest first: the first that still fails is kept
        }
      }
    }
  }
  r.bits_after = input_bits(r.inputs);
  return r;
}

}  // namespace shadowproof
