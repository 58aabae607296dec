#pragma once
// What every operation's case generator shares: the random source with our own mapping to
// numbers exactly representable in the case's type, random planes and lights, and the exact
// constructions of degenerate configurations (a point exactly on a plane, a direction exactly
// orthogonal to a normal, a flat view volume).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "shadowproof/core/random.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/operation.h"

namespace shadowproof::detail {

// Our own mapping from the 64-bit generator to numbers: std::uniform_*_distribution is
// implementation-defined, and case files must be identical on every platform.
class case_rng {
 public:
  case_rng(std::uint64_t seed, scalar_type t) : source_(seed), bits_(t == scalar_type::f32 ? 24 : 53) {}

  std::uint64_t raw() { return source_.raw(); }
  /// Uniform integer in [lo, hi] (random_source::integer: modulo bias below 2^-40 here).
  long long integer(long long lo, long long hi) { return source_.integer(lo, hi); }
  /// A random number with up to `bits_` significant bits, magnitude below 2^e for e in
  /// [emin, emax]: exactly representable in the case's type.
  double value(int emin = -2, int emax = 2) {
    const std::uint64_t r = raw();
    const double m = static_cast<double>(r >> (64 - bits_));
    const int e = static_cast<int>(integer(emin, emax));
    const double v = std::ldexp(m, e - bits_);
    return (raw() & 1) ? -v : v;
  }
  /// Rounds a double to the case's type (the generator's own arithmetic is not graded). The
  /// float goes through memory: GCC 12's basic-block vectoriser at -O3 was seen to store the
  /// unrounded doubles of a vectorised double -> float -> double round trip (near_plane).
  double fit(double x) const {
    if (bits_ != 24) return x;
    volatile float rounded = static_cast<float>(x);
    return static_cast<double>(rounded);
  }
  int bits() const { return bits_; }

  /// Planes must have a unit normal (±1 on one axis), for routines that require one.
  bool unit_normal = false;

