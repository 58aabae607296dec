// The filtered oracle's dedicated kernels (src/verify/oracle_fast.h, src/verify/kernels/):
// the error-free transformations' defining properties, checked exactly with rationals on the
// instances compiled into the library; correct rounding of exact quotients, ties included; and
// every kernel against the all-rational reference, output by output, for every operation,
// type, class and convention, with the filter and with exact expansions alone.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "../src/verify/kernels/error_free.h"
#include "../src/verify/kernels/exact_rounding.h"
#include "../src/verify/operation_table.h"
#include "shadowproof/core/number.h"
#include "shadowproof/core/ulp.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/grade.h"
#include "shadowproof/verify/protocol.h"

using namespace shadowproof;

namespace {

// Doubles with random signs, 53-bit significands and exponents in [emin, emax].
struct random_doubles {
  std::mt19937_64 rng;
  explicit random_doubles(std::uint64_t seed) : rng(seed) {}
  double operator()(int emin, int emax) {
    const double m = static_cast<double>(rng() >> 11) * 0x1p-53 + 0.5;  // [0.5, 1)
    const int e = emin + static_cast<int>(rng() % static_cast<std::uint64_t>(emax - emin + 1));
    const double v = std::ldexp(m, e);
    return (rng() & 1) ? -v : v;
  }
  // Often a neighbour of the other operand, so that sums cancel and products round at ties.
  double near(double x) {
    switch (rng() % 4) {
      case 0: return -x;
      case 1: return -std::nextafter(x, 0.0);
      case 2: return std::ldexp(x, -static_cast<int>(rng() % 60));
      default: return (*this)(-60, 60);
    }
  }
};

// Significant bits of x: the length of its odd integer significand.
int significant_bits(double x) {
  if (x == 0) return 0;
  int e;
  double m = std::frexp(std::fabs(x), &e);
  std::uint64_t n = static_cast<std::uint64_t>(std::ldexp(m, 53));
  while ((n & 1) == 0) n >>= 1;
  int bits = 0;
  while (n) {
    ++bits;
    n >>= 1;
  }
  return bits;
}

}  // namespace

// ----------------------------------------------------------------------------------------------
// Error-free transformations, as compiled into the library.

TEST_CASE("TwoSum: s is the rounded sum and s + e is the exact sum", "[kernels][error-free]") {
  random_doubles r(1);
  for (int i = 0; i < 20000; ++i) {
    const double a = r(-300, 300);
    const double b = (i % 2) ? r.near(a) : r(-300, 300);
    double s, e;
    detail::compiled::two_sum(a, b, s, e);
    INFO("a = " << hex_string(a) << ", b = " << hex_string(b));
    REQUIRE(s == a + b);
    REQUIRE(exact_value(s) + exact_value(e) == exact_value(a) + exact_value(b));
  }
}

TEST_CASE("Veltkamp's split: hi + lo is x exactly, hi and lo with at most 26 significant bits", "[kernels][error-free]") {
  random_doubles r(2);
  for (int i = 0; i < 20000; ++i) {
    const double x = r(-900, 900);
    double hi, lo;
    detail::compiled::split(x, hi, lo);
    INFO("x = " << hex_string(x) << ", hi = " << hex_string(hi) << ", lo = " << hex_string(lo));
    REQUIRE(exact_value(hi) + exact_value(lo) == exact_value(x));
    REQUIRE(significant_bits(hi) <= 26);
    REQUIRE(significant_bits(lo) <= 26);
  }
}

TEST_CASE("TwoProduct: p is the rounded product and p + e is the exact product", "[kernels][error-free]") {
  random_doubles r(3);
  for (int i = 0; i < 20000; ++i) {
    const double a = r(-400, 400), b = r(-400, 400);
    const rational exact = exact_value(a) * exact_value(b);
    INFO("a = " << hex_string(a) << ", b = " << hex_string(b));
    double p, e;
    detail::compiled::two_product(a, b, p, e);
    REQUIRE(p == a * b);
    REQUIRE(exact_value(p) + exact_value(e) == exact);
    detail::compiled::two_product_dekker(a, b, p, e);
    REQUIRE(p == a * b);
    REQUIRE(exact_value(p) + exact_value(e) == exact);
  }
}

