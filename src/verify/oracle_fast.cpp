// Dedicated f32 kernels of the filtered oracle (see oracle_fast.h). The library is built for
// baseline x86-64, so no multiply-add is contracted into an FMA here and the error-free
// transformations below hold as written.
#include "oracle_fast.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace shadowproof::detail {
namespace {

constexpr double u = 0x1p-53;  // unit roundoff of double
constexpr double tiny = std::numeric_limits<double>::denorm_min();
constexpr double inflate = 1 + 0x1p-40;  // covers the rounding of a bound's own computation

// Knuth's TwoSum: s + e = a + b exactly.
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

// Veltkamp's split: hi + lo = x exactly, each with at most 26 significant bits, so the product
// of either with a float (24 bits) is exact in a double. No overflow for the magnitudes that
// f32 inputs produce (below 2^900).
inline void split(double x, double& hi, double& lo) {
  const double c = 134217729.0 * x;  // 2^27 + 1
  hi = c - (c - x);
  lo = x - hi;
}

// Dekker's product: p + e = a b exactly, for the f32-derived magnitudes (no under/overflow).
inline void two_product(double a, double b, double& p, double& e) {
  p = a * b;
  double a1, a2, b1, b2;
  split(a, a1, a2);
  split(b, b1, b2);
  e = ((a1 * b1 - p) + a1 * b2 + a2 * b1) + a2 * b2;
}

// A sum of doubles kept as hi + lo with a rigorous bound on how far it is from the exact sum:
// every term goes through TwoSum into hi, its exact error into lo (added in round-to-nearest,
// at most (n + 1) u Σ|error| off), and terms that were already approximate add their own bound.
struct accumulator {
  double hi = 0, lo = 0, error_mass = 0, extra = 0;
  int n = 0;

