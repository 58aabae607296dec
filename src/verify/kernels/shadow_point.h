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

/// The canonical light, in place: a directional light (w = 0) given along its rays is negated
/// (exact); L[4] as given.
template <class R>
void canonical_light_lanes(R* L, const conventions& conv) {
  const R flip = select(L[3] == R(0.0), R(conv.light == light_sign::along_rays ? -1.0 : 1.0), R(1.0));
  SHADOWPROOF_UNROLL
  for (int i = 0; i < 3; ++i) L[i] = L[i] * flip;
}

/// x = P[4], L[4] (as given), V[3]; writes the three outputs and the class (its point_class
/// value as a real) and returns the mask of lanes decided: s, t and D clearly nonzero, V not
/// the light, every output's rounding decided. The classes decided here are shadow,
/// behind_receiver and beyond_light (classify.h); the others have s, t or D = 0 or V = L/w.
template <class F, class R>
auto shadow_point_lanes(R* x, const conventions& conv, R* values, R& cls) {
  using N = filter_number_of<F, R>;
  canonical_light_lanes(x + 4, conv);
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

/// The side of the float image G on the line through the light and V (shadow_point.cpp's
/// image_class_stage over a vector of cases), with the canonical light L and the filter numbers
/// N: G's image_class value (a real) in `cls`, and the mask of lanes where it is decided. Only
/// the classes with every sign clearly nonzero are decided here: shadow, behind_receiver and
/// beyond_light (on_receiver and other need a zero).
///   Directional light (w = 0): k = (V − G)·L, positive for a shadow (G lies beyond V, away
///   from the light), negative behind the receiver.
///   Point light L/w: G's position on the line from the light (0) through V (1) is u = a / b,
///   a = Σ (w G_i − L_i)(w V_i − L_i), b = Σ (w V_i − L_i)² > 0: beyond the light for a < 0,
///   a shadow for a > b, behind the receiver for 0 < a < b.
template <class N, class R>
auto image_side_lanes(const R* L, const R* V, const N* light_to_v, const N& b, const R* G, R& cls) {
  const R w = L[3];
  const auto directional = w == R(0.0);
  N k = (N(V[0]) - N(G[0])) * N(L[0]);
  SHADOWPROOF_UNROLL
  for (int i = 1; i < 3; ++i) k = k + (N(V[i]) - N(G[i])) * N(L[i]);
  N a = (exact_product(N(w), N(G[0])) - N(L[0])) * light_to_v[0];
  SHADOWPROOF_UNROLL
  for (int i = 1; i < 3; ++i) a = a + (exact_product(N(w), N(G[i])) - N(L[i])) * light_to_v[i];
  const N beyond_v = a - b;
  const auto a_negative = first_of(a) < R(0.0);
  const auto point_decided = nonzero(b) & nonzero(a) & (a_negative | nonzero(beyond_v));
  constexpr double shadow = 1, behind_receiver = 2, beyond_light = 3;  // image_class values
  cls = select(directional, select(first_of(k) > R(0.0), R(shadow), R(behind_receiver)),
               select(a_negative, R(beyond_light),
                      select(first_of(beyond_v) > R(0.0), R(shadow), R(behind_receiver))));
  return (directional & nonzero(k)) | ((!directional) & point_decided);
}

/// Grading the float image G of a case against its correctly rounded image C (batch.h's image
/// filter, over a vector of cases): x = P[4], L[4] (as given), V[3], G[3], C[3]. Writes
/// cls = class(G) + 4 class(C) (image_class values), 1 in values[2] where C's class is decided
/// (0 where not), P·(G, 1) correctly rounded to double in values[0] and 1 in values[1] where
/// that rounding is decided, and returns the mask of lanes where G's class is decided.
template <class F, class R>
auto shadow_image_lanes(R* x, const conventions& conv, R* values, R& cls) {
  using N = filter_number_of<F, R>;
  canonical_light_lanes(x + 4, conv);
  const auto in_range = kernel_inputs<F, 4, 11>(x);  // a: w² G V, degree 4
  const R* P = x;
  const R* L = x + 4;
  const R* V = x + 8;
  const R* G = x + 11;
  const R* C = x + 14;
  // w V − L and b = |w V − L|², shared by both images.
  N light_to_v[3];
  SHADOWPROOF_UNROLL
  for (int i = 0; i < 3; ++i) light_to_v[i] = exact_product(N(L[3]), N(V[i])) - N(L[i]);
  const N b = light_to_v[0] * light_to_v[0] + light_to_v[1] * light_to_v[1] + light_to_v[2] * light_to_v[2];
  R got_class, reference_class;
  const auto got_decided = in_range & kernel_inputs<F, 4, 3>(G) & image_side_lanes(L, V, light_to_v, b, G, got_class);
  const auto reference_decided =
      in_range & kernel_inputs<F, 4, 3>(C) & image_side_lanes(L, V, light_to_v, b, C, reference_class);
  cls = got_class + R(4.0) * reference_class;
  values[2] = select(reference_decided, R(1.0), R(0.0));
  // P·(G, 1) from exact products: four doubles for f32, seven for f64 (two per product).
  if constexpr (std::is_same_v<F, float>) {
    R terms[4] = {P[0] * G[0], P[1] * G[1], P[2] * G[2], P[3]};
    values[1] = select(round_sum_to_double<4>(terms, values[0]), R(1.0), R(0.0));
  } else {
    R terms[7];
    SHADOWPROOF_UNROLL
    for (int i = 0; i < 3; ++i) two_product(P[i], G[i], terms[2 * i], terms[2 * i + 1]);
    terms[6] = P[3];
    values[1] = select(round_sum_to_double<7>(terms, values[0]), R(1.0), R(0.0));
  }
  return got_decided;
}

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
