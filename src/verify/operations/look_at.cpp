// look-at: eye[3], target[3], up[3] -> the view matrix (world to eye), 16 entries, and
// target-to: the same inputs -> the camera's placement (eye to world), its inverse
// (constructions/look_at.h). Right-handed (gluLookAt, gl-matrix lookAt/targetTo, three.js)
// or left-handed (D3DX/Babylon LookAtLH, wgpu-matrix aim) by the declared handedness.
// Every entry is q/√s with q, s rational, rounded correctly: exactly when √s is rational,
// by Ziv's strategy otherwise (constructions/irrational.h).
// Classes: near-degenerate = up within a relative 2^-k of the view direction, or the target
// within a relative 2^-k of the eye; degenerate = up exactly parallel to the view direction
// (x and y rows undefined) or eye = target (every axis undefined).
#include <cmath>
#include <limits>
#include <type_traits>

#include "irrational_entries.h"
#include "shadowproof/constructions/look_at.h"
#include "view_volume.h"

namespace shadowproof::detail {
namespace {

vec3<rational> vec3_from(const double* x) { return {exact_value(x[0]), exact_value(x[1]), exact_value(x[2])}; }

template <bool placement>
exact_outputs<rational> exact_rational(const double* in, const conventions& conv) {
  const vec3<rational> eye = vec3_from(in), target = vec3_from(in + 3), up = vec3_from(in + 6);
  const auto entries =
      placement ? target_to_entries(eye, target, up, conv.hand) : look_at_entries(eye, target, up, conv.hand);
  exact_outputs<rational> r;
  r.entry_undefined.assign(16, false);
  for (std::size_t i = 0; i < 16; ++i) {
    const root_entry<rational>& e = entries[i];
    if (!e.defined) {
      r.entry_undefined[i] = true;
      r.values.push_back(rational(0));
      continue;
    }
    // q/√s = sign(q) √(q²/s)
    r.values.push_back(signed_sqrt_representative(sgn(e.numerator), e.numerator * e.numerator / e.radicand));
  }
  return r;
}

// The same entries q/√s over intervals: q and s by the same exact formulas, outward rounded,
// then √s (oracle_interval.h) and the quotient. Whether |X|² or |W|² vanishes is decided or
// throws `undecided`, so an entry is undefined exactly when it is over rationals.
template <class N, bool placement>
exact_outputs<N> enclosed(const double* in, const conventions& conv) {
  require_finite_inputs(in, 9);
  const auto vec = [](const double* x) { return vec3<N>{N::point(x[0]), N::point(x[1]), N::point(x[2])}; };
  const vec3<N> eye = vec(in), target = vec(in + 3), up = vec(in + 6);
  const auto entries =
      placement ? target_to_entries(eye, target, up, conv.hand) : look_at_entries(eye, target, up, conv.hand);
  exact_outputs<N> r;
  r.entry_undefined.assign(16, false);
  for (std::size_t i = 0; i < 16; ++i) {
    const root_entry<N>& e = entries[i];
    if (!e.defined) r.entry_undefined[i] = true;
    const bool zero = !e.defined || (e.numerator.is_point() && e.numerator.mid() == 0);
    r.values.push_back(zero ? N(0) : N(e.numerator / sqrt(e.radicand)));
  }
  return r;
}

template <class N, bool placement>
exact_outputs<N> exact(const double* in, const conventions& conv) {
  refuse_grading_up_to_scale(conv, placement ? "target-to" : "look-at");
  if constexpr (std::is_same_v<N, rational>) return exact_rational<placement>(in, conv);
  else return enclosed<N, placement>(in, conv);
}

// Integer coordinates in [−64, 64] for a degenerate case, so that eye − target and its
// multiples are exact in every type.
double small_integer(case_rng& r) { return static_cast<double>(r.integer(-64, 64)); }

void generate(case_rng& r, input_class cls, const conventions&, double* x) {
  double* eye = x;
  double* target = x + 3;
  double* up = x + 6;
  if (cls == input_class::degenerate) {
    for (int i = 0; i < 3; ++i) eye[i] = small_integer(r);
    if (r.raw() & 1) {
      for (int i = 0; i < 3; ++i) target[i] = eye[i];  // eye = target
      for (int i = 0; i < 3; ++i) up[i] = small_integer(r);
    } else {
      do {
        for (int i = 0; i < 3; ++i) target[i] = small_integer(r);
      } while (target[0] == eye[0] && target[1] == eye[1] && target[2] == eye[2]);
      const double k = static_cast<double>(r.integer(-3, 3));  // up = k (eye − target), k = 0 too
      for (int i = 0; i < 3; ++i) up[i] = k * (eye[i] - target[i]);
    }
    return;
  }
  for (int i = 0; i < 3; ++i) eye[i] = r.value(-2, 4);
  do {
    for (int i = 0; i < 3; ++i) target[i] = r.value(-2, 4);
  } while (target[0] == eye[0] && target[1] == eye[1] && target[2] == eye[2]);
  if (r.raw() & 1) {  // the usual world up
    up[0] = up[2] = 0;
    up[1] = 1;
  } else {
    for (int i = 0; i < 3; ++i) up[i] = r.value(-1, 1);
  }
  if (cls == input_class::near_degenerate) {
    const int k = static_cast<int>(r.integer(4, r.bits() + 4));
    if (r.raw() & 1) {  // target a relative 2^-k from the eye
      for (int i = 0; i < 3; ++i) target[i] = r.fit(eye[i] + std::ldexp(std::fabs(eye[i]) + 1, -k) * ((r.raw() & 1) ? 1 : -1));
    } else {  // up a relative 2^-k off the view direction
      for (int i = 0; i < 3; ++i)
        up[i] = r.fit((target[i] - eye[i]) + std::ldexp(std::fabs(target[i] - eye[i]) + 1, -k) * ((r.raw() & 1) ? 1 : -1));
    }
  }
  for (int i = 0; i < 9; ++i) x[i] = r.fit(x[i]);
  if (cls == input_class::range) {
    // Every input scaled by one power of two (the frame does not change, the translation scales)
    // so that |eye − target|² overflows, or underflows.
    const int top = top_exponent(x, 9);
    const int e = (r.raw() & 1) ? max_exponent(r) / 2 - top + static_cast<int>(r.integer(1, 3))
                                : min_normal_exponent(r) / 2 - top - 3 - static_cast<int>(r.integer(0, 2));
    if (!scale_exactly(r, x, 9, e)) generate(r, cls, conventions{}, x);  // draw again
  }
}

// log2 of the sine of the angle between up and the view direction (−inf when parallel or
// when eye = target).
double closeness(const double* x) {
  long double w[3], u[3];
  for (int i = 0; i < 3; ++i) {
    w[i] = static_cast<long double>(x[i]) - x[3 + i];
    u[i] = x[6 + i];
  }
  const long double c0 = u[1] * w[2] - u[2] * w[1], c1 = u[2] * w[0] - u[0] * w[2], c2 = u[0] * w[1] - u[1] * w[0];
  const long double cross = std::sqrt(c0 * c0 + c1 * c1 + c2 * c2);
  const long double lw = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  const long double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  if (cross == 0 || lw == 0 || lu == 0) return -std::numeric_limits<double>::infinity();
  return static_cast<double>(std::log2(cross / (lw * lu)));
}

template <bool placement>
std::string reproducer(const test_case& c, const conventions& conv) {
  if (std::isinf(closeness(c.inputs.data()))) return exact_command(c, conv);  // no frame: `camera` rejects it
  return std::string("shadowproof camera ") + (placement ? "target-to" : "look-at") + " --eye " + hex_list(c, 0, 3) +
         " --target " + hex_list(c, 3, 3) + " --up " + hex_list(c, 6, 3) + handedness_flag(conv);
}

template <bool placement>
operation_spec make() {
  operation_spec s{};
  if constexpr (placement) {
    s.op = operation::target_to;
    s.name = "target-to";
    s.summary = "eye[3], target[3], up[3] -> the camera's placement (eye to world, the look-at inverse), 16 "
                "entries (square roots rounded correctly)";
  } else {
    s.op = operation::look_at;
    s.name = "look-at";
    s.summary = "eye[3], target[3], up[3] -> the view matrix (world to eye), 16 entries (square roots rounded "
                "correctly)";
  }
  s.signature = make_signature({{"eye", 3}, {"target", 3}, {"up", 3}}, 16, 4);
  s.generate = generate;
  s.closeness = closeness;
  s.exact_rational = exact<rational, placement>;
  s.exact_ival32 = exact<ival32, placement>;
  s.exact_ival64 = exact<ival64, placement>;
  s.fast_f32 = placement ? fast_target_to_f32 : fast_look_at_f32;
  s.fast_f64 = placement ? fast_target_to_f64 : fast_look_at_f64;
  s.fast_kernels_read_handedness = true;
  // No derivatives over dual numbers (square roots): the verdicts take the generic
  // sensitivities (conditioning.cpp). Longest path of the straightforward evaluation: the
  // difference eye − target, |w|² (three), the square root and the division, the cross product
  // with up (two) and its normalisation (five), the second cross product (two), the translation's
  // dot product (three): sixteen roundings, c = 2 × 16.
  s.stable_constant = 32;
  s.sentinel_outputs = matrix_sentinels;
  s.reproducer = reproducer<placement>;
  s.invalid = never_invalid;
  return s;
}

}  // namespace

const operation_spec& look_at_spec() {
  static const operation_spec s = make<false>();
  return s;
}

const operation_spec& target_to_spec() {
  static const operation_spec s = make<true>();
  return s;
}

}  // namespace shadowproof::detail