  void add(double x) {  // x exact
    double s, e;
    two_sum(hi, x, s, e);
    hi = s;
    lo += e;
    error_mass += std::fabs(e);
    ++n;
  }
  void add(double x, double bound) {  // the exact term lies within x ± bound
    add(x);
    extra += bound;
  }
  // x · f exactly, f with at most 24 significant bits (a float); with `bound`, x stands for
  // a value within x ± bound, so the term for f times that value is within ± |f| bound.
  void add_product(double x, double f, double bound = 0) {
    double x1, x2;
    split(x, x1, x2);
    add(x1 * f);
    add(x2 * f);
    if (bound != 0) extra += std::fabs(f) * bound * inflate + tiny;
  }
  bool exact() const { return error_mass == 0 && extra == 0; }  // then lo = 0, sum = hi
  // Bound on |(hi + lo) − exact sum|.
  double lo_bound() const {
    return exact() ? 0.0 : ((n + 1) * u * error_mass + extra) * inflate + (n + 1) * tiny;
  }
  // The sum rounded once, y, and a bound E with the exact sum in [y − E, y + E].
  void value(double& y, double& bound) const {
    if (exact()) {
      y = hi;
      bound = 0;
      return;
    }
    y = hi + lo;
    bound = (u * std::fabs(y) + lo_bound()) * inflate + tiny;
  }
  // Sign of the exact sum: −1, 0, +1, or 2 when undecided.
  int sign() const {
    double y, bound;
    value(y, bound);
    if (bound == 0) return y > 0 ? 1 : (y < 0 ? -1 : 0);
    if (std::fabs(y) > bound) return y > 0 ? 1 : -1;
    return 2;
  }
};

inline double down(double r) { return r - (std::fabs(r) * 2 * u + tiny); }
inline double up(double r) { return r + (std::fabs(r) * 2 * u + tiny); }

// The float nearest to every point of [y − bound, y + bound], if they share one.
bool round_to_float(double y, double bound, double& out) {
  if (!std::isfinite(y) || !(bound >= 0)) return false;
  float a;
  if (bound == 0) {
    a = static_cast<float>(y);  // one correct rounding, ties to even
  } else {
    // Round-to-nearest is monotone: equal roundings of both ends decide every point.
    a = static_cast<float>(down(y - bound));
    const float b = static_cast<float>(up(y + bound));
    if (!(a == b)) return false;
  }
  out = a == 0 ? 0.0 : static_cast<double>(a);
  return true;
}

// The float nearest to every point within q ± |q| relative, if they share one. The ends are
// pushed out by 4u |q| more, which covers the rounding of their own computation.
[[gnu::always_inline]] inline bool round_to_float_relative(double q, double relative, double& out) {
  const double reach = std::fabs(q) * (relative + 4 * u) + tiny;
  const float a = static_cast<float>(q - reach), b = static_cast<float>(q + reach);
  if (!(a == b)) return false;
  out = a == 0 ? 0.0 : static_cast<double>(a);
  return true;
}

bool round_to_float(const accumulator& acc, double& out) {
  double y, bound;
  acc.value(y, bound);
  return round_to_float(y, bound, out);
}

// Recursive summation of n ≤ 4 exact terms: the sum y and the bound γ_{n−1} Σ|t_i| on its
// error (Higham, Accuracy and Stability of Numerical Algorithms, §4.2), pushed out a little
// further for the rounding of the bound itself.
template <int n>
void quick_sum(const double* t, double& y, double& bound) {
  y = t[0];
  double mass = std::fabs(t[0]);
  for (int i = 1; i < n; ++i) {
    y += t[i];
    mass += std::fabs(t[i]);
  }
  bound = mass * ((n - 1) * u) * (1 + 0x1p-40) + tiny;
}

// The float nearest to the exact sum of n exact terms: first from the recursive sum and its
// bound, then, when that straddles a rounding boundary, from the accumulator.
template <int n>
bool round_sum_to_float(const double* t, double& out) {
  double y, bound;
  quick_sum<n>(t, y, bound);
  if (y != 0 && round_to_float(y, bound, out)) return true;
  accumulator acc;
  for (int i = 0; i < n; ++i) acc.add(t[i]);
  return round_to_float(acc, out);
}

// A denominator prepared once for several quotients: its value yd within ± ed, the relative
// bound b = ed / |yd| and the reciprocal 1/yd rounded once.
struct denominator {
  double yd = 0, ed = 0, b = 0, inverse = 0;
  double exact_numerator = 0;  // the quotient's relative bound when the numerator is exact
  bool usable = false;
  explicit denominator(const accumulator& den) {
    den.value(yd, ed);
    prepare();
  }
  denominator(double value, double bound) : yd(value), ed(bound) { prepare(); }
  void prepare() {
    if (!(std::fabs(yd) > ed)) return;
    b = ed / std::fabs(yd);
    inverse = 1 / yd;
    usable = b < 0x1p-20 && std::isfinite(inverse);
    exact_numerator = (2 * u + b * (1 + 0x1p-18)) * (1 + 0x1p-30);
  }
};

// The exact quotient num / den rounded to float.
[[gnu::always_inline]] inline bool round_quotient_to_float(double yn, double en, const denominator& den,
                                                           double& out) {
  if (!den.usable) return false;
  if (en == 0 && yn == 0) {
    out = 0;
    return true;
  }
  if (!(std::fabs(yn) > en)) return false;
  // num = yn (1 + α), den = yd (1 + β), |α| ≤ a, |β| ≤ b ≤ 2^-20; q = yn (1/yd) rounded twice
  // is yn/yd (1 + δ), |δ| ≤ 2u + u²; so |num/den − q| ≤ |q| (2u + (a + b)/(1 − b)) (1 + 3u).
  const double q = yn * den.inverse;
  if (!std::isfinite(q)) return false;
  const double relative =
      en == 0 ? den.exact_numerator : (2 * u + (en / std::fabs(yn) + den.b) * (1 + 0x1p-18)) * (1 + 0x1p-30);
  if (round_to_float_relative(q, relative, out)) return true;
  if (en == 0 && den.ed == 0) {  // both exact: is the quotient a double (e.g. a float midpoint)?
    const double qd = yn / den.yd;
    double p, e;
    two_product(qd, den.yd, p, e);
    if (p == yn && e == 0) return round_to_float(qd, 0, out);
  }
  return false;
}

bool round_quotient_to_float(const accumulator& num, const denominator& den, double& out) {
  double yn, en;
  num.value(yn, en);
  return round_quotient_to_float(yn, en, den, out);
}

bool is_float(double x) { return representable_in_float(x); }

// The canonical light: a directional light given along its rays is negated (exact).
void canonical_light(const double* in, const conventions& conv, double* L) {
  const bool flip = conv.light == light_sign::along_rays && in[3] == 0;
  for (int i = 0; i < 3; ++i) L[i] = flip ? -in[i] : in[i];
  L[3] = in[3];
}

// M = (P·L) I − L Pᵀ: off-diagonal entries are one exact product; the diagonal entry i is
// P·L − L_i P_i = Σ_{j≠i} P_j L_j exactly (the same exact value, fewer terms).
bool shadow_matrix_f32(const double* P, const double* L, fast_reference& out) {
  out.count = 16;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      double& v = out.value[r * 4 + c];
      if (r != c) {  // one exact product, below 2^256 in magnitude: one rounding
        const float f = static_cast<float>(-(L[r] * P[c]));
        v = f == 0 ? 0.0 : static_cast<double>(f);
        continue;
      }
      double terms[3];
      for (int j = 0, k = 0; j < 4; ++j)
        if (j != r) terms[k++] = P[j] * L[j];
      if (!round_sum_to_float<3>(terms, v)) return false;
    }
  return true;
}

