// shadow-point: plane P[4], light L[4], point V[3] -> the affine shadow of V, the image of
// (V, 1) under M = (P·L) I − L Pᵀ divided by its w, 3 entries.
// Classes: near-degenerate = light nearly parallel to / on the receiver, or the point nearly
// on the receiver or nearly level with a point light (relative 2^-4 … 2^-(p−1));
// degenerate = exactly so (then the image is at infinity, or V itself, or does not exist);
// range = P and L scaled (the image does not move) so that P·L and P·V over- or underflow.
// Stable: (s V − t L) / (s − w t) with s = P·L, t = P·V + d: s and t take four products and three
// sums (four roundings on the longest path of a dot product of four terms), then s·V_i, the
// difference and the quotient add three: seven roundings, c = 2 × 7 = 14.
// Beyond the values, the grade says where the float image lies on the line through the light
// and V (image_class), and whether that contradicts the exact class of V.
#include "shadowproof/constructions/shadow.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "../operation_table.h"

namespace shadowproof::detail {
namespace {

template <class N>
exact_outputs<N> exact(const double* in, const conventions& conv) {
  exact_outputs<N> r;
  const plane<N> P = plane_from<N>(in);
  const light<N> L = canonical_light<N>(in + 4, conv);
  const vec4<N> V = vec_from<N>(in + 8, 3, N(1));
  r.cls = classify_point(P, L, V);
  // A point on the receiver is its own shadow: the formula below gives (s V)/s = V, with the
  // derivatives of the shadow around it. When the light is parallel to or on the receiver too
  // (line_in_plane), the whole line from V to the light lies in it and the formula gives 0/0,
  // but V is still where the line meets the receiver.
  if (*r.cls == point_class::line_in_plane ||
      (conv.clamps_behind_receiver && *r.cls == point_class::behind_receiver)) {
    for (std::size_t i = 0; i < 3; ++i) r.values.push_back(V[i]);
    return r;
  }
  const vec4<N> h = shadow_image(P, L, V);
  if (sign_n(h[3]) == 0) {
    r.set_undefined(3);
    return r;
  }
  for (std::size_t i = 0; i < 3; ++i) r.values.push_back(h[i] / h[3]);
  return r;
}

// Where the float image G lies on the line through the light and V (see image_class).
template <class N>
image_class classify_image(const double* in, const conventions& conv, const double* got) {
  for (std::size_t i = 0; i < 3; ++i)
    if (!std::isfinite(got[i])) return image_class::nonfinite;
  const light<N> L = canonical_light<N>(in + 4, conv);
  const vec4<N> V = vec_from<N>(in + 8, 3, N(1));
  const vec4<N> G = vec_from<N>(got, 3, N(1));
  const bool same = got[0] == in[8] && got[1] == in[9] && got[2] == in[10];
  if (L.is_directional()) {
    // Travelling from V towards the light means moving away from a real shadow.
    const N k = (V[0] - G[0]) * L.l[0] + (V[1] - G[1]) * L.l[1] + (V[2] - G[2]) * L.l[2];
    const int s = sign_n(k);
    if (s > 0) return image_class::shadow;
    if (s < 0) return image_class::behind_receiver;
    return same ? image_class::on_receiver : image_class::other;
  }
  // Point light Lc = L/w; G's position on the line is u = (G − Lc)·(V − Lc) / |V − Lc|²,
  // compared with 1 after multiplying by w² (division-free): a = u b with b > 0.
  const N& w = L.l[3];
  N a(0), b(0);
  for (std::size_t i = 0; i < 3; ++i) {
    const N dv = w * V[i] - L.l[i];
    a += (w * G[i] - L.l[i]) * dv;
    b += dv * dv;
  }
  if (sign_n(b) == 0) return image_class::other;  // V is the light
  if (sign_n(a) < 0) return image_class::beyond_light;
  if (sign_n(a) == 0) return image_class::other;
  const int beyond_v = sign_n(N(a - b));
  if (beyond_v > 0) return image_class::shadow;
  if (beyond_v < 0) return image_class::behind_receiver;
  return same ? image_class::on_receiver : image_class::other;
}

// The sides of the receiver and the light an image can be on; the other image classes (on the
// receiver, at the light, off the line) are left to the values.
bool is_side(image_class k) {
  return k == image_class::shadow || k == image_class::behind_receiver || k == image_class::beyond_light;
}

// P·(G, 1) for the float image G, correctly rounded to double, with number type N.
template <class N>
double plane_value_with(const double* in, const double* got) {
  return round_exact<double>(evaluate(plane_from<N>(in), vec_from<N>(got, 3, N(1))));
}

// The class of the float image: the dedicated kernels first, then intervals, then rationals.
image_class image_class_of(const test_case& c, const conventions& conv, const double* got, oracle_mode mode) {
  const double* in = c.inputs.data();
  if (mode == oracle_mode::naive) return classify_image<rational>(in, conv, got);
  image_class k;
  const bool f32 = c.type == scalar_type::f32;
  if (f32 ? fast_image_class_f32(in, conv, got, k) : fast_image_class_f64(in, conv, got, k)) return k;
  try {
    return f32 ? classify_image<ival32>(in, conv, got) : classify_image<ival64>(in, conv, got);
  } catch (const undecided&) {
    return classify_image<rational>(in, conv, got);
  }
}

// The plane value: it cancels to a few ulps of its terms (G is nearly on P), which double
// intervals rarely decide for double inputs; then only this small dot product is redone
// exactly, not the whole case. f32 products are exact in long double's 64-bit significand.
double plane_value(const test_case& c, const double* got, oracle_mode mode) {
  const double* in = c.inputs.data();
  if (mode == oracle_mode::naive) return plane_value_with<rational>(in, got);
  double v;
  if (c.type == scalar_type::f32 ? fast_plane_value_f32(in, got, v) : fast_plane_value_f64(in, got, v)) return v;
  try {
    return plane_value_with<ival64>(in, got);
  } catch (const undecided&) {
    return plane_value_with<rational>(in, got);
  }
}

// Misclassified: the image and the correctly rounded exact image lie on different sides. Both
// classes come from the same classification of a float image, so the correctly rounded answer
// is never misclassified; an image next to the light or to V whose correct rounding is the light
// or V itself is left to the values, as is a non-finite image (its own verdict).
void grade_meaning(case_grade& g, const test_case& c, const conventions& conv, const double* got, bool,
                   oracle_mode mode) {
  const image_class got_class = image_class_of(c, conv, got, mode);
  g.got_class = got_class;
  if (got_class != image_class::nonfinite) g.plane_value = plane_value(c, got, mode);
  if (!is_side(got_class) || g.rejected) return;
  std::array<double, 3> reference{};
  bool same = true;
  for (std::size_t i = 0; i < 3; ++i) {
    const output_grade& o = g.outputs[i];
    if (!o.exact_defined || !std::isfinite(o.reference)) return;
    reference[i] = o.reference;
    same = same && o.reference == got[i];
  }
  if (same) {
    g.reference_class = got_class;
    return;
  }
  const image_class want = image_class_of(c, conv, reference.data(), mode);
  g.reference_class = want;
  g.misclassified = is_side(want) && want != got_class;
}

void point_inputs(case_rng& r, input_class cls, const conventions& req, double* in) {
  const bool directional_only = req.directional_only;
  double* p = in;
  double* l = in + 4;
  double* v = in + 8;
  const int flavour = static_cast<int>(r.integer(0, 2));
  if (cls == input_class::regular || cls == input_class::range) {
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

// Seed 001's clamping shader assumes the light on the positive side of the receiver (above
// the ground): orient the plane so, exactly (negating is exact, the sign is decided exactly).
void generate(case_rng& r, input_class cls, const conventions& requirements, double* in) {
  point_inputs(r, cls, requirements, in);
  if (requirements.clamps_behind_receiver) {
    rational s = 0;
    for (std::size_t k = 0; k < 4; ++k) s += exact_value(in[k]) * exact_value(in[4 + k]);
    if (sgn(s) < 0)
      for (std::size_t k = 0; k < 4; ++k) in[k] = -in[k];
  }
}

// For a point light, how close the line from the light through V is to parallel with the
// receiver: log2(|n·(l − wV)| / (|n| |l − wV|)), the image's w relative to its terms (−inf when
// it is exactly 0 or V is the light, whose image is the zero vector).
double line_closeness(const double* in) {
  if (in[7] == 0) return std::numeric_limits<double>::infinity();
  long double along[3], w = 0, size = 0, normal = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    along[i] = static_cast<long double>(in[4 + i]) - static_cast<long double>(in[7]) * in[8 + i];
    w += static_cast<long double>(in[i]) * along[i];
    size += along[i] * along[i];
    normal += static_cast<long double>(in[i]) * in[i];
  }
  const long double scale = std::sqrt(size * normal);
  if (std::fabs(w) >= 0x1p-40L * scale && scale > 0) return static_cast<double>(std::log2(std::fabs(w) / scale));
  // Near 0 (or V near the light): decide exactly.
  rational exact_along[3], exact_w = 0;
  bool at_light = true;
  for (std::size_t i = 0; i < 3; ++i) {
    exact_along[i] = exact_value(in[4 + i]) - exact_value(in[7]) * exact_value(in[8 + i]);
    at_light = at_light && sgn(exact_along[i]) == 0;
    exact_w += exact_value(in[i]) * exact_along[i];
  }
  if (at_light || sgn(exact_w) == 0) return -std::numeric_limits<double>::infinity();
  long double exact_size = 0;
  for (const rational& a : exact_along) exact_size += static_cast<long double>(to_nearest_double(a)) * to_nearest_double(a);
  return static_cast<double>(std::log2(std::fabs(static_cast<long double>(to_nearest_double(exact_w))) /
                                       std::sqrt(exact_size * normal)));
}

double closeness(const double* in) {
  return std::min({log2_relative_dot(in, in + 4, 4), log2_relative_dot(in, in + 8, 3), line_closeness(in)});
}

std::string reproducer(const test_case& c, const conventions& conv) {
  // `shadow` knows neither a light given along its rays (the image is the same) nor clamping.
  if (conv.clamps_behind_receiver) return exact_command(c, conv);
  return "shadowproof shadow --plane " + hex_list(c, 0, 4) + " --light " + hex_list(c, 4, 4) + " --point " +
         hex_list(c, 8, 3);
}

void from_configuration(const double* plane, const double* light, const double* point, double* in) {
  std::copy(plane, plane + 4, in);
  std::copy(light, light + 4, in + 4);
  std::copy(point, point + 3, in + 8);
}

operation_spec make() {
  operation_spec s{};
  s.op = operation::shadow_point;
  s.name = "shadow-point";
  s.summary = "plane[4], light[4], point[3] -> affine shadow of the point, 3 entries";
  s.signature = make_signature({{"plane", 4}, {"light", 4}, {"point", 3}}, 3, 0);
  s.generate = generate;
  s.closeness = closeness;
  SHADOWPROOF_EXACT_TEMPLATE(s, exact);
  s.sensitivity = shadow_point_sensitivity;
  s.stable_constant = 14;
  s.sentinel_outputs = point_sentinels;
  s.fast_f32 = fast_shadow_point_f32;
  s.fast_f64 = fast_shadow_point_f64;
  s.grade_meaning = grade_meaning;
  s.reproducer = reproducer;
  s.invalid = invalid_plane_and_light;
  s.from_configuration = from_configuration;
  s.symmetries.plane_degree = 0;  // the image does not depend on the scale of P or of L
  s.symmetries.light_degree = 0;
  s.symmetries.swap_xy = true;
  s.symmetries.translation = true;
  return s;
}

}  // namespace

const operation_spec& shadow_point_spec() {
  static const operation_spec s = make();
  return s;
}

}  // namespace shadowproof::detail
