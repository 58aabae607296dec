// ortho: box[6] = l, r, b, t, n, f -> orthographic(l, r, b, t, n, f, depth), 16 entries: the
// box [l, r] × [b, t] × [−f, −n] onto the canonical volume of the declared depth convention.
// Classes: near-degenerate = one extent a relative 2^-4 … 2^-(p−1) of its position, or
// far ≫ near; degenerate = l = r, b = t or n = f (those rows' scale and offset undefined); range
// = the box scaled so that r − l, f + n overflow or 2/(r − l) leaves the range.
// Stable: 2/(r − l) and (r + l)/(r − l) take two roundings on their longest path, z_near + A n
// three (A, then A n): c = 2 × 3 = 6.
#include "view_volume.h"

namespace shadowproof::detail {
namespace {

template <class N>
exact_outputs<N> exact(const double* in, const conventions& conv) {
  return view_volume_matrix(
      box_from<N>(in), conv,
      [&](const std::array<N, 6>& v) { return orthographic(v[0], v[1], v[2], v[3], v[4], v[5], conv.depth); },
      [](std::size_t) { return std::size_t(3); });
}

std::string reproducer(const test_case& c, const conventions& conv) { return box_reproducer("ortho", c, conv); }

operation_spec make() {
  operation_spec s{};
  s.op = operation::ortho;
  s.name = "ortho";
  s.summary = "box[6] = l, r, b, t, n, f -> orthographic projection in the declared depth convention, 16 entries";
  s.signature = make_signature({{"box", 6}}, 16, 4);
  s.generate = box_inputs;
  s.closeness = box_closeness;
  SHADOWPROOF_EXACT_TEMPLATE(s, exact);
  s.stable_constant = 6;
  s.sentinel_outputs = matrix_sentinels;
  s.fast_f32 = fast_ortho_f32;
  s.fast_f64 = fast_ortho_f64;
  s.reproducer = reproducer;
  s.invalid = never_invalid;
  return s;
}

}  // namespace

const operation_spec& ortho_spec() {
  static const operation_spec s = make();
  return s;
}

}  // namespace shadowproof::detail