// M = I − 2 n nᵀ/|n|² with the offset column −2 d n/|n|²: entry (i, j) is
// (δ_ij |n|² − 2 n_i n_j) / |n|², a quotient of exact sums of float products.
bool reflection_matrix_f32(const double* P, fast_reference& out) {
  out.count = 16;
  const double squares[3] = {P[0] * P[0], P[1] * P[1], P[2] * P[2]};
  double y, bound;
  quick_sum<3>(squares, y, bound);  // positive terms: a relative bound of 2u
  const denominator quick(y, bound);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      double& v = out.value[i * 4 + j];
      if (j < i) {  // −2 n_i n_j / |n|² is symmetric in i and j
        v = out.value[j * 4 + i];
        continue;
      }
      double terms[3] = {-2 * (P[i] * P[j]), 0, 0};  // exact
      if (i == j) {
        for (int k = 0; k < 3; ++k) terms[k] = k == i ? -squares[k] : squares[k];
        quick_sum<3>(terms, y, bound);
      } else {
        y = terms[0];
        bound = 0;
      }
      if (round_quotient_to_float(y, bound, quick, v)) continue;
      // Undecided: the same quotient from accumulators, which also see exact zeros and ties.
      accumulator nn, num;
      for (int k = 0; k < 3; ++k) nn.add(squares[k]);
      for (int k = 0; k < (i == j ? 3 : 1); ++k) num.add(terms[k]);
      if (!round_quotient_to_float(num, denominator(nn), v)) return false;
    }
  }
  out.value[12] = out.value[13] = out.value[14] = 0;
  out.value[15] = 1;
  return true;
}

// The same image from plain double arithmetic with a running error bound (Higham's γ_n bounds
// for the dot products, first-order terms for the rest), for cases far enough from every
// degeneracy: false whenever a sign, a zero or a rounding is not clearly decided, and then
// shadow_point_f32 below does it with exact sums.
bool shadow_point_quick_f32(const double* P, const double* L, const double* V3, const conventions& conv,
                            fast_reference& out) {
  out.count = 3;
  const double p[4] = {P[0] * L[0], P[1] * L[1], P[2] * L[2], P[3] * L[3]};
  const double q[4] = {P[0] * V3[0], P[1] * V3[1], P[2] * V3[2], P[3]};
  double s, es, t, et;
  quick_sum<4>(p, s, es);
  quick_sum<4>(q, t, et);
  if (!(std::fabs(s) > es) || !(std::fabs(t) > et)) return false;  // near zero: exact sums decide
  const double w = L[3];
  double D = s, ed = es;
  if (w != 0) {
    const double wt = w * t;
    D = s - wt;
    ed = (es + std::fabs(w) * et + u * (std::fabs(wt) + std::fabs(D))) * inflate;
    if (!(std::fabs(D) > ed)) return false;
  }
  const int ss = s > 0 ? 1 : -1, ts = t > 0 ? 1 : -1, ds = D > 0 ? 1 : -1;
  if (w == 0) {
    out.cls = ts == ss ? point_class::shadow : point_class::behind_receiver;
  } else if (V3[0] * w == L[0] && V3[1] * w == L[1] && V3[2] * w == L[2]) {
    return false;  // the light itself: D = 0, which the bound cannot show
  } else if ((w > 0 ? ts : -ts) != ss) {
    out.cls = point_class::behind_receiver;
  } else {
    out.cls = ds == ss ? point_class::shadow : point_class::beyond_light;
  }
  if (conv.clamps_behind_receiver && *out.cls == point_class::behind_receiver) {
    for (int i = 0; i < 3; ++i) out.value[i] = V3[i] == 0 ? 0.0 : V3[i];
    return true;
  }
  const denominator den(D, ed);
  for (int i = 0; i < 3; ++i) {
    // N_i = s V_i − t L_i from the approximate s and t, each product and the difference
    // rounded once.
    const double a = s * V3[i], b = t * L[i], n = a - b;
    const double rounding = u * (std::fabs(a) + std::fabs(b) + std::fabs(n));
    const double en = (std::fabs(V3[i]) * es + std::fabs(L[i]) * et + rounding) * inflate;
    if (!round_quotient_to_float(n, en, den, out.value[i])) return false;
  }
  return true;
}

