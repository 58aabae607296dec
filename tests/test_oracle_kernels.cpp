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

#include "../src/verify/kernels/cotangent.h"
#include "../src/verify/kernels/error_free.h"
#include "../src/verify/kernels/exact_rounding.h"
#include "../src/verify/operation_table.h"
#include "shadowproof/constructions/irrational.h"
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

// Inputs on which any fused multiply-add in the library's copies changes the answer: all 53
// significand bits set, products that need 106 bits, sums at a tie. Contracted, Veltkamp's
// c − (c − x) with c = (2^27 + 1) x becomes fma(2^27 + 1, x, −fma(2^27 + 1, x, −x)) = x: hi keeps
// all 53 bits and lo is 0, so the bit counts below fail. (GCC fuses every step of Dekker's
// product too, and that fused product happens to stay exact: the split's halves are what the
// interval filter's product test and a build without FMA rely on.)
TEST_CASE("error-free transformations stay exact on hard inputs, so a contracted build fails here",
          "[kernels][error-free][contraction]") {
  const double all_ones = 0x1.fffffffffffffp0;  // 2 − 2^-52: 53 significant bits
  const double hard[] = {all_ones,        0x1.0000000000001p0,  0x1.5555555555555p-1, 0x1.8000000000001p0,
                         0x1.fffffffffffffp+900, 0x1.fffffffffffffp-900, 0x1.0000008000001p0, -0x1.3333333333333p+7,
                         134217729.0,     0x1.ffffffep26};
  for (double x : hard) {
    double hi, lo;
    detail::compiled::split(x, hi, lo);
    INFO("x = " << hex_string(x) << ", hi = " << hex_string(hi) << ", lo = " << hex_string(lo));
    REQUIRE(exact_value(hi) + exact_value(lo) == exact_value(x));
    REQUIRE(significant_bits(hi) <= 26);
    REQUIRE(significant_bits(lo) <= 26);
    // Products of halves are exact in double only because each half has at most 26 bits.
    if (std::fabs(x) < 0x1p+500 && std::fabs(x) > 0x1p-400) REQUIRE(exact_value(hi * hi) == exact_value(hi) * exact_value(hi));
  }
  for (double a : hard)
    for (double b : hard) {
      if (std::fabs(a * b) > 0x1p+996 || std::fabs(a * b) < 0x1p-900) continue;  // Dekker's range
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
  // (2 − 2^-52)² = 4 − 2^-50 + 2^-104 needs 106 bits: p = 4 − 2^-50 and the error term 2^-104.
  double p, e;
  detail::compiled::two_product(all_ones, all_ones, p, e);
  REQUIRE(p == 0x1.ffffffffffffep1);
  REQUIRE(e == 0x1p-104);
  detail::compiled::two_product_dekker(all_ones, all_ones, p, e);
  REQUIRE(p == 0x1.ffffffffffffep1);
  REQUIRE(e == 0x1p-104);
  // Sums at a tie (1 + 2^-53 rounds to even, 1) and with total cancellation of the rounded part.
  const double sums[][2] = {{1.0, 0x1p-53}, {0x1p53, 1.0}, {all_ones, -0x1.ffffffffffffep0}, {0x1p-1074, -1.0},
                            {0x1.fffffffffffffp+1023, -0x1p+970}, {3.0, 0x1.8p-52}};
  for (const auto& ab : sums) {
    double s, err;
    detail::compiled::two_sum(ab[0], ab[1], s, err);
    INFO("a = " << hex_string(ab[0]) << ", b = " << hex_string(ab[1]));
    REQUIRE(s == ab[0] + ab[1]);
    REQUIRE(exact_value(s) + exact_value(err) == exact_value(ab[0]) + exact_value(ab[1]));
  }
  detail::compiled::two_sum(1.0, 0x1p-53, p, e);
  REQUIRE(p == 1.0);
  REQUIRE(e == 0x1p-53);
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
  std::size_t cases = 0, declined = 0, declined_regular = 0, declined_near_degenerate = 0;
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
    case operation::ortho_size:
    case operation::perspective_size:
      all.clear();
      for (depth_convention d : {depth_convention::gl, depth_convention::d3d, depth_convention::reverse_z})
        for (bool symmetric : {false, true}) {
          if (symmetric && op == operation::perspective) continue;
          conventions c;
          c.depth = d;
          c.symmetric_view = symmetric;
          all.push_back(c);
          // Left-handed: the same matrix with column 2 negated (handedness.h).
          c.hand = handedness::left;
          all.push_back(c);
        }
      break;
    default: break;  // normal-matrix; the camera builders: their own test below
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
    if (c.cls == input_class::near_degenerate) ++tally.declined_near_degenerate;
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

// The operations with dedicated kernels whose exact values are rational functions of the
// inputs (with an exact stage). The camera builders with tangents and square roots: below.
const operation kernel_operations[] = {operation::shadow_matrix, operation::shadow_point, operation::reflection_matrix,
                                       operation::ortho,         operation::frustum,      operation::normal_matrix,
                                       operation::perspective,   operation::ortho_size,   operation::perspective_size};

void check_every_kernel(std::size_t per_class, std::uint64_t seed) {
  for (operation op : kernel_operations) {
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

// ----------------------------------------------------------------------------------------------
// The camera builders with irrational values: cot(fovy/2) in double-double, and their kernels.

namespace {

// Angles across the half turn: uniform, tiny, about the switch between the two evaluations
// (fovy = 1.6 rad, 90°), about the quarter turn and just below the half turn.
std::vector<double> half_turn_angles(angle_unit unit, std::size_t uniform, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const double pi_below = 0x1.921fb54442d18p+1, full = unit == angle_unit::degrees ? 180.0 : pi_below;
  std::vector<double> a;
  for (std::size_t i = 0; i < uniform; ++i) a.push_back(full * (static_cast<double>(rng() >> 11) * 0x1p-53));
  for (int k = 1; k <= 390; k += 7) a.push_back(std::ldexp(full, -k));
  a.push_back(unit == angle_unit::degrees ? 0x1p-390 : 0x1p-400);  // the smallest covered
  for (double centre : {unit == angle_unit::degrees ? 90.0 : 1.6, full / 2, full}) {
    double up = centre, down = centre;
    for (int i = 0; i < 40; ++i) {
      up = std::nextafter(up, 1e300);
      down = std::nextafter(down, 0.0);
      a.push_back(down);
      if (up < full || (unit == angle_unit::radians && up <= pi_below)) a.push_back(up);
    }
    a.push_back(centre);
  }
  std::vector<double> inside;
  for (double x : a)
    if (x > 0 && (unit == angle_unit::degrees ? x < 180 : x <= pi_below)) inside.push_back(x);
  return inside;
}

}  // namespace

TEST_CASE("cot(fovy/2) in double-double encloses MPFR's value tightly", "[kernels][cotangent]") {
  // MPFR's 256-bit enclosure [lo, hi] of cot(fovy/2) (constructions/irrational.h), which holds
  // the exact value, must lie inside hi' + lo' ± e of the double-double evaluation, whose bound
  // must be at most 2^-100 of the value. For tiny angles the double-double bound is narrower
  // than 256 bits (cot x ≈ 1/x is evaluated to about 2^-106 relative and x is exact): there
  // the enclosure at 1024 bits.
  std::size_t checked = 0;
  for (angle_unit unit : {angle_unit::radians, angle_unit::degrees})
    for (double fovy : half_turn_angles(unit, 1500, unit == angle_unit::degrees ? 7 : 8)) {
      INFO("fovy " << hex_string(fovy) << (unit == angle_unit::degrees ? " degrees" : " radians"));
      detail::cot_pair c;
      REQUIRE(detail::cot_half_angle_pair(fovy, unit, c));
      const rational mid = exact_value(c.hi) + exact_value(c.lo), e = exact_value(c.e);
      enclosure mp = cot_half_angle(fovy, unit, 256);
      if (mp.hi - mp.lo >= e) mp = cot_half_angle(fovy, unit, 1024);
      REQUIRE(mp.hi - mp.lo < e);
      CHECK(mid - e <= mp.lo);
      CHECK(mp.hi <= mid + e);
      CHECK(c.e <= std::fabs(c.hi) * 0x1p-100);
      ++checked;
    }
  CHECK(checked > 3000);
  // Outside the half turn, or below the evaluation's range: declined (MPFR or nothing decides).
  detail::cot_pair c;
  for (double fovy : {0.0, -1.0, 0x1.921fb54442d19p+1, 4.0, 0x1p-401, std::nan("")})
    CHECK_FALSE(detail::cot_half_angle_pair(fovy, angle_unit::radians, c));
  for (double fovy : {0.0, 180.0, 200.0, 0x1p-391})
    CHECK_FALSE(detail::cot_half_angle_pair(fovy, angle_unit::degrees, c));
}

TEST_CASE("the field of view's range is decided as with MPFR's enclosure of pi", "[kernels][cotangent]") {
  for (double fovy : {0x1.921fb54442d18p+1, 0x1.921fb54442d19p+1, 0x1.921fb54442d17p+1, 3.0, 1e-300, 0.0, -0.0,
                      -1.0, 180.0, 179.99999999999997, 1e300})
    for (angle_unit unit : {angle_unit::radians, angle_unit::degrees}) {
      INFO("fovy " << hex_string(fovy) << " " << to_string(unit));
      CHECK(detail::field_of_view_inside_half_turn(fovy, unit) == field_of_view_in_range(fovy, unit));
    }
}

TEST_CASE("the camera kernels give the rational oracle's outputs bit for bit", "[kernels][oracle]") {
  // perspective-fov(-infinite) in radians and degrees and every depth convention, look-at and
  // target-to in both handednesses (their kernels read it), every class; few cases per class,
  // the rational oracle of these is slow. A kernel may decline (its bound straddles a
  // rounding boundary, a degenerate frame): rarely on regular inputs.
  for (operation op : {operation::perspective_fov, operation::perspective_fov_infinite, operation::look_at,
                       operation::target_to}) {
    const detail::operation_spec& spec = detail::spec_of(op);
    const bool frame = op == operation::look_at || op == operation::target_to;
    std::vector<conventions> all;
    if (frame) {
      all.push_back(conventions{});
      all.back().hand = handedness::left;
      all.push_back(conventions{});
    } else {
      for (depth_convention d : {depth_convention::gl, depth_convention::d3d, depth_convention::reverse_z})
        for (angle_unit unit : {angle_unit::radians, angle_unit::degrees}) {
          conventions c;
          c.depth = d;
          c.angle = unit;
          all.push_back(c);
        }
      all.back().hand = handedness::left;
    }
    for (scalar_type type : {scalar_type::f32, scalar_type::f64}) {
      kernel_tally tally;
      for (const conventions& conv : all)
        for (input_class cls : all_input_classes()) {
          const auto cases = generate_cases(op, type, frame ? 20 : 16, 77 + static_cast<std::uint64_t>(op), cls, conv);
          for (const auto& c : cases) {
            if (type == scalar_type::f32) require_kernel_agrees<float>(spec, c, conv, tally);
            else require_kernel_agrees<double>(spec, c, conv, tally);
          }
        }
      INFO("operation " << to_string(op) << ", type " << to_string(type) << ": " << tally.declined << " of "
                        << tally.cases << " cases declined");
      // Declined: the degenerate classes (no field of view, a frame without an axis) and the
      // range classes (inputs beyond the kernels' ranges), not the regular ones; nor the
      // near-degenerate frames, where up × w cancels: their second pass, in double-double
      // with up × w as exact sums, decides them in both types.
      CHECK(tally.declined_regular == 0);
      if (frame) CHECK(tally.declined_near_degenerate == 0);
      CHECK(tally.declined * 16 <= tally.cases * 9);
    }
  }
}
