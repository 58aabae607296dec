// Closed forms of D_i = Σ_j |∂f_i/∂x_j| |x_j| for the shadow matrix, the shadow of a point, the
// mirror and the normal matrix, evaluated with midpoint-radius numbers: double for float cases
// (every product of two floats is exact in it), long double for double cases.
#include "sensitivity.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace shadowproof::detail {
namespace {

// A computed value and a bound on its distance to the exact one. Each operation adds its own
// rounding, u|r| plus the smallest subnormal for underflow, and inflates the bound by (1 + 8u) to
// cover the rounding of the bound itself (all its terms are non-negative).
template <class B>
struct bounded {
  B v = 0, e = 0;
};

template <class B>
constexpr B unit() {
  return std::numeric_limits<B>::epsilon() / 2;
}
template <class B>
B slack(B r) {
  return std::fabs(r) * unit<B>() + std::numeric_limits<B>::denorm_min();
}
template <class B>
B inflate(B e) {
  return e * (1 + 8 * unit<B>());
}
template <class B>
bounded<B> exact(B x) {
  return {x, 0};
}
template <class B>
bounded<B> operator+(const bounded<B>& a, const bounded<B>& b) {
  const B r = a.v + b.v;
  return {r, inflate(a.e + b.e + slack(r))};
}
template <class B>
bounded<B> operator-(const bounded<B>& a, const bounded<B>& b) {
  const B r = a.v - b.v;
  return {r, inflate(a.e + b.e + slack(r))};
}
template <class B>
bounded<B> operator*(const bounded<B>& a, const bounded<B>& b) {
  const B r = a.v * b.v;
  return {r, inflate(std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + slack(r))};
}
// |a/b − ã/b̃| ≤ (e_a + |ã/b̃| e_b) / (|b̃| − e_b); the caller checks that b keeps its sign.
template <class B>
bounded<B> operator/(const bounded<B>& a, const bounded<B>& b) {
  const B r = a.v / b.v;
  const B room = (std::fabs(b.v) - b.e) * (1 - 4 * unit<B>());
  return {r, inflate((a.e + std::fabs(r) * (1 + 2 * unit<B>()) * b.e) / room + slack(r))};
}
// The product of two inputs of the case: exact in double for float inputs (24 + 24 bits), one
// rounding otherwise.
template <class B>
bounded<B> product_of_inputs(B a, B b, bool exact_products) {
  const B r = a * b;
  return {r, exact_products ? B(0) : inflate(slack(r))};
}

template <class B>
bounded<B> magnitude(const bounded<B>& a) {
  return {std::fabs(a.v), a.e};
}
// a is certainly away from 0.
template <class B>
bool nonzero(const bounded<B>& a) {
  return std::fabs(a.v) * (1 - 4 * unit<B>()) > a.e * (1 + 4 * unit<B>());
}
template <class B>
double lower(const bounded<B>& a) {
  const B x = (a.v - a.e) * (1 - 4 * unit<B>());
  return x > 0 ? static_cast<double>(x) * (1 - 0x1p-52) : 0.0;
}
template <class B>
double upper(const bounded<B>& a) {
  return static_cast<double>((a.v + a.e) * (1 + 4 * unit<B>())) * (1 + 0x1p-52);
}

// An exact value f known through its correct rounding ref to the case's type: within half the
// larger gap next to ref.
template <class B>
bounded<B> from_reference(double ref, scalar_type type) {
  double gap;
  if (type == scalar_type::f32) {
    const float r = std::fabs(static_cast<float>(ref));
    gap = static_cast<double>(std::nextafter(r, std::numeric_limits<float>::infinity())) - r;
  } else {
    const double r = std::fabs(ref);
    gap = std::nextafter(r, std::numeric_limits<double>::infinity()) - r;
  }
  return {static_cast<B>(ref), static_cast<B>(gap) / 2};
}

// No formula of degree at most 5 in the inputs over- or underflows the type: every nonzero input
// lies within 2^(emin/5) … 2^(emax/5) (a sum of four such products stays in range too).
bool moderate(const test_case& c) {
  const int top = c.type == scalar_type::f32 ? std::numeric_limits<float>::max_exponent
                                             : std::numeric_limits<double>::max_exponent;
  const int bottom = c.type == scalar_type::f32 ? std::numeric_limits<float>::min_exponent
                                                : std::numeric_limits<double>::min_exponent;
  for (double x : c.inputs) {
    if (x == 0) continue;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1023;  // floor(log2 |x|); subnormals read as −1023
    if (e >= top / 5 || e <= bottom / 5) return false;
  }
  return true;
}

// Every output's reference is 0 or well inside the normal range: no quotient or product that
// yields an output underflows or overflows on the way.
bool outputs_moderate(const sensitivity_query& q, std::size_t n) {
  const double top = q.c->type == scalar_type::f32 ? static_cast<double>(std::numeric_limits<float>::max())
                                                    : std::numeric_limits<double>::max();
  const double bottom = q.c->type == scalar_type::f32 ? static_cast<double>(std::numeric_limits<float>::min())
                                                       : std::numeric_limits<double>::min();
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::fabs(q.reference[i]);
    if (!(r == 0 || (r > 2 * bottom && r < top / 2))) return false;
  }
  return true;
}

