// shadow-point kernels: the affine image of V = (x, y, z, 1) under M = (P·L) I − L Pᵀ, its
// class, and (for grading the float image) the class of a given image and its plane value.
// With s = P·L, t = P·V and w = L_3, the homogeneous image is s V − t L with w-coordinate
// D = s − w t, so the affine image is N_i / D with N_i = s V_i − t L_i: one shared
// denominator, but the class logic (classify.h) decides which outputs exist, so this kernel
// has its own driver instead of fraction_kernel's. Every formula is written once over the
// number type (bounded, bounded_pair, expansion) and evaluated filter first, exactly second.
#include <cmath>

#include "fraction_kernel.h"


namespace shadowproof::detail {
namespace {

int sign_of(const expansion& x) { return x.sign(); }
int sign_of(const bounded& x) { return sign(x); }
int sign_of(const bounded_pair& x) { return sign(x); }

// V_i w = L_i for i < 3, exactly (V is the light itself): for f32 inputs the products are
// exact doubles, for f64 ones exact pairs.
template <class F>
bool at_light(const double* L, const double* V) {
  bool same = true;
  for (int i = 0; i < 3; ++i) {
    double p, e = 0;
    if constexpr (std::is_same_v<F, float>) p = V[i] * L[3];
    else two_product(V[i], L[3], p, e);
    same = same && p == L[i] && e == 0;
  }
  return same;
}

// The canonical light: a directional light given along its rays is negated (exact).
void canonical_light(const double* in, const conventions& conv, double* L) {
  const bool flip = conv.light == light_sign::along_rays && in[3] == 0;
  for (int i = 0; i < 3; ++i) L[i] = flip ? -in[i] : in[i];
  L[3] = in[3];
}

// The image of V and V's class over N: 1 decided, 0 a sign or rounding undecided, −1 for the
// generic oracle. x = P[4], canonical L[4], V[3].
template <class F, class N>
int shadow_point_stage(const double* x, const conventions& conv, fast_reference& out) {
  const double* P = x;
  const double* L = x + 4;
  const double* V = x + 8;
  N s = exact_product(N(P[0]), N(L[0]));
  N t = exact_product(N(P[0]), N(V[0]));
  for (int j = 1; j < 3; ++j) {
    s = s + exact_product(N(P[j]), N(L[j]));
    t = t + exact_product(N(P[j]), N(V[j]));
  }
  s = s + exact_product(N(P[3]), N(L[3]));
  t = t + N(P[3]);
  const int ss = sign_of(s), ts = sign_of(t);
  if (ss == 2 || ts == 2) return 0;
  const double w = L[3];
  const bool directional = w == 0;
  const N D = directional ? s : s - N(w) * t;
  const int ds = directional ? ss : sign_of(D);
  if (ds == 2) return 0;
  // The class, as classify_point decides it (division-free in w).
  point_class cls;
  if (ss == 0) cls = ts == 0 ? point_class::line_in_plane
                             : (directional ? point_class::light_parallel : point_class::light_on_plane);
  else if (ts == 0) cls = point_class::on_receiver;
  else if (directional) cls = ts == ss ? point_class::shadow : point_class::behind_receiver;
  else if (at_light<F>(L, V)) cls = point_class::at_light;
  else if (ds == 0) cls = point_class::at_infinity;                    // w t = s
  else if ((w > 0 ? ts : -ts) != ss) cls = point_class::behind_receiver;  // sign(w t) ≠ sign(s)
  else cls = ds == ss ? point_class::shadow : point_class::beyond_light;  // |w t| < |s|
  out.cls = cls;
  // A point on the receiver is its own image, also when the light is parallel to or on the
  // receiver (the whole line from V to the light then lies in it); a clamping shader leaves a
  // point behind the receiver where it is.
  if (cls == point_class::on_receiver || cls == point_class::line_in_plane ||
      (conv.clamps_behind_receiver && cls == point_class::behind_receiver)) {
    for (int i = 0; i < 3; ++i) out.value[i] = V[i] == 0 ? 0.0 : V[i];
    return 1;
  }
  if (ds == 0) {  // the image is at infinity or the zero vector: no finite image
    out.defined = false;
    out.value[0] = out.value[1] = out.value[2] = 0;
    return 1;
  }
  if constexpr (std::is_same_v<N, expansion>) {
    for (int i = 0; i < 3; ++i) {
      const expansion n = s * N(V[i]) - t * N(L[i]);
      if (!round_exact_quotient<F>(n, D, out.value[i])) return -1;
    }
  } else {
    const auto den = prepare(D);
    for (int i = 0; i < 3; ++i)
      if (!round_quotient(s * N(V[i]) - t * N(L[i]), den, out.value[i])) return 0;
  }
  return 1;
}

template <class F>
bool shadow_point_kernel(const double* in, const conventions& conv, fast_reference& out) {
  double x[11];
  copy_inputs(in, 4, x);
  canonical_light(in + 4, conv, x + 4);
  copy_inputs(in + 8, 3, x + 8);
  if (!kernel_inputs<F, 3, 11>(x)) return false;  // N_i = s V_i − t L_i, D = s − w t: degree 3
  out = fast_reference{};
  out.count = 3;
  const int filtered = kernels_exact_only ? 0 : shadow_point_stage<F, filter_number<F>>(x, conv, out);
  if (filtered != 0) return filtered > 0;
  out = fast_reference{};
  out.count = 3;
  return shadow_point_stage<F, expansion>(x, conv, out) > 0;
}

// ---------------------------------------------------------------------------------------------
// Grading the float image G (shadow_point.cpp of the operations: classify_image and the plane
// value), with the same number types.

// Where G lies on the line through the light and V (see image_class), over N: 1 decided,
// 0 undecided, −1 generic oracle. x = P[4], canonical L[4], V[3]; G finite, of the case's type.
// Products of two of those values are exact_product when `exact_products` (f32 values in double,
// or pairs), ordinary bounded products otherwise (a first, cheaper filter for f64).
template <class N, bool exact_products>
int image_class_stage(const double* x, const double* G, image_class& result) {
  auto product = [](const N& a, const N& b) {
    if constexpr (exact_products) return exact_product(a, b);
    else return a * b;
  };
  const double* L = x + 4;
  const double* V = x + 8;
  const bool same = G[0] == V[0] && G[1] == V[1] && G[2] == V[2];
  const double w = L[3];
  if (w == 0) {
    // Travelling from V towards the light means moving away from a real shadow:
    // k = (V − G)·L, positive for a shadow.
    N k = (N(V[0]) - N(G[0])) * N(L[0]);
    for (int i = 1; i < 3; ++i) k = k + (N(V[i]) - N(G[i])) * N(L[i]);
    const int sk = sign_of(k);
    if (sk == 2) return 0;
    result = sk > 0 ? image_class::shadow
                    : (sk < 0 ? image_class::behind_receiver : (same ? image_class::on_receiver : image_class::other));
    return 1;
  }
  // Point light L/w: G's position on the line is u = a / b with a = Σ (w G_i − L_i)(w V_i − L_i)
  // and b = Σ (w V_i − L_i)² (division-free: compare a with 0 and with b).
  N a(0.0), b(0.0);
  for (int i = 0; i < 3; ++i) {
    const N dv = product(N(w), N(V[i])) - N(L[i]);
    a = a + (product(N(w), N(G[i])) - N(L[i])) * dv;
    b = b + dv * dv;
  }
  const int sb = sign_of(b), sa = sign_of(a);
  if (sb == 2 || sa == 2) return 0;
  if (sb == 0) {  // V is the light
    result = image_class::other;
    return 1;
  }
  if (sa <= 0) {
    result = sa < 0 ? image_class::beyond_light : image_class::other;
    return 1;
  }
  const int beyond_v = sign_of(a - b);
  if (beyond_v == 2) return 0;
  result = beyond_v > 0 ? image_class::shadow
                        : (beyond_v < 0 ? image_class::behind_receiver : (same ? image_class::on_receiver : image_class::other));
  return 1;
}

template <class F>
bool image_class_kernel(const double* in, const conventions& conv, const double* got, image_class& out) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(got[i])) {
      out = image_class::nonfinite;
      return true;
    }
  double x[11];
  copy_inputs(in, 4, x);
  canonical_light(in + 4, conv, x + 4);
  copy_inputs(in + 8, 3, x + 8);
  // The products w G_i must be exact (f32) or exact pairs (f64) like those of the inputs.
  if (!kernel_inputs<F, 4, 11>(x) || !kernel_inputs<F, 4, 3>(got)) return false;  // a: w² G V, degree 4
  if (!kernels_exact_only) {
    // f64: plain double with bounds first (regular images lie far from V and the light), then
    // double-double.
    if constexpr (std::is_same_v<F, double>)
      if (image_class_stage<bounded, false>(x, got, out) == 1) return true;
    if (image_class_stage<filter_number<F>, true>(x, got, out) == 1) return true;
  }
  return image_class_stage<expansion, true>(x, got, out) > 0;
}