TEST_CASE("an expansion is nonoverlapping, increasing and sums exactly to its terms", "[kernels][error-free]") {
  random_doubles r(4);
  for (int i = 0; i < 2000; ++i) {
    double terms[12];
    rational sum = 0;
    for (int k = 0; k < 12; ++k) {
      terms[k] = k > 0 && (r.rng() & 1) ? r.near(terms[k - 1]) : r(-200, 200);
      sum += exact_value(terms[k]);
    }
    double e[13];
    const int m = detail::compiled::expansion_of(terms, 12, e);
    rational total = 0;
    for (int k = 0; k < m; ++k) {
      REQUIRE(e[k] != 0);
      total += exact_value(e[k]);
      // Nonoverlapping and increasing: |e[k]| is below the lowest set bit of e[k+1].
      if (k + 1 < m) {
        int exponent;
        std::frexp(e[k + 1], &exponent);
        const double lowest = std::ldexp(1.0, exponent - significant_bits(e[k + 1]));
        REQUIRE(std::fabs(e[k]) < lowest);
      }
    }
    REQUIRE(total == sum);
  }
}

// ----------------------------------------------------------------------------------------------
// Correct rounding of exact quotients.

namespace {

detail::expansion expansion_of(const rational& q) {
  // q = n / 2^k with n an integer below 2^200: summed from 50-bit chunks of n.
  detail::expansion x;
  rational rest = q;
  for (int chunk = 0; chunk < 8 && rest != 0; ++chunk) {
    const double part = to_nearest_double(rest);
    x.add(part);
    rest -= exact_value(part);
  }
  REQUIRE(rest == 0);
  return x;
}

template <class F>
double rounded(const rational& num, const rational& den) {
  double out = -1;
  REQUIRE(detail::round_exact_quotient<F>(expansion_of(num), expansion_of(den), out));
  return out;
}

template <class F>
double rounded_value(const rational& x) {
  double out = -1;
  REQUIRE(detail::round_exact_value<F>(expansion_of(x), out));
  return out;
}

}  // namespace

TEST_CASE("exact sums at a tie round to even", "[kernels][rounding]") {
  const rational two24 = exact_value(0x1p24), two53 = exact_value(0x1p53);
  CHECK(rounded_value<float>(two24 + 1) == 0x1p24);
  CHECK(rounded_value<float>(two24 + 3) == 0x1p24 + 4);
  CHECK(rounded_value<float>(-(two24 + 3)) == -(0x1p24 + 4));
  CHECK(rounded_value<float>(two24 + 1 + exact_value(0x1p-80)) == 0x1p24 + 2);
  CHECK(rounded_value<float>(two24 + 1 - exact_value(0x1p-80)) == 0x1p24);
  CHECK(rounded_value<double>(two53 + 1) == 0x1p53);
  CHECK(rounded_value<double>(two53 + 3) == 0x1p53 + 4);
  CHECK(rounded_value<double>(two53 + 1 + exact_value(0x1p-200)) == 0x1p53 + 2);
  CHECK(rounded_value<double>(two53 + 1 - exact_value(0x1p-200)) == 0x1p53);
  CHECK(rounded_value<double>(exact_value(1.0) + exact_value(0x1p-53)) == 1.0);  // halfway to the next double
  CHECK(rounded_value<double>(exact_value(1.0) - exact_value(0x1p-54)) == 1.0);  // halfway below 1: even is 1
  CHECK(rounded_value<double>(exact_value(1.0) - exact_value(0x1p-54) - exact_value(0x1p-300)) == 1 - 0x1p-53);
  CHECK(rounded_value<float>(exact_value(0x1p-150)) == 0);
  CHECK(std::isinf(rounded_value<float>(exact_value(0x1.ffffffp127))));
}