template <class B>
bool finite(const bounded<B>& a) {
  return std::isfinite(a.v) && std::isfinite(a.e);
}

template <class B>
void store(const bounded<B>& d, std::size_t i, sensitivity_bounds& out) {
  out.lo[i] = lower(d);
  out.hi[i] = upper(d);
}

// The exact value f_i within [v − e, v + e], widened for the rounding of the ends.
template <class B>
void store_value(const bounded<B>& f, std::size_t i, sensitivity_bounds& out) {
  const long double v = f.v, e = f.e;
  const long double low = v - e, high = v + e;
  out.f_lo[i] = low - std::fabs(low) * 0x1p-60L - std::numeric_limits<long double>::denorm_min();
  out.f_hi[i] = high + std::fabs(high) * 0x1p-60L + std::numeric_limits<long double>::denorm_min();
}

// near_singular for the divisor `b` with sensitivity S = Σ_j |∂b/∂x_j| |x_j|: |b| ≤ c·u S.
template <class B>
noted near(const bounded<B>& b, const bounded<B>& sensitivity, double cu) {
  const bounded<B> edge = exact(static_cast<B>(cu)) * sensitivity - magnitude(b);
  if (!finite(edge)) return noted::undecided;
  if (edge.v - edge.e > 0) return noted::yes;
  if (edge.v + edge.e < 0) return noted::no;
  return noted::undecided;
}

double cu(const sensitivity_query& q) {
  return q.stable_constant * (q.c->type == scalar_type::f32 ? 0x1p-24 : 0x1p-53);
}

// ---- the shadow matrix: entry (r, c) is −L_r P_c off the diagonal (D = 2 |L_r P_c|) and
// Σ_{k≠r} P_k L_k on it (D = 2 Σ_{k≠r} |P_k L_k|); no divisor.
template <class B>
bool shadow_matrix_with(const sensitivity_query& q, sensitivity_bounds& out) {
  // Plain arithmetic: an entry is one product or a sum of three, so its computed value and the
  // sum of its terms' sizes are within 4u of their sums of sizes (products of two float inputs
  // are exact in double).
  const double* x = q.c->inputs.data();
  const B u = unit<B>(), tiny = std::numeric_limits<B>::denorm_min();
  const bool flip = q.conv->light == light_sign::along_rays && x[7] == 0;  // the canonical light
  auto light = [&](std::size_t r) { return static_cast<B>(flip && r < 3 ? -x[4 + r] : x[4 + r]); };
  for (std::size_t i = 0; i < 16; ++i) {
    if (!q.wanted[i]) continue;
    const std::size_t r = i / 4, c = i % 4;
    B f = 0, size = 0;
    if (r != c) {
      f = -(light(r) * static_cast<B>(x[c]));
      size = std::fabs(f);
    } else {
      for (std::size_t k = 0; k < 4; ++k)
        if (k != r) {
          const B p = static_cast<B>(x[k]) * light(k);
          f += p;
          size += std::fabs(p);
        }
    }
    const B error = 4 * u * size * (1 + 8 * u) + tiny;
    if (!std::isfinite(size) || !std::isfinite(error)) return false;
    out.lo[i] = static_cast<double>(std::max(B(0), 2 * size - 2 * error)) * (1 - 0x1p-52);
    out.hi[i] = static_cast<double>(2 * size + 2 * error) * (1 + 0x1p-52);
    out.f_lo[i] = static_cast<long double>(f) - static_cast<long double>(error) * (1 + 0x1p-60L);
    out.f_hi[i] = static_cast<long double>(f) + static_cast<long double>(error) * (1 + 0x1p-60L);
  }
  out.values = true;
  out.near_singular = noted::no;
  return true;
}