 private:
  random_source source_;
  int bits_;
};

// The type's exponent range: finite values below 2^max_exponent, normal ones from
// 2^min_normal_exponent.
inline int max_exponent(const case_rng& r) { return r.bits() == 24 ? 128 : 1024; }
inline int min_normal_exponent(const case_rng& r) { return r.bits() == 24 ? -126 : -1022; }

// floor(log2 max |x_i|) over the nonzero x_i of x[0..n); 0 when all are zero.
inline int top_exponent(const double* x, std::size_t n) {
  int top = std::numeric_limits<int>::min();
  for (std::size_t i = 0; i < n; ++i)
    if (x[i] != 0) top = std::max(top, std::ilogb(x[i]));
  return top == std::numeric_limits<int>::min() ? 0 : top;
}

// Multiplies x[0..n) by 2^e when every product is exact and finite in the case's type (a power
// of two scales exactly unless it lands among the subnormals and drops bits); false, with x
// unchanged, otherwise.
inline bool scale_exactly(const case_rng& r, double* x, std::size_t n, int e) {
  for (std::size_t i = 0; i < n; ++i) {
    const double y = r.fit(std::ldexp(x[i], e));
    if (!std::isfinite(y) || std::ldexp(y, -e) != x[i]) return false;
  }
  for (std::size_t i = 0; i < n; ++i) x[i] = std::ldexp(x[i], e);
  return true;
}

inline void random_normal(case_rng& r, double* n) {
  if (r.unit_normal) {
    n[0] = n[1] = n[2] = 0;
    n[r.integer(0, 2)] = (r.raw() & 1) ? 1.0 : -1.0;
    return;
  }
  do {
    for (int i = 0; i < 3; ++i) n[i] = r.value();
  } while (n[0] == 0 && n[1] == 0 && n[2] == 0);
}

// P = (n, d), random.
inline void random_plane(case_rng& r, double* p) {
  random_normal(r, p);
  p[3] = r.value();
}

// A light: directional (w = 0) or a point light (w = 1).
inline void random_light(case_rng& r, double* l, bool directional) {
  do {
    for (int i = 0; i < 3; ++i) l[i] = r.value(0, 3);
  } while (l[0] == 0 && l[1] == 0 && l[2] == 0);
  l[3] = directional ? 0 : 1;
}

inline long double dot3l(const double* a, const double* b) {
  return static_cast<long double>(a[0]) * b[0] + static_cast<long double>(a[1]) * b[1] +
         static_cast<long double>(a[2]) * b[2];
}

// Moves the light (or point) x = (x, w) to within a relative 2^-k of the plane P, k random in
// 4 … p−1:
// x − ((P·x)/(n·n) − 2^-k |x| / |n|) n, rounded to the case's type.
inline void near_plane(case_rng& r, const double* p, double* x) {
  const long double nn = dot3l(p, p);
  const long double px = dot3l(p, x) + static_cast<long double>(p[3]) * x[3];
  const long double norm_x = std::sqrt(dot3l(x, x) + static_cast<long double>(x[3]) * x[3]);
  const int k = static_cast<int>(r.integer(4, r.bits() - 1));  // within the type's resolution
  const long double offset = std::ldexp(norm_x / std::sqrt(nn), -k) * ((r.raw() & 1) ? 1 : -1);
  const long double t = px / nn - offset / std::sqrt(nn);
  for (int i = 0; i < 3; ++i) x[i] = r.fit(static_cast<double>(x[i] - t * p[i]));
}

// Integer-valued plane and point with the point exactly on the plane: n random integers,
// d = −n·x (exact: every product and sum is a small integer).
inline void integer_plane_through(case_rng& r, double* p, double* x) {
  if (r.unit_normal) {
    random_normal(r, p);
  } else do {
    for (int i = 0; i < 3; ++i) p[i] = static_cast<double>(r.integer(-100, 100));
  } while (p[0] == 0 && p[1] == 0 && p[2] == 0);
  for (int i = 0; i < 3; ++i) x[i] = static_cast<double>(r.integer(-100, 100));
  p[3] = -(p[0] * x[0] + p[1] * x[1] + p[2] * x[2]);
}

// A direction exactly orthogonal to n: (n_j, −n_i) on a random pair of axes, 0 elsewhere.
inline void exact_orthogonal(case_rng& r, const double* n, double* l) {
  const int i = static_cast<int>(r.integer(0, 2));
  const int j = (i + 1 + static_cast<int>(r.integer(0, 1))) % 3;
  const int k = 3 - i - j;
  l[i] = n[j];
  l[j] = -n[i];
  l[k] = 0;
  if (l[0] == 0 && l[1] == 0 && l[2] == 0) {  // n along axis k: any axis-orthogonal direction
    l[i] = 1;
  }
}

// Scales a regular plane P and light L by powers of two, as far as the declared restrictions
// allow (a unit normal keeps P, a point light with w = 1 keeps L), so that the products P_i L_j
// overflow (the largest one at least 2^max_exponent) or underflow (all below the smallest
// normal value). The shadow point does not move: P and L are homogeneous. False when the draw
// cannot be scaled so exactly; the caller draws again.
inline bool scale_out_of_range(case_rng& r, const conventions& req, double* p, double* l) {
  const bool plane_scales = !req.unit_normal, light_scales = !req.point_light_only;
  const int mp = top_exponent(p, 4), ml = top_exponent(l, 4);
  // Underflow needs both scaled down far enough to keep their own bits.
  const bool overflow = !(plane_scales && light_scales) || (r.raw() & 1);
  const int shift = overflow ? max_exponent(r) - (mp + ml) + static_cast<int>(r.integer(0, 2))
                             : min_normal_exponent(r) - (mp + ml) - 2 - static_cast<int>(r.integer(0, 2));
  int a = 0, b = 0;  // P by 2^a, L by 2^b
  if (plane_scales && light_scales) {
    a = shift / 2;
    b = shift - a;
  } else if (plane_scales) {
    a = shift;
  } else if (light_scales) {
    b = shift;
  } else {  // a unit normal and a point light: only the plane's offset d can grow
    if (p[3] == 0) p[3] = 1;
    a = max_exponent(r) - 1 - top_exponent(p + 3, 1);
    return ml >= 1 && scale_exactly(r, p + 3, 1, a);
  }
  if (mp + a > max_exponent(r) - 1 || ml + b > max_exponent(r) - 1) return false;
  double pp[4], ll[4];
  std::copy(p, p + 4, pp);
  std::copy(l, l + 4, ll);
  if (!scale_exactly(r, pp, 4, a) || !scale_exactly(r, ll, 4, b)) return false;
  std::copy(pp, pp + 4, p);
  std::copy(ll, ll + 4, l);
  return true;
}

inline void shadow_inputs(case_rng& r, input_class cls, const conventions& req, double* p, double* l) {
  const bool directional = !req.point_light_only && (req.directional_only || (r.raw() & 1));
  switch (cls) {
    case input_class::range:
      do {
        random_plane(r, p);
        random_light(r, l, directional);
      } while (!scale_out_of_range(r, req, p, l));
      break;
    case input_class::regular:
      random_plane(r, p);
      random_light(r, l, directional);
      break;
    case input_class::near_degenerate:
      random_plane(r, p);
      random_light(r, l, directional);
      near_plane(r, p, l);  // light nearly parallel to (directional) or nearly on the plane
      if (l[0] == 0 && l[1] == 0 && l[2] == 0 && l[3] == 0) l[0] = 1;
      break;
    case input_class::degenerate:
      if (directional) {
        random_plane(r, p);
        exact_orthogonal(r, p, l);
        l[3] = 0;
      } else {
        integer_plane_through(r, p, l);
        l[3] = 1;
      }
      break;
  }
}

// A view volume l, r, b, t, n, f: regular boxes; nearly flat ones (one extent a relative
// 2^-k of its position, or far/near large); exactly flat ones (l = r, b = t or n = f); boxes
// scaled out of the type's range.
inline void box_inputs(case_rng& r, input_class cls, const conventions& req, double* x) {
  auto positive = [&](int emin, int emax) {
    double v = 0;
    while (v == 0) v = std::fabs(r.value(emin, emax));
    return v;
  };
  x[0] = r.value();
  x[1] = x[0] + positive(-1, 2);
  x[2] = r.value();
  x[3] = x[2] + positive(-1, 2);
  x[4] = positive(-4, 0);
  x[5] = x[4] + positive(0, 6);
  const int which = static_cast<int>(r.integer(0, 2));
  if (cls == input_class::near_degenerate) {
    const int k = static_cast<int>(r.integer(4, r.bits() - 1));
    if (which == 2 && (r.raw() & 1)) {
      x[5] = x[4] * std::ldexp(1.0, static_cast<int>(r.integer(4, r.bits() - 1)));  // far ≫ near
    } else {
      const int lo = 2 * which;  // l/r, b/t or n/f pair
      x[lo + 1] = x[lo] + std::ldexp(std::fabs(x[lo]) + 1, -k);
    }
  } else if (cls == input_class::degenerate) {
    x[2 * which + 1] = x[2 * which];
  }
  for (int i = 0; i < 6; ++i) x[i] = r.fit(x[i]);
  if (req.symmetric_view) {  // builders taking width and height: l = −r, b = −t exactly
    x[0] = -std::fabs(x[1]);
    x[1] = std::fabs(x[1]);
    x[2] = -std::fabs(x[3]);
    x[3] = std::fabs(x[3]);
    if (cls == input_class::degenerate && which < 2) x[2 * which] = x[2 * which + 1] = 0;
  }
  if (cls == input_class::range) {
    // The whole box scaled so that its largest coordinate is near the largest finite value
    // (r − l, f + n and 2 f n overflow) or so small that 2 f n underflows; the projection is
    // unchanged up to the scale of its translations and of 2/(r − l).
    const int top = top_exponent(x, 6);
    const int e = (r.raw() & 1) ? max_exponent(r) - 1 - top
                                : min_normal_exponent(r) / 2 - top - 1 - static_cast<int>(r.integer(0, 2));
    if (!scale_exactly(r, x, 6, e)) box_inputs(r, cls, req, x);  // draw again
  }
}

}  // namespace shadowproof::detail