// Image of V = (x, y, z, 1): with s = P·L, t = P·V and w = L_3, the image is (s V − t L)
// divided by its w, D = s − w t. s and t are exact sums of float products kept as hi + lo;
// s V_i and t L_i are split so that every product with a float stays exact.
bool shadow_point_f32(const double* P, const double* L, const double* V3, const conventions& conv,
                      fast_reference& out) {
  out.count = 3;
  const double V[4] = {V3[0], V3[1], V3[2], 1};
  accumulator s, t;
  for (int j = 0; j < 4; ++j) {
    s.add(P[j] * L[j]);
    t.add(P[j] * V[j]);
  }
  const int ss = s.sign(), ts = t.sign();
  if (ss == 2 || ts == 2) return false;
  const double w = L[3];
  const bool directional = w == 0;
  // A point on the receiver is its own image, even when the light is parallel to or on the
  // receiver (the whole line then lies in it).
  if (ts == 0) {
    out.cls = ss == 0 ? point_class::line_in_plane : point_class::on_receiver;
    for (int i = 0; i < 3; ++i) out.value[i] = V[i] == 0 ? 0.0 : V[i];
    return true;
  }
  if (ss == 0) {
    out.cls = directional ? point_class::light_parallel : point_class::light_on_plane;
  }
  // D = s − w t, with t's double-double parts split to keep w t exact.
  const double s_bound = s.lo_bound(), t_bound = t.lo_bound();
  accumulator D;
  D.add(s.hi);
  D.add(s.lo, s_bound);
  if (!directional) {
    D.add_product(-t.hi, w);
    D.add_product(-t.lo, w, t_bound);
  }
  const int ds = D.sign();
  if (ds == 2) return false;
  if (ss != 0) {
    if (directional) {
      out.cls = ts == ss ? point_class::shadow : point_class::behind_receiver;
    } else if (V[0] * w == L[0] && V[1] * w == L[1] && V[2] * w == L[2]) {  // exact products
      out.cls = point_class::at_light;
    } else if (ds == 0) {
      out.cls = point_class::at_infinity;  // w t = s
    } else if ((w > 0 ? ts : -ts) != ss) {
      out.cls = point_class::behind_receiver;  // sign(w t) ≠ sign(s)
    } else {
      out.cls = ds == ss ? point_class::shadow : point_class::beyond_light;  // |w t| < |s|
    }
  }
  if (conv.clamps_behind_receiver && *out.cls == point_class::behind_receiver) {
    for (int i = 0; i < 3; ++i) out.value[i] = V[i] == 0 ? 0.0 : V[i];
    return true;
  }
  if (ds == 0) {  // image at infinity or the zero vector: no finite image
    out.defined = false;
    out.value[0] = out.value[1] = out.value[2] = 0;
    return true;
  }
  const denominator den(D);
  for (int i = 0; i < 3; ++i) {
    // N_i = s V_i − t L_i.
    accumulator N;
    N.add_product(s.hi, V[i]);
    N.add_product(s.lo, V[i], s_bound);
    N.add_product(-t.hi, L[i]);
    N.add_product(-t.lo, L[i], t_bound);
    if (!round_quotient_to_float(N, den, out.value[i])) return false;
  }
  return true;
}

// Products rounded in double with their error added to a running bound: enough to decide
// signs that do not cancel to the last bits (the exact ties are recognised before).
struct rounded_sum {
  double sum = 0, bound = 0;
  void add_product(double a, double b) {
    const double p = a * b;
    sum += p;
    bound += (std::fabs(p) + std::fabs(sum)) * u + 2 * tiny;
  }
  int sign() const {
    const double b = bound * (1 + 0x1p-30);
    if (std::fabs(sum) > b) return sum > 0 ? 1 : -1;
    return 2;
  }
};

