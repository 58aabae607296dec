#pragma once
// What every operation's case generator shares: the random source with our own mapping to
// numbers exactly representable in the case's type, random planes and lights, and the exact
// constructions of degenerate configurations (a point exactly on a plane, a direction exactly
// orthogonal to a normal, a flat view volume).
#include <cmath>
#include <cstdint>

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

// Moves the light (or point) x = (x, w) to within a relative 2^-k of the plane P, k random:
// x − ((P·x)/(n·n) − 2^-k |x| / |n|) n, rounded to the case's type.
inline void near_plane(case_rng& r, const double* p, double* x) {
  const long double nn = dot3l(p, p);
  const long double px = dot3l(p, x) + static_cast<long double>(p[3]) * x[3];
  const long double norm_x = std::sqrt(dot3l(x, x) + static_cast<long double>(x[3]) * x[3]);
  const int k = static_cast<int>(r.integer(4, r.bits() + 8));
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

inline void shadow_inputs(case_rng& r, input_class cls, const conventions& req, double* p, double* l) {
  const bool directional = !req.point_light_only && (req.directional_only || (r.raw() & 1));
  switch (cls) {
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
// 2^-k of its position, or far/near huge); exactly flat ones (l = r, b = t or n = f).
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
      x[5] = x[4] * std::ldexp(1.0, static_cast<int>(r.integer(10, r.bits() == 24 ? 60 : 400)));  // far ≫ near
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
}

}  // namespace shadowproof::detail
