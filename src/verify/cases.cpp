// Deterministic test cases for the grader, in three classes of closeness to degeneracy.
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include <gmpxx.h>

#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"
#include "shadowproof/core/ulp.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/protocol.h"

namespace shadowproof {
namespace {

// Our own mapping from the 64-bit generator to numbers: std::uniform_*_distribution is
// implementation-defined, and case files must be identical on every platform.
class case_rng {
 public:
  case_rng(std::uint64_t seed, scalar_type t) : gen_(seed), bits_(t == scalar_type::f32 ? 24 : 53) {}

  std::uint64_t raw() { return gen_(); }
  /// Uniform integer in [lo, hi] (modulo bias below 2^-40 for our small ranges).
  long long integer(long long lo, long long hi) {
    return lo + static_cast<long long>(raw() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  /// A random number with up to `bits_` significant bits, magnitude below 2^e for e in
  /// [emin, emax]: exactly representable in the case's type.
  double value(int emin = -2, int emax = 2) {
    const std::uint64_t r = raw();
    const double m = static_cast<double>(r >> (64 - bits_));
    const int e = static_cast<int>(integer(emin, emax));
    const double v = std::ldexp(m, e - bits_);
    return (raw() & 1) ? -v : v;
  }
  /// Rounds a double to the case's type (the generator's own arithmetic is not graded).
  double fit(double x) const { return bits_ == 24 ? static_cast<double>(static_cast<float>(x)) : x; }
  int bits() const { return bits_; }

  /// Planes must have a unit normal (±1 on one axis), for routines that require one.
  bool unit_normal = false;

 private:
  std::mt19937_64 gen_;
  int bits_;
};

void random_normal(case_rng& r, double* n) {
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
void random_plane(case_rng& r, double* p) {
  random_normal(r, p);
  p[3] = r.value();
}

// A light: directional (w = 0) or a point light (w = 1).
void random_light(case_rng& r, double* l, bool directional) {
  do {
    for (int i = 0; i < 3; ++i) l[i] = r.value(0, 3);
  } while (l[0] == 0 && l[1] == 0 && l[2] == 0);
  l[3] = directional ? 0 : 1;
}

long double dot3l(const double* a, const double* b) {
  return static_cast<long double>(a[0]) * b[0] + static_cast<long double>(a[1]) * b[1] +
         static_cast<long double>(a[2]) * b[2];
}

// Moves the light (or point) x = (x, w) to within a relative 2^-k of the plane P, k random:
// x − ((P·x)/(n·n) − 2^-k |x| / |n|) n, rounded to the case's type.
void near_plane(case_rng& r, const double* p, double* x) {
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
void integer_plane_through(case_rng& r, double* p, double* x) {
  if (r.unit_normal) {
    random_normal(r, p);
  } else do {
    for (int i = 0; i < 3; ++i) p[i] = static_cast<double>(r.integer(-100, 100));
  } while (p[0] == 0 && p[1] == 0 && p[2] == 0);
  for (int i = 0; i < 3; ++i) x[i] = static_cast<double>(r.integer(-100, 100));
  p[3] = -(p[0] * x[0] + p[1] * x[1] + p[2] * x[2]);
}

// A direction exactly orthogonal to n: (n_j, −n_i) on a random pair of axes, 0 elsewhere.
void exact_orthogonal(case_rng& r, const double* n, double* l) {
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

void shadow_inputs(case_rng& r, input_class cls, const conventions& req, double* p, double* l) {
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

void point_inputs(case_rng& r, input_class cls, const conventions& req, double* in) {
  const bool directional_only = req.directional_only;
  double* p = in;
  double* l = in + 4;
  double* v = in + 8;
  const int flavour = static_cast<int>(r.integer(0, 2));
  if (cls == input_class::regular) {
    shadow_inputs(r, cls, req, p, l);
    for (int i = 0; i < 3; ++i) v[i] = r.value();
    return;
  }
  if (cls == input_class::near_degenerate) {
    shadow_inputs(r, flavour == 0 ? input_class::near_degenerate : input_class::regular,
                  req, p, l);
    for (int i = 0; i < 3; ++i) v[i] = r.value();
    if (flavour == 1) {  // point nearly on the receiver
      double x[4] = {v[0], v[1], v[2], 1};
      near_plane(r, p, x);
      for (int i = 0; i < 3; ++i) v[i] = x[i];
    } else if (flavour == 2 && l[3] != 0) {  // point nearly level with the light
      double shifted[4] = {p[0], p[1], p[2], p[3] - (p[0] * l[0] + p[1] * l[1] + p[2] * l[2] + p[3])};
      double x[4] = {v[0], v[1], v[2], 1};
      near_plane(r, shifted, x);
      for (int i = 0; i < 3; ++i) v[i] = x[i];
    }
    return;
  }
  // Degenerate: exactly on the receiver, exactly level with a point light (image at
  // infinity), or a directional light exactly parallel to the receiver.
  if (flavour == 0) {
    integer_plane_through(r, p, v);
    random_light(r, l, !req.point_light_only && (directional_only || (r.raw() & 1)));
  } else if (flavour == 1 && !directional_only) {
    integer_plane_through(r, p, l);
    for (int i = 0; i < 3; ++i) l[i] += static_cast<double>(r.integer(1, 50));  // off the plane
    l[3] = 1;
    double offset[3];
    exact_orthogonal(r, p, offset);
    const double k = static_cast<double>(r.integer(1, 20));
    for (int i = 0; i < 3; ++i) v[i] = l[i] + k * offset[i];
  } else if (!req.point_light_only) {
    random_plane(r, p);
    exact_orthogonal(r, p, l);
    l[3] = 0;
    for (int i = 0; i < 3; ++i) v[i] = r.value();
  } else {  // point light exactly on the receiver
    integer_plane_through(r, p, l);
    l[3] = 1;
    for (int i = 0; i < 3; ++i) v[i] = r.value();
  }
}

void reflection_inputs(case_rng& r, input_class cls, double* p) {
  random_plane(r, p);
  if (cls == input_class::near_degenerate) {
    // The mirror far from the origin compared with its normal: the translation column is
    // a large multiple of n and the linear block must still be exact to within an ulp.
    p[3] = std::ldexp(p[3] == 0 ? 1.0 : p[3], static_cast<int>(r.integer(8, 40)));
  } else if (cls == input_class::degenerate) {
    // |n|² under- or overflows the type while the mirror itself is an ordinary plane.
    const int e = r.bits() == 24 ? 70 : 540;
    const int s = (r.raw() & 1) ? e : -e;
    for (int i = 0; i < 4; ++i) p[i] = std::ldexp(p[i], s);
  }
}

// A view volume l, r, b, t, n, f: regular boxes; nearly flat ones (one extent a relative
// 2^-k of its position, or far/near huge); exactly flat ones (l = r, b = t or n = f).
void box_inputs(case_rng& r, input_class cls, const conventions& req, double* x) {
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

// A 3x3 linear map: regular; nearly singular (third row = first + second, rounded, plus a
// relative 2^-k); exactly singular (third row = 2 × first row, exact).
void matrix_inputs(case_rng& r, input_class cls, double* m) {
  for (int i = 0; i < 9; ++i) m[i] = r.value();
  if (cls == input_class::near_degenerate) {
    const int k = static_cast<int>(r.integer(4, r.bits() + 4));
    for (int j = 0; j < 3; ++j) m[6 + j] = r.fit(m[j] + m[3 + j] + std::ldexp(r.value(), -k));
  } else if (cls == input_class::degenerate) {
    for (int j = 0; j < 3; ++j) m[6 + j] = 2 * m[j];
  }
}

}  // namespace

std::vector<test_case> generate_cases(operation op, scalar_type type, std::size_t count,
                                      std::uint64_t seed, std::optional<input_class> cls,
                                      const conventions& requirements, std::uint64_t first_id) {
  case_rng r(seed, type);
  r.unit_normal = requirements.unit_normal;
  std::vector<test_case> cases;
  cases.reserve(count);
  const input_class cycle[3] = {input_class::regular, input_class::near_degenerate, input_class::degenerate};
  for (std::size_t i = 0; i < count; ++i) {
    test_case c;
    c.id = first_id + i;
    c.op = op;
    c.type = type;
    c.cls = cls ? *cls : cycle[i % 3];
    c.inputs.assign(signature(op).input_count, 0.0);
    switch (op) {
      case operation::shadow_matrix:
        shadow_inputs(r, c.cls, requirements, c.inputs.data(), c.inputs.data() + 4);
        break;
      case operation::shadow_point:
        point_inputs(r, c.cls, requirements, c.inputs.data());
        break;
      case operation::reflection_matrix:
        reflection_inputs(r, c.cls, c.inputs.data());
        break;
      case operation::ortho:
      case operation::frustum:
        box_inputs(r, c.cls, requirements, c.inputs.data());
        break;
      case operation::normal_matrix:
        matrix_inputs(r, c.cls, c.inputs.data());
        break;
    }
    // A clamping shader assumes the light on the positive side of the receiver (above the
    // ground): orient the plane so, exactly (negating is exact, the sign is decided exactly).
    if (op == operation::shadow_point && requirements.clamps_behind_receiver) {
      rational s = 0;
      for (std::size_t k = 0; k < 4; ++k) s += exact_value(c.inputs[k]) * exact_value(c.inputs[4 + k]);
      if (sgn(s) < 0)
        for (std::size_t k = 0; k < 4; ++k) c.inputs[k] = -c.inputs[k];
    }
    for (double& x : c.inputs)
      if (x == 0) x = 0.0;  // no −0: the case file's exact decimals could not tell them apart
    cases.push_back(std::move(c));
  }
  return cases;
}

double closeness_to_degeneracy(const test_case& c) {
  const double* in = c.inputs.data();
  auto norm4 = [](const double* x, std::size_t n) {
    long double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += static_cast<long double>(x[i]) * x[i];
    return std::sqrt(s);
  };
  auto ratio = [&](const double* a, const double* b, std::size_t nb) {
    long double d = 0;
    for (std::size_t i = 0; i < nb; ++i) d += static_cast<long double>(a[i]) * b[i];
    if (nb == 3) d += a[3];  // b is a finite point (x, y, z, 1)
    const long double nbn = nb == 3 ? std::sqrt(norm4(b, 3) * norm4(b, 3) + 1) : norm4(b, 4);
    if (d == 0) return -std::numeric_limits<double>::infinity();
    return static_cast<double>(std::log2(std::fabs(d) / (norm4(a, 4) * nbn)));
  };
  switch (c.op) {
    case operation::shadow_matrix: return ratio(in, in + 4, 4);
    case operation::shadow_point: return std::min(ratio(in, in + 4, 4), ratio(in, in + 8, 3));
    case operation::reflection_matrix:
      return static_cast<double>(std::log2(norm4(in, 3) / norm4(in, 4)));
    case operation::ortho:
    case operation::frustum: {
      // Relative extent of the flattest side of the view volume.
      double worst = std::numeric_limits<double>::infinity();
      for (int i = 0; i < 6; i += 2) {
        const long double extent = std::fabs(static_cast<long double>(in[i + 1]) - in[i]);
        const long double scale = std::fabs(static_cast<long double>(in[i])) + std::fabs(static_cast<long double>(in[i + 1]));
        if (extent == 0) return -std::numeric_limits<double>::infinity();
        worst = std::min(worst, static_cast<double>(std::log2(extent / scale)));
      }
      return worst;
    }
    case operation::normal_matrix: {
      // |det A| / (|row 0| |row 1| |row 2|): 1 for orthogonal rows, 0 for singular A.
      const long double det = static_cast<long double>(in[0]) * (static_cast<long double>(in[4]) * in[8] - static_cast<long double>(in[5]) * in[7]) -
                              static_cast<long double>(in[1]) * (static_cast<long double>(in[3]) * in[8] - static_cast<long double>(in[5]) * in[6]) +
                              static_cast<long double>(in[2]) * (static_cast<long double>(in[3]) * in[7] - static_cast<long double>(in[4]) * in[6]);
      if (det == 0) return -std::numeric_limits<double>::infinity();
      return static_cast<double>(std::log2(std::fabs(det) / (norm4(in, 3) * norm4(in + 3, 3) * norm4(in + 6, 3))));
    }
  }
  return 0;
}

}  // namespace shadowproof