// P·(G, 1) = Σ P_i G_i + P_3, from exact products of two values of the case's type: four
// exact doubles for f32, seven for f64 (two per product), summed by round_sum_to_double; the
// exact expansion where that does not decide.
template <class F>
bool plane_value_kernel(const double* in, const double* got, double& out) {
  if (!kernel_inputs<F, 2, 4>(in) || !kernel_inputs<F, 2, 3>(got)) return false;
  if constexpr (std::is_same_v<F, float>) {  // products of floats are exact doubles
    double terms[4] = {in[0] * got[0], in[1] * got[1], in[2] * got[2], in[3]};
    if (!kernels_exact_only && round_sum_to_double<4>(terms, out)) return true;
  } else {
    double terms[7];
    for (int i = 0; i < 3; ++i) two_product(in[i], got[i], terms[2 * i], terms[2 * i + 1]);
    terms[6] = in[3];
    if (!kernels_exact_only && round_sum_to_double<7>(terms, out)) return true;
  }
  expansion x(in[3]);
  for (int i = 0; i < 3; ++i) x.add_product(in[i], got[i]);
  return round_exact_value<double>(x, out);
}

}  // namespace

bool fast_shadow_point_f32(const double* in, const conventions& conv, fast_reference& out) {
  return shadow_point_kernel<float>(in, conv, out);
}

bool fast_shadow_point_f64(const double* in, const conventions& conv, fast_reference& out) {
  return shadow_point_kernel<double>(in, conv, out);
}

bool fast_image_class_f32(const double* in, const conventions& conv, const double* got, image_class& out) {
  return image_class_kernel<float>(in, conv, got, out);
}

bool fast_image_class_f64(const double* in, const conventions& conv, const double* got, image_class& out) {
  return image_class_kernel<double>(in, conv, got, out);
}

bool fast_plane_value_f32(const double* in, const double* got, double& out) {
  return plane_value_kernel<float>(in, got, out);
}

bool fast_plane_value_f64(const double* in, const double* got, double& out) {
  return plane_value_kernel<double>(in, got, out);
}

}  // namespace shadowproof::detail
