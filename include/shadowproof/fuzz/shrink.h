#pragma once
/// Shrinking a failing input to a minimal reproducer that still fails the same way.
#include <cstddef>
#include <functional>
#include <vector>

namespace shadowproof {

/// Size of an input as the sum, over its numbers, of the bits of the exact rational's numerator
/// and denominator (0 counts 0 bits, 1 counts 2). A reproducer with fewer bits is simpler.
std::size_t input_bits(const std::vector<double>& inputs);

struct shrink_result {
  std::vector<double> inputs;
  std::size_t bits_before = 0, bits_after = 0;
  std::size_t evaluations = 0;  ///< calls of the predicate
};

/// Greedy shrinking: repeatedly replaces one number by a simpler one and keeps the change when
/// `still_fails` holds. Candidates for x, simplest first: 0; small integers ±1..±16 (x's sign
/// first); powers of two between 1 and |x|; x rounded to 1, 2, 3, ... significant bits. Only
/// candidates with fewer bits than x that are exactly representable in the input format
/// (`single_precision`: float, else double) are tried. Stops when a full pass changes nothing
/// or after `max_evaluations` predicate calls. `keep[i]` pins input i (e.g. a light's w that a
/// convention fixes). Deterministic.
shrink_result shrink_inputs(const std::vector<double>& inputs, bool single_precision,
                            const std::function<bool(const std::vector<double>&)>& still_fails,
                            const std::vector<bool>& keep = {}, std::size_t max_evaluations = 20000);

}  // namespace shadowproof