TEST_CASE("exact quotients at a float tie round to even", "[kernels][rounding]") {
  const rational two24 = exact_value(0x1p24);
  // (2^24 + 1) is halfway between the floats 2^24 and 2^24 + 2: even is 2^24.
  CHECK(rounded<float>(two24 + 1, 1) == 0x1p24);
  // (2^24 + 3) · 3 / 3 is halfway between 2^24 + 2 and 2^24 + 4: even is 2^24 + 4.
  CHECK(rounded<float>((two24 + 3) * 3, 3) == 0x1p24 + 4);
  // Just above and below a tie.
  CHECK(rounded<float>(two24 * 1024 + 1024 + 1, 1024) == 0x1p24 + 2);
  CHECK(rounded<float>(two24 * 1024 + 1024 - 1, 1024) == 0x1p24);
  // Negative ties.
  CHECK(rounded<float>(-(two24 + 1), 1) == -0x1p24);
  CHECK(rounded<float>(two24 + 1, -1) == -0x1p24);
  // Half the smallest subnormal float is a tie with 0 (even): +0.
  double z = rounded<float>(exact_value(0x1p-150), 1);
  CHECK(z == 0);
  CHECK(!std::signbit(z));
  CHECK(rounded<float>(exact_value(0x1p-150) * 3, 1) == 0x1p-148);  // 1.5 · 2^-149: even is 2^-148
  // The overflow threshold FLT_MAX + half its ulp rounds to infinity, just below it to FLT_MAX.
  const rational threshold = exact_value(0x1.ffffffp127);
  CHECK(std::isinf(rounded<float>(threshold, 1)));
  CHECK(rounded<float>(threshold * 1024 - 1, 1024) == static_cast<double>(std::numeric_limits<float>::max()));
}

TEST_CASE("exact quotients at a double tie round to even", "[kernels][rounding]") {
  const rational two53 = exact_value(0x1p53);
  CHECK(rounded<double>(two53 + 1, 1) == 0x1p53);
  CHECK(rounded<double>((two53 + 3) * 7, 7) == 0x1p53 + 4);
  CHECK(rounded<double>(two53 * 4096 + 4096 + 1, 4096) == 0x1p53 + 2);
  CHECK(rounded<double>(two53 * 4096 + 4096 - 1, 4096) == 0x1p53);
  CHECK(rounded<double>(-(two53 + 1), 3) == to_nearest_double(-(two53 + 1) / 3));
  // 1/3, 2/3, 1/10: the filter's own cases, against MPFR.
  for (long n = 1; n < 40; ++n)
    for (long d : {3L, 7L, 10L, 49L, 641L}) {
      CHECK(rounded<double>(n, d) == to_nearest_double(rational(n) / rational(d)));
      CHECK(rounded<float>(n, d) == static_cast<double>(to_nearest_float(rational(n) / rational(d))));
    }
}

// ----------------------------------------------------------------------------------------------
// Every kernel against the all-rational reference.

