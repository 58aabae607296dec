// Shrinking failing inputs to minimal reproducers.
#include <catch2/catch.hpp>

#include <cmath>

#include "shadowproof/fuzz/shrink.h"

using namespace shadowproof;

TEST_CASE("input bits count numerator and denominator bits of the exact values", "[shrink]") {
  CHECK(input_bits({0.0}) == 0);
  CHECK(input_bits({1.0}) == 2);           // 1/1
  CHECK(input_bits({0.5}) == 3);           // 1/2: 1 + 2 bits
  CHECK(input_bits({3.0, -0.75}) == 3 + 5); // 3/1: 2 + 1; 3/4: 2 + 3
}

TEST_CASE("a predicate true everywhere shrinks every input to zero", "[shrink]") {
  const auto r = shrink_inputs({0.1, -123456.789, 1e-30}, false, [](const std::vector<double>&) { return true; });
  CHECK(r.inputs == std::vector<double>{0, 0, 0});
  CHECK(r.bits_after == 0);
  CHECK(r.bits_before > 100);
}

TEST_CASE("shrinking keeps the failure and stops at a fixed point", "[shrink]") {
  // Fails when x·y > 1000 with x and y positive.
  auto fails = [](const std::vector<double>& v) { return v[0] > 0 && v[1] > 0 && v[0] * v[1] > 1000; };
  const auto r = shrink_inputs({123.456789, 98.7654321}, false, fails);
  CHECK(fails(r.inputs));
  CHECK(r.bits_after < r.bits_before);
  for (double x : r.inputs) CHECK(x == std::round(x));  // reduced to integers
  // Shrinking the result again changes nothing: no single simpler candidate still fails.
  const auto again = shrink_inputs(r.inputs, false, fails);
  CHECK(again.inputs == r.inputs);
  // In particular no small integer (the first candidates) works in place of either factor.
  for (std::size_t i = 0; i < 2; ++i)
    for (int k = 1; k <= 16; ++k) {
      auto trial = r.inputs;
      trial[i] = k;
      if (input_bits({double(k)}) < input_bits({r.inputs[i]})) CHECK_FALSE(fails(trial));
    }
}

TEST_CASE("pinned inputs are never changed and float inputs stay floats", "[shrink]") {
  const auto r = shrink_inputs({0.1f, 0.3f}, true, [](const std::vector<double>&) { return true; }, {true, false});
  CHECK(r.inputs[0] == static_cast<double>(0.1f));
  CHECK(r.inputs[1] == 0);
  auto near_tenth = [](const std::vector<double>& v) { return v[0] > 0.099 && v[0] < 0.101; };
  const auto f = shrink_inputs({static_cast<double>(0.1f)}, true, near_tenth);
  CHECK(static_cast<double>(static_cast<float>(f.inputs[0])) == f.inputs[0]);
  CHECK(near_tenth(f.inputs));
  CHECK(f.bits_after < f.bits_before);
}

TEST_CASE("the evaluation budget bounds the work", "[shrink]") {
  std::size_t calls = 0;
  const auto r = shrink_inputs({1e300, 3e-300, 7.77}, false, [&](const std::vector<double>&) { ++calls; return false; }, {}, 50);
  CHECK(calls == 50);
  CHECK(r.evaluations == 50);
  CHECK(r.bits_after == r.bits_before);
}