// ---- the mirror about (n, d), S = n·n, q_k = 2 n_k²/S:
//   entry (i, j), i, j < 3: δ_ij − 2 n_i n_j / S, D = (2 |n_i n_j| / S) Σ_k |q_k − δ_ik − δ_jk|;
//   entry (i, 3): −2 d n_i / S, D = |2 d n_i / S| (1 + Σ_k |δ_ik − q_k|);
//   row 3: constants, D = 0. S never nears 0 relative to its sensitivity 2S.
template <class B>
bool reflection_with(const sensitivity_query& q, sensitivity_bounds& out) {
  const double* x = q.c->inputs.data();
  bounded<B> n[3], square[3], s;
  for (std::size_t k = 0; k < 3; ++k) {
    n[k] = exact(static_cast<B>(x[k]));
    square[k] = n[k] * n[k];
    s = s + square[k];
  }
  if (!nonzero(s)) return false;
  bounded<B> share[3];
  for (std::size_t k = 0; k < 3; ++k) share[k] = exact(B(2)) * square[k] / s;
  for (std::size_t i = 0; i < 16; ++i) {
    if (!q.wanted[i]) continue;
    const std::size_t r = i / 4, c = i % 4;
    bounded<B> d, f;
    if (r == 3) {
      d = exact(B(0));
      f = exact(static_cast<B>(c == 3));
    } else if (c < 3) {
      bounded<B> sum;
      for (std::size_t k = 0; k < 3; ++k)
        sum = sum + magnitude(share[k] - exact(static_cast<B>((k == r) + (k == c))));
      const bounded<B> term = exact(B(2)) * n[r] * n[c] / s;
      d = magnitude(term) * sum;
      f = exact(static_cast<B>(r == c)) - term;
    } else {
      bounded<B> sum = exact(B(1));
      for (std::size_t k = 0; k < 3; ++k) sum = sum + magnitude(exact(static_cast<B>(k == r)) - share[k]);
      const bounded<B> term = exact(B(-2)) * exact(static_cast<B>(x[3])) * n[r] / s;
      d = magnitude(term) * sum;
      f = term;
    }
    if (!finite(d) || !finite(f)) return false;
    store(d, i, out);
    store_value(f, i, out);
  }
  out.values = true;
  out.near_singular = noted::no;
  return true;
}

