// frustum: box[6] = l, r, b, t, n, f -> frustum(l, r, b, t, n, f, depth), 16 entries: the
// glFrustum perspective of the near-plane window [l, r] × [b, t] at distance n, far plane at
// distance f, onto the canonical volume of the declared depth convention.
// Classes: as ortho; near ≤ 0 (or far ≤ 0) admits no projection, so every output is undefined.
// Stable: 2n/(r − l), (r + l)/(r − l), A = (n z_near − f z_far)/(f − n) and
// B = n f (z_near − z_far)/(f − n) take two or three roundings on their longest path:
// c = 2 × 3 = 6.
#include "view_volume.h"

namespace shadowproof::detail {
namespace {

template <class N>
exact_outputs<N> exact(const double* in, const conventions& conv) {
  const std::array<N, 6> x = box_from<N>(in);
  if (sign_n(x[4]) <= 0 || sign_n(x[5]) <= 0) {  // near or far behind the eye: no such projection
    exact_outputs<N> r;
    r.set_undefined(16);
    return r;
  }
  return view_volume_matrix(
      x, conv,
      [&](const std::array<N, 6>& v) { return frustum(v[0], v[1], v[2], v[3], v[4], v[5], conv.depth, false); },
      [](std::size_t k) { return k < 2 ? std::size_t(2) : std::size_t(3); });
}

std::string reproducer(const test_case& c, const conventions& conv) { return box_reproducer("frustum", c, conv); }

operation_spec make() {
  operation_spec s{};
  s.op = operation::frustum;
  s.name = "frustum";
  s.summary = "box[6] = l, r, b, t, n, f -> perspective frustum in the declared depth convention, 16 entries";
  s.signature = make_signature({{"box", 6}}, 16, 4);
  s.generate = box_inputs;
  s.closeness = box_closeness;
  SHADOWPROOF_EXACT_TEMPLATE(s, exact);
  s.stable_constant = 6;
  s.sentinel_outputs = matrix_sentinels;
  s.fast_f32 = fast_frustum_f32;
  s.fast_f64 = fast_frustum_f64;
  s.reproducer = reproducer;
  s.invalid = never_invalid;
  return s;
}

}  // namespace

const operation_spec& frustum_spec() {
  static const operation_spec s = make();
  return s;
}

}  // namespace shadowproof::detail