// Exact sum of exact terms correctly rounded to double: y + r = hi + lo exactly, the exact sum
// is within lo_bound of that, and y is its correct rounding when the whole range lies strictly
// inside half the gap to y's neighbour on each side (gaps halve below a power of two; halving
// is exact, so a sum exactly at a midpoint is never decided here).
// hi + lo ± bound correctly rounded to double: (y, r) = TwoSum(hi, lo), and y is the correct
// rounding when the whole range lies strictly inside half the gap to y's neighbour on each side
// (gaps halve below a power of two; halving is exact, so a midpoint is never decided here).
bool round_pair_to_double(double hi, double lo, double bound, double& out) {
  double y, r;
  two_sum(hi, lo, y, r);
  if (y == 0 || !std::isfinite(y) || !(bound >= 0)) return false;
  const double magnitude = std::fabs(y);
  const double outward = y > 0 ? r : -r;  // r measured away from zero
  // Neighbours of a positive finite double: its bit pattern ± 1 (as std::nextafter, cheaper).
  std::uint64_t bits;
  std::memcpy(&bits, &magnitude, sizeof bits);
  double above, below;
  const std::uint64_t bits_above = bits + 1, bits_below = bits - 1;
  std::memcpy(&above, &bits_above, sizeof above);
  std::memcpy(&below, &bits_below, sizeof below);
  const double half_up = (above - magnitude) / 2;
  const double half_down = (magnitude - below) / 2;
  if (!(outward + bound < half_up && bound - outward < half_down)) return false;
  out = y;
  return true;
}

// An exact sum of exact terms correctly rounded to double.
bool round_to_double(const accumulator& acc, double& out) {
  if (acc.exact()) {
    out = acc.hi == 0 ? 0.0 : acc.hi;
    return true;
  }
  return round_pair_to_double(acc.hi, acc.lo, acc.lo_bound(), out);
}

// Shewchuk's grow-expansion with zero elimination: e[0..m) nonoverlapping, increasing in
// magnitude, summing exactly to the n ≤ 16 terms. Returns m.
int expansion(const double* terms, int n, double* e) {
  int m = 0;
  for (int t = 0; t < n; ++t) {
    double q = terms[t];
    int k = 0;
    for (int i = 0; i < m; ++i) {
      double sum, err;
      two_sum(q, e[i], sum, err);
      q = sum;
      if (err != 0) e[k++] = err;
    }
    if (q != 0) e[k++] = q;
    m = k;
  }
  return m;
}

// The exact sum of n ≤ 16 exact doubles correctly rounded to double, from Shewchuk's
// nonoverlapping expansion (grow-expansion with zero elimination): exact zeros and sums that
// need more than a double-double are decided here too. Its sign is the sum's exact sign.
bool round_to_double_exact(const double* terms, int n, double& out) {
  if (n > 16) return false;
  double e[16];
  const int m = expansion(terms, n, e);
  if (m == 0) {
    out = 0;
    return true;
  }
  if (m <= 2) {  // the sum of two doubles, rounded once by the addition itself
    const double y = m == 1 ? e[0] : e[1] + e[0];
    out = y == 0 ? 0.0 : y;
    return std::isfinite(y);
  }
  accumulator acc;
  acc.add(e[m - 1]);
  for (int i = m - 2; i >= 0; --i) acc.add(e[i]);
  return round_to_double(acc, out);
}

// Doubles whose products (and Dekker's split of them) neither overflow nor underflow.
bool moderate(double x) { return x == 0 || (std::fabs(x) > 0x1p-400 && std::fabs(x) < 0x1p400); }

// f64 shadow matrix: off-diagonal entries −L_r P_c are one IEEE product, correctly rounded by
// definition; a diagonal entry Σ_{j≠r} P_j L_j is a sum of three products, each split exactly
// into two doubles by Dekker's product, and rounded once from the exact accumulator.
bool shadow_matrix_f64(const double* P, const double* L, fast_reference& out) {
  for (int i = 0; i < 4; ++i)
    if (!moderate(P[i]) || !moderate(L[i])) return false;
  out.count = 16;
  double p[4], e[4];
  for (int j = 0; j < 4; ++j) two_product(P[j], L[j], p[j], e[j]);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      double& v = out.value[r * 4 + c];
      if (r != c) {
        const double x = -(L[r] * P[c]);
        v = x == 0 ? 0.0 : x;
        continue;
      }
      accumulator acc;
      double terms[6];
      int n = 0;
      for (int j = 0; j < 4; ++j)
        if (j != r) {
          acc.add(p[j]);
          acc.add(e[j]);
          terms[n++] = p[j];
          terms[n++] = e[j];
        }
      if (!round_to_double(acc, v) && !round_to_double_exact(terms, n, v)) return false;
    }
  return true;
}

// An exact sum as hi + lo within ± bound, hi and lo its two largest expansion components (so
// the bound is below 2^-100 of the sum), and its exact sign.
struct exact_pair {
  double hi = 0, lo = 0, bound = 0;
  int sign = 0;
  exact_pair(const double* terms, int n) {
    double e[16];
    const int m = expansion(terms, n, e);
    if (m == 0) return;
    hi = e[m - 1];
    lo = m >= 2 ? e[m - 2] : 0;
    for (int i = 0; i + 2 < m; ++i) bound += std::fabs(e[i]);
    bound *= inflate;
    sign = hi > 0 ? 1 : -1;
  }
};