namespace {

struct kernel_tally {
  std::size_t cases = 0, declined = 0, declined_regular = 0;
};

// The conventions under which an operation's kernels are checked: every declared convention
// the kernel reads (light sign, clamping, depth convention, symmetric volumes) and the input
// restrictions that change the generated cases.
std::vector<conventions> conventions_for(operation op) {
  std::vector<conventions> all{conventions{}};
  auto with = [&](auto set) {
    conventions c;
    set(c);
    all.push_back(c);
  };
  switch (op) {
    case operation::shadow_matrix:
      with([](conventions& c) { c.light = light_sign::along_rays; });
      with([](conventions& c) { c.directional_only = true; });
      with([](conventions& c) { c.point_light_only = true; c.unit_normal = true; });
      break;
    case operation::shadow_point:
      with([](conventions& c) { c.light = light_sign::along_rays; });
      with([](conventions& c) { c.clamps_behind_receiver = true; c.directional_only = true; });
      with([](conventions& c) { c.clamps_behind_receiver = true; c.point_light_only = true; });
      break;
    case operation::reflection_matrix:
      with([](conventions& c) { c.unit_normal = true; });
      break;
    case operation::ortho:
    case operation::frustum:
    case operation::perspective:
      all.clear();
      for (depth_convention d : {depth_convention::gl, depth_convention::d3d, depth_convention::reverse_z})
        for (bool symmetric : {false, true}) {
          if (symmetric && op == operation::perspective) continue;
          conventions c;
          c.depth = d;
          c.symmetric_view = symmetric;
          all.push_back(c);
        }
      break;
    case operation::normal_matrix: break;
  }
  return all;
}

template <class F>
void require_kernel_agrees(const detail::operation_spec& spec, const test_case& c, const conventions& conv,
                           kernel_tally& tally) {
  const auto kernel = std::is_same_v<F, float> ? spec.fast_f32 : spec.fast_f64;
  REQUIRE(kernel != nullptr);
  ++tally.cases;
  detail::fast_reference fast;
  if (!kernel(c.inputs.data(), conv, fast)) {
    ++tally.declined;
    if (c.cls == input_class::regular) ++tally.declined_regular;
    return;
  }
  const detail::exact_outputs<rational> e = spec.exact_rational(c.inputs.data(), conv);
  INFO("case " << case_json_line(c) << ", depth " << to_string(conv.depth) << (conv.symmetric_view ? " symmetric" : ""));
  REQUIRE(fast.count == spec.signature.output_count);
  REQUIRE(fast.defined == e.defined);
  REQUIRE(fast.cls == e.cls);
  for (std::size_t j = 0; j < fast.count; ++j) {
    INFO("output " << j);
    const bool undefined = !e.defined || (!e.entry_undefined.empty() && e.entry_undefined[j]);
    REQUIRE(((fast.undefined >> j) & 1) == (e.defined && undefined ? 1u : 0u));
    if (undefined) continue;
    const double want = static_cast<double>(detail::round_exact<F>(e.values[j]));
    REQUIRE(std::memcmp(&fast.value[j], &want, sizeof want) == 0);  // bit for bit, +0 for 0
  }
}

void check_every_kernel(std::size_t per_class, std::uint64_t seed) {
  for (operation op : all_operations()) {
    const detail::operation_spec& spec = detail::spec_of(op);
    if (!spec.fast_f32 && !spec.fast_f64) continue;  // irrational and size builders: the generic oracle
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      kernel_tally tally;
      for (const conventions& conv : conventions_for(op))
        for (input_class cls : {input_class::regular, input_class::near_degenerate, input_class::degenerate}) {
          const auto cases = generate_cases(op, type, per_class, seed + static_cast<std::uint64_t>(op), cls, conv);
          for (const auto& c : cases) {
            if (type == scalar_type::f32) require_kernel_agrees<float>(spec, c, conv, tally);
            else require_kernel_agrees<double>(spec, c, conv, tally);
          }
        }
      INFO("operation " << to_string(op) << ", type " << to_string(type) << ": " << tally.declined << " of "
                        << tally.cases << " cases declined");
      // Every regular case is in the kernels' range; only degenerate extremes (a normal whose
      // |n|² overflows a double) may go to the generic oracle.
      CHECK(tally.declined_regular == 0);
      CHECK(tally.declined * 10 <= tally.cases);
    }
  }
}

}  // namespace

TEST_CASE("every kernel gives the rational oracle's outputs bit for bit", "[kernels][oracle]") {
  check_every_kernel(200, 500);
}

TEST_CASE("the kernels' exact stage alone gives the rational oracle's outputs bit for bit", "[kernels][oracle]") {
  detail::kernels_exact_only = true;
  check_every_kernel(60, 900);
  detail::kernels_exact_only = false;
}