// ---- the shadow of V, f = h / h_3 with h = s V − t L, s = P·L, t = P·(V, 1), h_3 = s − w t:
//   x_k ∂f_i/∂x_k = x_k (∂h_i/∂x_k − f_i ∂h_3/∂x_k) / h_3, with
//   ∂h_m/∂P_k = L_k V_m − V_k L_m,  ∂h_m/∂L_k = P_k V_m − t δ_mk,  ∂h_m/∂V_k = s δ_mk − P_k L_m
//   (V_3 = 1, L_3 = w); the divisor h_3 has sensitivity Σ_k |∂h_3/∂x_k| |x_k|. A point that is its
//   own image (on the receiver with the light in it, or behind it under clamping) has f = V,
//   D_i = |V_i|. The exact values f_i are the references, within half an ulp.
template <class B>
bool shadow_point_with(const sensitivity_query& q, sensitivity_bounds& out) {
  const double* x = q.c->inputs.data();
  if (!q.cls) return false;
  const bool own_image = *q.cls == point_class::line_in_plane ||
                         (q.conv->clamps_behind_receiver && *q.cls == point_class::behind_receiver);
  if (own_image) {
    for (std::size_t i = 0; i < 3; ++i)
      if (q.wanted[i]) {
        out.lo[i] = out.hi[i] = std::fabs(x[8 + i]);
        out.f_lo[i] = out.f_hi[i] = x[8 + i];
      }
    out.values = true;
    out.near_singular = noted::no;
    return true;
  }
  // Plain arithmetic with a bound from the absolute-value evaluation: every quantity q below is
  // a sum of at most a few products of inputs (and of s, t, f), so |q̃ − q| ≤ k u |q|_abs with k
  // the operations on its path (at most 10, for the lanes), where |q|_abs evaluates the same
  // expression with absolute values; the margins add the errors of s, t and f explicitly.
  const B u = unit<B>(), tiny = std::numeric_limits<B>::denorm_min();
  const bool flip = q.conv->light == light_sign::along_rays && x[7] == 0;  // the canonical light
  B P[4], L[4], V[4];
  for (std::size_t k = 0; k < 4; ++k) {
    P[k] = static_cast<B>(x[k]);
    L[k] = static_cast<B>(flip && k < 3 ? -x[4 + k] : x[4 + k]);
  }
  for (std::size_t k = 0; k < 3; ++k) V[k] = static_cast<B>(x[8 + k]);
  V[3] = 1;
  const B w = L[3];
  B s = 0, s_abs = 0, t = 0, t_abs = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    s += P[k] * L[k];
    s_abs += std::fabs(P[k] * L[k]);
    t += P[k] * V[k];
    t_abs += std::fabs(P[k] * V[k]);
  }
  const B h3 = s - w * t;
  const B h3_error = 9 * u * (s_abs + std::fabs(w) * t_abs) * (1 + 16 * u) + tiny;
  if (!std::isfinite(h3) || !std::isfinite(h3_error) || !(std::fabs(h3) > 2 * h3_error)) return false;
  const B h3_lo = (std::fabs(h3) - h3_error) * (1 - 2 * u), h3_hi = (std::fabs(h3) + h3_error) * (1 + 2 * u);
  // The lanes of the divisor: ∂h_3/∂x_k, their sizes |·|_abs, and its sensitivity S_3.
  B b[11] = {}, b_abs[11] = {};
  for (std::size_t k = 0; k < 3; ++k) {
    b[k] = L[k] - V[k] * w;  // ∂h_3/∂P_k
    b_abs[k] = std::fabs(L[k]) + std::fabs(V[k] * w);
    b[4 + k] = P[k];  // ∂h_3/∂L_k
    b_abs[4 + k] = std::fabs(P[k]);
    b[8 + k] = -P[k] * w;  // ∂h_3/∂V_k
    b_abs[8 + k] = std::fabs(P[k] * w);
  }
  b[7] = P[3] - t;  // ∂h_3/∂w
  b_abs[7] = std::fabs(P[3]) + t_abs;
  B s3 = 0, s3_error = 0;
  for (std::size_t k = 0; k < 11; ++k) {
    const B size = std::fabs(static_cast<B>(x[k]));
    s3 += std::fabs(b[k]) * size;
    s3_error += 9 * u * b_abs[k] * size;
  }
  s3_error = (s3_error + 12 * u * s3) * (1 + 16 * u) + tiny;
  const B edge = static_cast<B>(cu(q));
  if (h3_hi <= edge * (s3 - s3_error) * (1 - 4 * u)) out.near_singular = noted::yes;
  else if (h3_lo > edge * (s3 + s3_error) * (1 + 4 * u)) out.near_singular = noted::no;
  else out.near_singular = noted::undecided;
  for (std::size_t i = 0; i < 3; ++i) {
    if (!q.wanted[i]) continue;
    // f_i = (s V_i − t L_i) / h_3 and its error.
    const B n = s * V[i] - t * L[i];
    const B n_error = 9 * u * (s_abs * std::fabs(V[i]) + t_abs * std::fabs(L[i])) * (1 + 16 * u) + tiny;
    const B f = n / h3;
    const B f_error = ((n_error + std::fabs(f) * h3_error) / h3_lo + 2 * u * std::fabs(f)) * (1 + 16 * u) + tiny;
    // Σ_k |∂h_i/∂x_k − f ∂h_3/∂x_k| |x_k| and its error.
    B sum = 0, sum_error = 0;
    for (std::size_t k = 0; k < 11; ++k) {
      if (x[k] == 0) continue;
      B a, a_abs;
      if (k < 4) {  // ∂h_i/∂P_k = L_k V_i − V_k L_i
        a = L[k] * V[i] - V[k] * L[i];
        a_abs = std::fabs(L[k] * V[i]) + std::fabs(V[k] * L[i]);
      } else if (k < 8) {  // ∂h_i/∂L_j = P_j V_i − t δ_ij
        const std::size_t j = k - 4;
        a = P[j] * V[i] - (i == j ? t : B(0));
        a_abs = std::fabs(P[j] * V[i]) + (i == j ? t_abs : B(0));
      } else {  // ∂h_i/∂V_j = s δ_ij − P_j L_i
        const std::size_t j = k - 8;
        a = (i == j ? s : B(0)) - P[j] * L[i];
        a_abs = (i == j ? s_abs : B(0)) + std::fabs(P[j] * L[i]);
      }
      const B lane = a - f * b[k];
      const B size = std::fabs(static_cast<B>(x[k]));
      sum += std::fabs(lane) * size;
      sum_error += (10 * u * (a_abs + std::fabs(f) * b_abs[k]) + f_error * b_abs[k]) * size;
    }
    sum_error = (sum_error + 14 * u * sum) * (1 + 16 * u) + tiny;
    const B d_lo = std::max(B(0), sum - sum_error) / h3_hi * (1 - 2 * u);
    const B d_hi = (sum + sum_error) / h3_lo * (1 + 2 * u);
    if (!std::isfinite(d_hi) || !std::isfinite(f_error)) return false;
    out.lo[i] = static_cast<double>(d_lo) * (1 - 0x1p-52);
    out.hi[i] = static_cast<double>(d_hi) * (1 + 0x1p-52);
    out.f_lo[i] = static_cast<long double>(f) - static_cast<long double>(f_error) * (1 + 0x1p-60L);
    out.f_hi[i] = static_cast<long double>(f) + static_cast<long double>(f_error) * (1 + 0x1p-60L);
  }
  out.values = true;
  return true;
}