// x · f for doubles x and f, added exactly as Dekker's two terms.
void add_product_exact(accumulator& acc, double x, double f) {
  double p, e;
  two_product(x, f, p, e);
  acc.add(p);
  acc.add(e);
}

// The exact quotient num / den correctly rounded to double, num within num.hi + num.lo ±
// n_bound, den = den.hi (1 + β) with |β| ≤ b: q1 = num.hi / den.hi, the remainder
// num − q1 den from Dekker products, and num/den = q1 + rem/den to double-double accuracy.
bool round_quotient_to_double(const exact_pair& num, double n_bound, const exact_pair& den, double b, double& out) {
  const double q1 = num.hi / den.hi;
  if (!(q1 != 0 && std::fabs(q1) > 0x1p-150 && std::fabs(q1) < 0x1p150)) return false;
  accumulator rem;
  rem.add(num.hi);
  rem.add(num.lo);
  add_product_exact(rem, -q1, den.hi);
  add_product_exact(rem, -q1, den.lo);
  double ry, re;
  rem.value(ry, re);
  re = (re + n_bound + std::fabs(q1) * den.bound) * inflate;
  // q2 = ry / den.hi rounded once; |rem/den − q2| ≤ |q2| (1 + 2u) (b (1 + 2b) + u) + re (1 + 2b) / |den.hi|.
  const double q2 = ry / den.hi;
  const double bound =
      ((std::fabs(q2) * (1 + 2 * u)) * (b * (1 + 2 * b) + u) + re / std::fabs(den.hi) * (1 + 2 * b)) * inflate + tiny;
  return round_pair_to_double(q1, q2, bound, out);
}

// f64 reflection: entry (i, j) is (δ_ij |n|² − 2 n_i n_j) / |n|², numerator and denominator exact
// expansions of Dekker products, the quotient as above.
bool reflection_matrix_f64(const double* P, fast_reference& out) {
  for (int i = 0; i < 4; ++i)
    if (!(P[i] == 0 || (std::fabs(P[i]) > 0x1p-150 && std::fabs(P[i]) < 0x1p150))) return false;
  out.count = 16;
  double sq[3][2];
  double nterms[6];
  for (int k = 0; k < 3; ++k) {
    two_product(P[k], P[k], sq[k][0], sq[k][1]);
    nterms[2 * k] = sq[k][0];
    nterms[2 * k + 1] = sq[k][1];
  }
  const exact_pair nn(nterms, 6);
  if (nn.sign <= 0) return false;
  const double b = (std::fabs(nn.lo) + nn.bound) / nn.hi * inflate;
  if (!(b < 0x1p-20)) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) {
      double& v = out.value[i * 4 + j];
      if (j < i) {  // symmetric
        v = out.value[j * 4 + i];
        continue;
      }
      double terms[6];
      int n = 0;
      if (i == j) {
        for (int k = 0; k < 3; ++k) {
          const double sign = k == i ? -1 : 1;
          terms[n++] = sign * sq[k][0];
          terms[n++] = sign * sq[k][1];
        }
      } else {
        two_product(-2 * P[i], P[j], terms[0], terms[1]);
        n = 2;
      }
      const exact_pair num(terms, n);
      if (num.sign == 0) {
        v = 0;
        continue;
      }
      if (!round_quotient_to_double(num, 0, nn, b, v)) return false;
    }
  out.value[12] = out.value[13] = out.value[14] = 0;
  out.value[15] = 1;
  return true;
}