namespace {

// The image-class and plane-value kernels of shadow-point against the all-rational grade of
// the same image: the library's own float formula, the point itself, the light, and those
// one ulp off.
void check_image_kernels(std::uint64_t seed) {
  std::size_t checked = 0, declined = 0;
  for (scalar_type type : {scalar_type::f32, scalar_type::f64})
    for (const conventions& conv : conventions_for(operation::shadow_point))
      for (input_class cls : {input_class::regular, input_class::near_degenerate, input_class::degenerate}) {
        const auto cases = generate_cases(operation::shadow_point, type, 150, seed, cls, conv);
        std::mt19937_64 rng(seed);
        for (const auto& c : cases) {
          const double* in = c.inputs.data();
          double got[3];
          const std::uint64_t pick = rng() % 4;
          for (int i = 0; i < 3; ++i) {
            const double w = in[7] == 0 ? 1 : in[7];
            got[i] = pick == 0 ? in[8 + i] : (pick == 1 ? in[4 + i] / w : in[8 + i] * 0.75 + in[4 + i] * 0.25);
            got[i] = type == scalar_type::f32 ? static_cast<double>(static_cast<float>(got[i])) : got[i];
            if (rng() % 3 == 0)
              got[i] = type == scalar_type::f32 ? std::nextafter(static_cast<float>(got[i]), 1e30f) : std::nextafter(got[i], 1e300);
          }
          const case_grade want = grade_case(c, conv, got, oracle_mode::naive);
          INFO("case " << case_json_line(c) << ", image " << hex_string(got[0]) << " " << hex_string(got[1]) << " "
                       << hex_string(got[2]));
          image_class k;
          const bool f32 = type == scalar_type::f32;
          if (f32 ? detail::fast_image_class_f32(in, conv, got, k) : detail::fast_image_class_f64(in, conv, got, k)) {
            REQUIRE(want.got_class == k);
            ++checked;
          } else {
            ++declined;
          }
          double v;
          if (f32 ? detail::fast_plane_value_f32(in, got, v) : detail::fast_plane_value_f64(in, got, v)) {
            REQUIRE(want.plane_value.has_value());
            REQUIRE(std::memcmp(&v, &*want.plane_value, sizeof v) == 0);
            ++checked;
          } else {
            ++declined;
          }
        }
      }
  CHECK(declined * 20 <= checked);
}

}  // namespace

TEST_CASE("the image-class and plane-value kernels agree with the rational grade", "[kernels][oracle]") {
  check_image_kernels(71);
  detail::kernels_exact_only = true;
  check_image_kernels(72);
  detail::kernels_exact_only = false;
}

TEST_CASE("a shadow-matrix diagonal exactly halfway between two values rounds to even", "[kernels][oracle]") {
  // Plane (0, 1, 1, 0), light (0, 2^24, 3, 0): P·L = 2^24 + 3, and the diagonal entry (0, 0) is
  // P·L − L_0 P_0 = 2^24 + 3, halfway between the floats 2^24 + 2 and 2^24 + 4 (even: + 4).
  const detail::operation_spec& spec = detail::spec_of(operation::shadow_matrix);
  detail::fast_reference r;
  const double f32_inputs[8] = {0, 1, 1, 0, 0, 0x1p24, 3, 0};
  REQUIRE(spec.fast_f32(f32_inputs, conventions{}, r));
  CHECK(r.value[0] == 0x1p24 + 4);
  CHECK(r.value[5] == 3);             // (1, 1): P·L − L_1 P_1 = 3
  CHECK(r.value[10] == 0x1p24);       // (2, 2): 2^24
  // In double: light (0, 2^53, 1, 0), (0, 0) = 2^53 + 1, halfway between 2^53 and 2^53 + 2.
  const double f64_inputs[8] = {0, 1, 1, 0, 0, 0x1p53, 1, 0};
  REQUIRE(spec.fast_f64(f64_inputs, conventions{}, r));
  CHECK(r.value[0] == 0x1p53);
}
