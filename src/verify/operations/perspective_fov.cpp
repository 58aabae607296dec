// perspective-fov: camera[4] = fovy, aspect, n, f -> perspective(cot(fovy/2), aspect, n, f,
// depth), 16 entries, and perspective-fov-infinite: camera[3] = fovy, aspect, n -> the same
// with the far plane at infinity. fovy is an angle in the declared unit (radians by default,
// or degrees); the focal scale cot(fovy/2) of a float angle is transcendental (rational only
// at 90°), so entries (0,0) = cot(fovy/2)/aspect and (1,1) = cot(fovy/2) are rounded correctly
// by Ziv's strategy (constructions/irrational.h); the depth rows are rational. Left-handed:
// column 2 negated.
// Classes: near-degenerate = far within a relative 2^-k of near, far ≫ near, or a field of
// view within 2^-k of 0 or of 180°; degenerate = n = f (the depth entries undefined), for the
// infinite one fovy = 0 (the focal scales (0,0) and (1,1) undefined, the depth entries exist).
// fovy outside [0, π), aspect ≤ 0, n ≤ 0 or f ≤ 0 admit no projection: every output undefined.
#include <mpfr.h>

#include <cmath>
#include <limits>
#include <type_traits>

#include "../kernels/cotangent.h"
#include "irrational_entries.h"
#include "view_volume.h"