// f64 image of V = (x, y, z, 1) for w ∈ {0, 1} (the lights the generators make; others go to
// the generic oracle): s = P·L and t = P·V are exact sums of Dekker products, D = s − w t is
// their exact difference, N_i = s V_i − t L_i the double-double s and t times V_i and L_i (again
// Dekker products) plus their bounds, and N_i / D is q1 + rem / D with q1 = N.hi / D.hi and the
// remainder N − q1 D from Dekker products again: a double-double quotient with a bound, rounded
// to double by the half-gap test.
bool shadow_point_f64(const double* P, const double* L, const double* V3, const conventions& conv,
                      fast_reference& out) {
  auto modest = [](double x) { return x == 0 || (std::fabs(x) > 0x1p-150 && std::fabs(x) < 0x1p150); };
  for (int i = 0; i < 4; ++i)
    if (!modest(P[i]) || !modest(L[i])) return false;
  for (int i = 0; i < 3; ++i)
    if (!modest(V3[i])) return false;
  const double w = L[3];
  if (w != 0 && w != 1) return false;
  out.count = 3;
  const double V[4] = {V3[0], V3[1], V3[2], 1};
  double sterms[8], tterms[8], dterms[16];
  int nd = 0;
  for (int j = 0; j < 4; ++j) {
    two_product(P[j], L[j], sterms[2 * j], sterms[2 * j + 1]);
    two_product(P[j], V[j], tterms[2 * j], tterms[2 * j + 1]);
  }
  for (int k = 0; k < 8; ++k) {
    dterms[nd++] = sterms[k];
    if (w != 0) dterms[nd++] = -tterms[k];
  }
  // Exact expansions: near-degenerate cases cancel s, t or D far below what a double-double
  // accumulator's bound can resolve.
  const exact_pair s(sterms, 8), t(tterms, 8), D(dterms, nd);
  const int ss = s.sign, ts = t.sign, ds = D.sign;
  const bool directional = w == 0;
  if (ts == 0) {  // a point on the receiver is its own image (see shadow_point_f32)
    out.cls = ss == 0 ? point_class::line_in_plane : point_class::on_receiver;
    for (int i = 0; i < 3; ++i) out.value[i] = V[i] == 0 ? 0.0 : V[i];
    return true;
  }
  if (ss == 0) {
    out.cls = directional ? point_class::light_parallel : point_class::light_on_plane;
  } else if (directional) {
    out.cls = ts == ss ? point_class::shadow : point_class::behind_receiver;
  } else if (V[0] == L[0] && V[1] == L[1] && V[2] == L[2]) {  // w = 1
    out.cls = point_class::at_light;
  } else if (ds == 0) {
    out.cls = point_class::at_infinity;
  } else if (ts != ss) {
    out.cls = point_class::behind_receiver;
  } else {
    out.cls = ds == ss ? point_class::shadow : point_class::beyond_light;
  }
  if (conv.clamps_behind_receiver && *out.cls == point_class::behind_receiver) {
    for (int i = 0; i < 3; ++i) out.value[i] = V[i] == 0 ? 0.0 : V[i];
    return true;
  }
  if (ds == 0) {
    out.defined = false;
    out.value[0] = out.value[1] = out.value[2] = 0;
    return true;
  }
  const double d_bound = D.bound;
  // D = D.hi (1 + β) with |β| ≤ b.
  const double b = (std::fabs(D.lo) + d_bound) / std::fabs(D.hi) * inflate;
  if (!(b < 0x1p-20)) return false;
  for (int i = 0; i < 3; ++i) {
    // N_i = s V_i − t L_i: the pairs of s and t times V_i and L_i, exactly, plus their bounds.
    double nterms[16];
    two_product(s.hi, V[i], nterms[0], nterms[1]);
    two_product(s.lo, V[i], nterms[2], nterms[3]);
    two_product(-t.hi, L[i], nterms[4], nterms[5]);
    two_product(-t.lo, L[i], nterms[6], nterms[7]);
    const exact_pair N(nterms, 8);
    const double n_bound = (N.bound + (std::fabs(V[i]) * s.bound + std::fabs(L[i]) * t.bound) * inflate) * inflate;
    if (N.sign == 0 && n_bound == 0) {
      out.value[i] = 0;
      continue;
    }
    if (!round_quotient_to_double(N, n_bound, D, b, out.value[i])) return false;
  }
  return true;
}

bool image_class_of(const double* in, const conventions& conv, const double* got, image_class& out);

}  // namespace

bool fast_shadow_matrix_f64(const double* in, const conventions& conv, fast_reference& out) {
  double L[4];
  canonical_light(in + 4, conv, L);
  return shadow_matrix_f64(in, L, out);
}

bool fast_shadow_point_f64(const double* in, const conventions& conv, fast_reference& out) {
  double L[4];
  canonical_light(in + 4, conv, L);
  return shadow_point_f64(in, L, in + 8, conv, out);
}

bool fast_reflection_matrix_f64(const double* in, const conventions&, fast_reference& out) {
  return reflection_matrix_f64(in, out);
}

bool fast_plane_value_f64(const double* in, const double* got, double& out) {
  double terms[7];
  for (int i = 0; i < 3; ++i) {
    if (!moderate(got[i])) return false;
    two_product(in[i], got[i], terms[2 * i], terms[2 * i + 1]);
  }
  for (int i = 0; i < 4; ++i)
    if (!moderate(in[i])) return false;
  terms[6] = in[3];
  accumulator acc;
  for (double x : terms) acc.add(x);
  return round_to_double(acc, out) || round_to_double_exact(terms, 7, out);
}