// ---- the normal matrix G = (A⁻¹)ᵀ: ∂(A⁻¹)_ji/∂a_kl = −(A⁻¹)_jk (A⁻¹)_li, so
//   D_ij = Σ_kl |G_kj| |G_il| |a_kl|   (the entries of |A⁻¹| |A| |A⁻¹|, transposed);
// the divisor det A has sensitivity Σ_kl |C_kl a_kl| = |det A| Σ_kl |G_kl a_kl| (C = det A · G,
// the cofactors), so it is within c·u of vanishing when Σ_kl |G_kl a_kl| ≥ 1/(c·u). The exact
// G_kl are the references, within half an ulp.
template <class B>
bool normal_matrix_with(const sensitivity_query& q, sensitivity_bounds& out) {
  const double* a = q.c->inputs.data();
  bounded<B> G[9];
  for (std::size_t i = 0; i < 9; ++i) {
    if (!std::isfinite(q.reference[i])) return false;
    G[i] = from_reference<B>(q.reference[i], q.c->type);
  }
  for (std::size_t i = 0; i < 9; ++i) {
    if (!q.wanted[i]) continue;
    const std::size_t r = i / 3, c = i % 3;
    bounded<B> d;
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t l = 0; l < 3; ++l)
        if (a[3 * k + l] != 0)
          d = d + magnitude(G[3 * k + c]) * magnitude(G[3 * r + l]) * magnitude(exact(static_cast<B>(a[3 * k + l])));
    if (!finite(d)) return false;
    store(d, i, out);
  }
  bounded<B> spread;
  for (std::size_t k = 0; k < 9; ++k) spread = spread + magnitude(G[k]) * magnitude(exact(static_cast<B>(a[k])));
  // near: 1/Σ ≤ c·u, i.e. c·u Σ − 1 ≥ 0 (Σ's sensitivity form with b = 1).
  out.near_singular = near(exact(B(1)), spread, cu(q));
  // 1/det A is an intermediate of the formula: in range when |det A| = 1/|det G| stays within it,
  // which moderate inputs and a moderate det G guarantee.
  const bounded<B> det_g = G[0] * (G[4] * G[8] - G[5] * G[7]) - G[1] * (G[3] * G[8] - G[5] * G[6]) +
                           G[2] * (G[3] * G[7] - G[4] * G[6]);
  const double top = std::ldexp(1.0, (q.c->type == scalar_type::f32 ? 128 : 1024) / 5);
  out.formula_in_range = finite(det_g) && upper(magnitude(det_g)) < top && lower(magnitude(det_g)) > 1 / top;
  return true;
}

}  // namespace

bool in_range(const sensitivity_query& q, std::size_t outputs, const sensitivity_bounds& b) {
  return b.formula_in_range && moderate(*q.c) && outputs_moderate(q, outputs);
}

bool shadow_matrix_sensitivity(const sensitivity_query& q, sensitivity_bounds& out) {
  return q.c->type == scalar_type::f32 ? shadow_matrix_with<double>(q, out) : shadow_matrix_with<long double>(q, out);
}

bool shadow_point_sensitivity(const sensitivity_query& q, sensitivity_bounds& out) {
  return q.c->type == scalar_type::f32 ? shadow_point_with<double>(q, out) : shadow_point_with<long double>(q, out);
}

bool reflection_matrix_sensitivity(const sensitivity_query& q, sensitivity_bounds& out) {
  return q.c->type == scalar_type::f32 ? reflection_with<double>(q, out) : reflection_with<long double>(q, out);
}

bool normal_matrix_sensitivity(const sensitivity_query& q, sensitivity_bounds& out) {
  return q.c->type == scalar_type::f32 ? normal_matrix_with<double>(q, out) : normal_matrix_with<long double>(q, out);
}

}  // namespace shadowproof::detail