namespace shadowproof::detail {
namespace {

template <bool infinite>
exact_outputs<rational> exact_rational(const double* in, const conventions& conv) {
  exact_outputs<rational> r;
  const double fovy = in[0];
  const rational aspect = exact_value(in[1]), n = exact_value(in[2]);
  rational f = infinite ? rational(0) : exact_value(in[3]);
  const bool no_field = fovy == 0;  // cot(0) does not exist: only the focal scales go
  if ((!no_field && !field_of_view_in_range(fovy, conv.angle)) || sgn(aspect) <= 0 || sgn(n) <= 0 || (!infinite && sgn(f) <= 0)) {
    r.set_undefined(16);
    return r;
  }
  r.entry_undefined.assign(16, false);
  if (!infinite && f == n) {  // zero depth extent: only the depth row divides by f − n
    r.entry_undefined[2 * 4 + 2] = r.entry_undefined[2 * 4 + 3] = true;
    f = n + 1;
  }
  // The depth rows exactly, with a unit focal scale in the x and y rows replaced below.
  mat4<rational> M = perspective(rational(1), rational(1), n, f, conv.depth, infinite);
  if (no_field) {
    r.entry_undefined[0] = r.entry_undefined[5] = true;
    M(0, 0) = M(1, 1) = rational(0);
    r.set_matrix(with_handedness(M, conv.hand));
    return r;
  }
  M(1, 1) = correctly_rounding_representative([&](long p) { return cot_half_angle(fovy, conv.angle, p); },
                                              "cot(fovy/2)");
  M(0, 0) = correctly_rounding_representative(
      [&](long p) {
        const enclosure c = cot_half_angle(fovy, conv.angle, p);
        return enclosure{c.lo / aspect, c.hi / aspect};  // aspect > 0 keeps the order
      },
      "cot(fovy/2)/aspect");
  r.set_matrix(with_handedness(M, conv.hand));
  return r;
}

// lo ≤ cot(fovy/2) ≤ hi, and the rational oracle's representative of cot(fovy/2) within
// [lo, hi] widened by 2^-62 of its magnitude (conditioning.cpp's representative_enclosure).
// From the double-double enclosure (kernels/cotangent.h) where it covers the angle: in
// radians the representative is within 2^-63 |cot| of cot (MPFR's directed roundings at
// p ≥ 64 bits), inside that widening. In degrees MPFR encloses h = fovy·π/360 first, within
// 3·2^-63 h on each side at 64 bits (and nested inside at more bits), so the representative is
// within 6.2·2^-63 h / sin²h + 2^-62 |cot h| of cot h; h/sin h ≤ π/2 and 1/sin h ≤ 1 + cot h
// make that at most 2^-58 (1 + cot h), by which the enclosure is widened. Otherwise the
// 64-bit MPFR enclosure itself, read into long double, whose 64-bit significand holds both
// ends exactly. The last angle is remembered per thread: the verdicts' sensitivities evaluate
// the same angle while they perturb the other inputs.
struct cot_bounds {
  long double lo, hi;
};
cot_bounds cot_half_angle_64(double fovy, angle_unit unit) {
  thread_local double last_fovy = std::numeric_limits<double>::quiet_NaN();
  thread_local angle_unit last_unit = angle_unit::radians;
  thread_local cot_bounds last{};
  if (fovy == last_fovy && unit == last_unit) return last;
  cot_pair c;
  if (cot_half_angle_pair(fovy, unit, c)) {
    double w = c.e;
    if (unit == angle_unit::degrees) w += (1 + (std::fabs(c.hi) + c.e) * (1 + 0x1p-50)) * 0x1p-58 * (1 + 0x1p-50);
    const ival64 v = ival64::point(c.hi) + ival64::point(c.lo) + ival64::between(-w, w);
    last = {v.lower(), v.upper()};
  } else {
    const enclosure e = cot_half_angle(fovy, unit, 64);
    mpfr_t x;
    mpfr_init2(x, 64);
    mpfr_set_q(x, e.lo.get_mpq_t(), MPFR_RNDD);  // exact: a 64-bit number
    last.lo = mpfr_get_ld(x, MPFR_RNDD);
    mpfr_set_q(x, e.hi.get_mpq_t(), MPFR_RNDU);
    last.hi = mpfr_get_ld(x, MPFR_RNDU);
    mpfr_clear(x);
  }
  last_fovy = fovy;
  last_unit = unit;
  return last;
}

// [lo, hi] as an interval over B, rounded outwards when B is narrower than long double.
template <class B>
interval<B> enclosing(long double lo, long double hi) {
  B l = static_cast<B>(lo), h = static_cast<B>(hi);
  if (static_cast<long double>(l) > lo) l = std::nextafter(l, -std::numeric_limits<B>::infinity());
  if (static_cast<long double>(h) < hi) h = std::nextafter(h, std::numeric_limits<B>::infinity());
  return interval<B>::between(l, h);
}

// The same outputs over intervals: the depth rows by the same exact formulas, the focal scales
// from the 64-bit enclosure of cot(fovy/2). Which outputs exist is decided on the doubles
// themselves, exactly as over rationals.
template <class N, bool infinite>
exact_outputs<N> enclosed(const double* in, const conventions& conv) {
  using B = decltype(N().mid());
  require_finite_inputs(in, infinite ? 3 : 4);
  exact_outputs<N> r;
  const double fovy = in[0];
  const bool no_field = fovy == 0;
  if ((!no_field && !field_of_view_inside_half_turn(fovy, conv.angle)) || !(in[1] > 0) || !(in[2] > 0) ||
      (!infinite && !(in[3] > 0))) {
    r.set_undefined(16);
    return r;
  }
  r.entry_undefined.assign(16, false);
  const N aspect = N::point(in[1]), n = N::point(in[2]);
  N f = infinite ? N(0) : N::point(in[3]);
  if (!infinite && in[3] == in[2]) {
    r.entry_undefined[2 * 4 + 2] = r.entry_undefined[2 * 4 + 3] = true;
    f = n + N(1);
  }
  mat4<N> M = perspective(N(1), N(1), n, f, conv.depth, infinite);
  if (no_field) {
    r.entry_undefined[0] = r.entry_undefined[5] = true;
    M(0, 0) = M(1, 1) = N(0);
  } else {
    const cot_bounds c = cot_half_angle_64(fovy, conv.angle);
    M(1, 1) = enclosing<B>(c.lo, c.hi);
    M(0, 0) = M(1, 1) / aspect;
  }
  r.set_matrix(with_handedness(M, conv.hand));
  return r;
}

template <class N, bool infinite>
exact_outputs<N> exact(const double* in, const conventions& conv) {
  refuse_grading_up_to_scale(conv, infinite ? "perspective-fov-infinite" : "perspective-fov");
  if constexpr (std::is_same_v<N, rational>) return exact_rational<infinite>(in, conv);
  else return enclosed<N, infinite>(in, conv);
}

double positive(case_rng& r, int emin, int emax) {
  double v = 0;
  while (v == 0) v = std::fabs(r.value(emin, emax));
  return v;
}

// A field of view inside (0, π) radians or (0°, 180°): mostly 10°–150°, near-degenerate ones
// within a relative 2^-k of either end.
double field_of_view(case_rng& r, input_class cls, angle_unit unit) {
  const double full = unit == angle_unit::degrees ? 180.0 : 3.140625;  // 3.140625 < π, a float
  double x = full * (0.05 + 0.8 * std::ldexp(static_cast<double>(r.integer(0, (1 << 20) - 1)), -20));
  if (cls == input_class::near_degenerate && (r.raw() & 1)) {
    const double tiny = std::ldexp(full, -static_cast<int>(r.integer(4, r.bits() - 2)));
    x = (r.raw() & 1) ? tiny : full - tiny;
  }
  return r.fit(x);
}

// range: n (and f) scaled by one power of two so that n f (n²) overflows, or underflows; A does
// not change, B scales.
void scale_depth(case_rng& r, double* x, std::size_t count) {
  const int top = top_exponent(x + 2, count);
  const int e = (r.raw() & 1) ? max_exponent(r) / 2 - top + static_cast<int>(r.integer(1, 3))
                              : min_normal_exponent(r) / 2 - top - 3 - static_cast<int>(r.integer(0, 2));
  if (!scale_exactly(r, x + 2, count, e)) x[2] = 0;  // hardly ever: out of the class, drawn again
}

template <bool infinite>
void generate(case_rng& r, input_class cls, const conventions& req, double* x) {
  x[0] = field_of_view(r, cls, req.angle);
  x[1] = r.fit(positive(r, -1, 2));  // aspect
  x[2] = r.fit(positive(r, -4, 0));  // near
  if (infinite) {
    if (cls == input_class::degenerate) x[0] = 0;  // no field of view: cot(0) does not exist
    if (cls == input_class::range) scale_depth(r, x, 1);
    return;
  }
  x[3] = r.fit(x[2] + positive(r, 0, 6));
  if (cls == input_class::near_degenerate && (r.raw() & 1)) {
    if (r.raw() & 1) {
      x[3] = x[2] * std::ldexp(1.0, static_cast<int>(r.integer(10, r.bits() == 24 ? 60 : 400)));  // far ≫ near
    } else {
      const int k = static_cast<int>(r.integer(4, r.bits() - 1));
      x[3] = r.fit(x[2] + std::ldexp(x[2], -k));  // far a relative 2^-k beyond near
    }
  } else if (cls == input_class::degenerate) {
    x[3] = x[2];
  }
  if (cls == input_class::range) scale_depth(r, x, 2);
}

// The smaller of log2 of the relative depth extent and log2 of the angle's relative distance
// to 0 or to a half turn.
template <bool infinite>
double closeness(const double* x) {
  // The unit is not known here; a fovy above π is in degrees.
  const long double full = x[0] > 3.2 ? 180.0L : 3.14159265358979323846L;
  const long double a = std::fabs(static_cast<long double>(x[0]));
  double c = static_cast<double>(std::log2(std::min(a, std::fabs(full - a)) / full));
  if (!infinite) {
    const long double extent = std::fabs(static_cast<long double>(x[3]) - x[2]);
    if (extent == 0) return -std::numeric_limits<double>::infinity();
    c = std::min(c, static_cast<double>(std::log2(extent / (std::fabs(static_cast<long double>(x[2])) +
                                                             std::fabs(static_cast<long double>(x[3]))))));
  }
  return c;
}

template <bool infinite>
std::string reproducer(const test_case& c, const conventions& conv) {
  const double* x = c.inputs.data();
  const bool proper = x[0] > 0 && x[1] > 0 && x[2] > 0 && (infinite || (x[3] > 0 && x[3] != x[2]));
  if (!proper) return exact_command(c, conv);  // inputs `camera` rejects
  std::string s = "shadowproof camera perspective --fovy " + hex_string(c.inputs[0]) +
                  (conv.angle == angle_unit::degrees ? " --degrees" : "") + " --aspect " + hex_string(c.inputs[1]) +
                  " --near " + hex_string(c.inputs[2]);
  s += infinite ? std::string(" --infinite-far") : " --far " + hex_string(c.inputs[3]);
  return s + " --convention " + std::string(to_string(conv.depth)) + handedness_flag(conv);
}

template <bool infinite>
operation_spec make() {
  operation_spec s{};
  if constexpr (infinite) {
    s.op = operation::perspective_fov_infinite;
    s.name = "perspective-fov-infinite";
    s.summary = "camera[3] = fovy, aspect, n -> perspective with the far plane at infinity, 16 entries "
                "(cot(fovy/2) rounded correctly)";
    s.signature = make_signature({{"camera", 3}}, 16, 4);
  } else {
    s.op = operation::perspective_fov;
    s.name = "perspective-fov";
    s.summary = "camera[4] = fovy, aspect, n, f -> symmetric perspective in the declared depth convention, 16 "
                "entries (cot(fovy/2) rounded correctly)";
    s.signature = make_signature({{"camera", 4}}, 16, 4);
  }
  s.generate = generate<infinite>;
  s.closeness = closeness<infinite>;
  s.exact_rational = exact<rational, infinite>;
  s.exact_ival32 = exact<ival32, infinite>;
  s.exact_ival64 = exact<ival64, infinite>;
  s.fast_f32 = infinite ? fast_perspective_fov_infinite_f32 : fast_perspective_fov_f32;
  s.fast_f64 = infinite ? fast_perspective_fov_infinite_f64 : fast_perspective_fov_f64;
  s.fast_kernels_read_handedness = true;
  // No derivatives over dual numbers (cot is irrational): the verdicts take the generic
  // sensitivities (conditioning.cpp). cot(fovy/2) as 1/tan: the angle's conversion (two
  // roundings in degrees), tan, the reciprocal, the quotient by aspect; A and B three: c = 2 × 5.
  s.stable_constant = 10;
  s.sentinel_outputs = matrix_sentinels;
  s.reproducer = reproducer<infinite>;
  s.invalid = never_invalid;
  return s;
}

}  // namespace

const operation_spec& perspective_fov_spec() {
  static const operation_spec s = make<false>();
  return s;
}

const operation_spec& perspective_fov_infinite_spec() {
  static const operation_spec s = make<true>();
  return s;
}

}  // namespace shadowproof::detail