bool fast_shadow_matrix_f32(const double* in, const conventions& conv, fast_reference& out) {
  double L[4];
  canonical_light(in + 4, conv, L);
  return shadow_matrix_f32(in, L, out);
}

bool fast_shadow_point_f32(const double* in, const conventions& conv, fast_reference& out) {
  double L[4];
  canonical_light(in + 4, conv, L);
  if (shadow_point_quick_f32(in, L, in + 8, conv, out)) return true;
  out = fast_reference{};
  return shadow_point_f32(in, L, in + 8, conv, out);
}

bool fast_reflection_matrix_f32(const double* in, const conventions&, fast_reference& out) {
  return reflection_matrix_f32(in, out);
}

bool fast_image_class_f32(const double* in, const conventions& conv, const double* got, image_class& out) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(got[i])) {
      out = image_class::nonfinite;
      return true;
    }
    if (!is_float(got[i])) return false;
  }
  return image_class_of(in, conv, got, out);
}

bool fast_image_class_f64(const double* in, const conventions& conv, const double* got, image_class& out) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(got[i])) {
      out = image_class::nonfinite;
      return true;
    }
  // w V_i and w G_i must stay exact (w ∈ {0, 1}), products far from under- and overflow.
  if (in[7] != 0 && in[7] != 1) return false;
  for (int i = 0; i < 11; ++i)
    if (!moderate(in[i]) || (i < 3 && !moderate(got[i]))) return false;
  return image_class_of(in, conv, got, out);
}

namespace {

// The class of a finite image whose products w V_i and w G_i are exact doubles.
bool image_class_of(const double* in, const conventions& conv, const double* got, image_class& out) {
  double L[4];
  canonical_light(in + 4, conv, L);
  const double* V = in + 8;
  const bool same = got[0] == V[0] && got[1] == V[1] && got[2] == V[2];
  const double w = L[3];
  if (w == 0) {
    // k = (V − G)·L: the differences are exact pairs, their products with L rounded.
    if (same) {  // k = 0 exactly
      out = image_class::on_receiver;
      return true;
    }
    rounded_sum k;
    for (int i = 0; i < 3; ++i) {
      double h, l;
      two_sum(V[i], -got[i], h, l);
      k.add_product(h, L[i]);
      k.add_product(l, L[i]);
    }
    const int sk = k.sign();
    if (sk == 2) return false;
    out = sk > 0 ? image_class::shadow : image_class::behind_receiver;
    return true;
  }
  // Point light (see classify_image): a = Σ (w G_i − L_i)(w V_i − L_i), b = Σ (w V_i − L_i)²,
  // a − b = w Σ (G_i − V_i)(w V_i − L_i), whose sign is sign(w) times that of the sum.
  // Every difference is an exact pair (w V_i and w G_i are exact float products).
  const bool at_light = V[0] * w == L[0] && V[1] * w == L[1] && V[2] * w == L[2];
  if (at_light) {  // b = 0
    out = image_class::other;
    return true;
  }
  rounded_sum a, amb;
  for (int i = 0; i < 3; ++i) {
    double vh, vl, gh, gl, dh, dl;
    two_sum(w * V[i], -L[i], vh, vl);
    two_sum(w * got[i], -L[i], gh, gl);
    two_sum(got[i], -V[i], dh, dl);
    a.add_product(gh, vh);
    a.add_product(gh, vl);
    a.add_product(gl, vh);
    a.add_product(gl, vl);
    amb.add_product(dh, vh);
    amb.add_product(dh, vl);
    amb.add_product(dl, vh);
    amb.add_product(dl, vl);
  }
  const int sa = a.sign();
  if (sa == 2) return false;
  if (sa < 0) {
    out = image_class::beyond_light;
    return true;
  }
  if (same) {  // a = b > 0
    out = image_class::on_receiver;
    return true;
  }
  int sd = amb.sign();
  if (sd == 2) return false;
  if (w < 0) sd = -sd;
  out = sd > 0 ? image_class::shadow : image_class::behind_receiver;
  return true;
}

}  // namespace

bool fast_plane_value_f32(const double* in, const double* got, double& out) {
  for (int i = 0; i < 3; ++i)
    if (!is_float(got[i])) return false;
  const double terms[4] = {in[0] * got[0], in[1] * got[1], in[2] * got[2], in[3]};
  accumulator acc;
  for (double t : terms) acc.add(t);
  return round_to_double(acc, out) || round_to_double_exact(terms, 4, out);
}

}  // namespace shadowproof::detail
