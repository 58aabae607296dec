#pragma once
// The shadow-point filter over a vector of cases (batch.h): the affine image of V under
// M = (P·L) I − L Pᵀ and V's class, without a branch on the values. With s = P·L, t = P·V and
// w = L_3 the image is N_i / D, N_i = s V_i − t L_i, D = s − w t (shadow_point.cpp has the
// kernel for one case, which also settles the degenerate classes).
#include "fraction_form.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// −1 or +1 by the sign of x (for a nonzero x).
template <class R>
R sign_value(R x) {
  return select(x > R(0.0), R(1.0), R(-1.0));
}

/// x = P[4], L[4] (as given), V[3]; writes the three outputs and the class (its point_class
/// value as a real) and returns the mask of lanes decided: s, t and D clearly nonzero, V not
/// the light, every output's rounding decided. The classes decided here are shadow,
/// behind_receiver and beyond_light (classify.h); the others have s, t or D = 0 or V = L/w.
template <class F, class R>
auto shadow_point_lanes(R* x, const conventions& conv, R* values, R& cls) {
  using N = filter_number_of<F, R>;
  // The canonical light: a directional light given along its rays is negated (exact).
  const R flip = select(x[7] == R(0.0), R(conv.light == light_sign::along_rays ? -1.0 : 1.0), R(1.0));
  SHADOWPROOF_UNROLL
  for (int i = 4; i < 7; ++i) x[i] = x[i] * flip;
  auto ok = kernel_inputs<F, 3, 11>(x);
  const R* P = x;
  const R* L = x + 4;
  const R* V = x + 8;
  N s = exact_product(N(P[0]), N(L[0]));
  N t = exact_product(N(P[0]), N(V[0]));
  SHADOWPROOF_UNROLL
  for (int j = 1; j < 3; ++j) {
    s = s + exact_product(N(P[j]), N(L[j]));
    t = t + exact_product(N(P[j]), N(V[j]));
  }
  s = s + exact_product(N(P[3]), N(L[3]));
  t = t + N(P[3]);
  const R w = L[3];
  const N D = s - N(w) * t;  // = s up to a bound of the smallest subnormal when w = 0
  ok = ok & nonzero(s) & nonzero(t) & nonzero(D);
  // V = L/w exactly: V_i w = L_i, exact products (f32) or exact pairs (f64).
  auto at_light = w != R(0.0);
  SHADOWPROOF_UNROLL
  for (int i = 0; i < 3; ++i) {
    R p, e;
    if constexpr (std::is_same_v<F, float>) {
      p = V[i] * w;
      e = R(0.0);
    } else {
      two_product(V[i], w, p, e);
    }
    at_light = at_light & (p == L[i]) & (e == R(0.0));
  }
  ok = ok & !at_light;
  // The class (classify.h): directional, shadow when sign t = sign s; point light, behind the
  // receiver when sign(w t) ≠ sign s, else shadow when sign D = sign s, beyond the light when not.
  const R ss = sign_value(first_of(s)), st = sign_value(first_of(t)), sd = sign_value(first_of(D));
  const auto directional = w == R(0.0);
  const auto behind = select(directional, st, st * sign_value(w)) != ss;
  const auto shadow = directional | (sd == ss);
  cls = select(behind, R(2.0), select(shadow, R(1.0), R(3.0)));
  // A clamping shader leaves a point behind the receiver where it is.
  const auto clamped = behind & (R(conv.clamps_behind_receiver ? 1.0 : 0.0) == R(1.0));
  const auto den = prepare(D);
  SHADOWPROOF_UNROLL
  for (int i = 0; i < 3; ++i) {
    R quotient;
    const auto decided = round_quotient(s * N(V[i]) - t * N(L[i]), den, quotient);
    values[i] = select(clamped, select(V[i] == R(0.0), R(0.0), V[i]), quotient);
    ok = ok & (clamped | decided);
  }
  return ok;
}

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
