// ortho-size and perspective-size: size[4] = w, h, n, f -> the symmetric view volume of width w
// and height h (at the near plane, for the perspective), i.e. ortho and frustum of the box
// (−w/2, w/2, −h/2, h/2, n, f), in the declared depth convention and handedness, 16 entries.
// The builders that take a width and a height (Babylon.js OrthoLH and PerspectiveLH, D3DX's
// MatrixOrthoLH and MatrixPerspectiveLH, Irrlicht's buildProjectionMatrixOrtho*):
//   ortho:       [2/w 0 0 0; 0 2/h 0 0; 0 0 A B; 0 0 0 1]
//   perspective: [2n/w 0 0 0; 0 2n/h 0 0; 0 0 A B; 0 0 −1 0]   (A, B as in project.h)
// Stable: 2/w (2n/w) one or two roundings, A and B as ortho and frustum: c = 2 × 3 = 6.
// Classes: near-degenerate = far within a relative 2^-k of near, or far ≫ near; degenerate =
// w = 0, h = 0 or n = f (only the scale of that axis is undefined: the centre offsets are 0 by
// construction). A non-positive w or h, or (perspective) n or f ≤ 0, admits no projection.
#include <cmath>
#include <limits>

#include "view_volume.h"

namespace shadowproof::detail {
namespace {

template <class N, bool perspective>
exact_outputs<N> exact(const double* in, const conventions& conv) {
  const N w = from_double<N>(in[0]), h = from_double<N>(in[1]), n = from_double<N>(in[2]), f = from_double<N>(in[3]);
  if (sign_n(w) < 0 || sign_n(h) < 0 || (perspective && (sign_n(n) <= 0 || sign_n(f) <= 0))) {
    exact_outputs<N> r;
    r.set_undefined(16);
    return r;
  }
  // The symmetric box; halving is exact in every number type.
  const N half(N(1) / N(2));
  const std::array<N, 6> box{N(-w * half), N(w * half), N(-h * half), N(h * half), n, f};
  conventions symmetric = conv;
  symmetric.symmetric_view = true;
  return view_volume_matrix(
      box, symmetric,
      [&](const std::array<N, 6>& v) {
        if constexpr (perspective) return frustum(v[0], v[1], v[2], v[3], v[4], v[5], conv.depth, false);
        else return orthographic(v[0], v[1], v[2], v[3], v[4], v[5], conv.depth);
      },
      [](std::size_t k) { return perspective && k < 2 ? std::size_t(2) : std::size_t(3); });
}

double positive(case_rng& r, int emin, int emax) {
  double v = 0;
  while (v == 0) v = std::fabs(r.value(emin, emax));
  return v;
}

void generate(case_rng& r, input_class cls, const conventions&, double* x) {
  x[0] = r.fit(positive(r, -1, 3));
  x[1] = r.fit(positive(r, -1, 3));
  x[2] = r.fit(positive(r, -4, 0));
  x[3] = r.fit(x[2] + positive(r, 0, 6));
  if (cls == input_class::near_degenerate) {
    if (r.raw() & 1) {
      x[3] = x[2] * std::ldexp(1.0, static_cast<int>(r.integer(10, r.bits() == 24 ? 60 : 400)));  // far ≫ near
    } else {
      const int k = static_cast<int>(r.integer(4, r.bits() - 1));
      x[3] = r.fit(x[2] + std::ldexp(x[2], -k));  // far a relative 2^-k beyond near
    }
  } else if (cls == input_class::degenerate) {
    const int which = static_cast<int>(r.integer(0, 2));
    if (which < 2) x[which] = 0;
    else x[3] = x[2];
  } else if (cls == input_class::range) {
    // n and f scaled by one power of two so that n f overflows, or underflows.
    const int top = top_exponent(x + 2, 2);
    const int e = (r.raw() & 1) ? max_exponent(r) / 2 - top + static_cast<int>(r.integer(1, 3))
                                : min_normal_exponent(r) / 2 - top - 3 - static_cast<int>(r.integer(0, 2));
    if (!scale_exactly(r, x + 2, 2, e)) generate(r, cls, conventions{}, x);  // draw again
  }
}

// log2 of the relative depth extent; −inf for a flat volume.
double closeness(const double* x) {
  if (x[0] == 0 || x[1] == 0) return -std::numeric_limits<double>::infinity();
  const long double extent = std::fabs(static_cast<long double>(x[3]) - x[2]);
  if (extent == 0) return -std::numeric_limits<double>::infinity();
  return static_cast<double>(
      std::log2(extent / (std::fabs(static_cast<long double>(x[2])) + std::fabs(static_cast<long double>(x[3])))));
}

// The box's own reproducer: l = −w/2 … t = h/2, exact halves written as hex floats.
template <bool perspective>
std::string reproducer(const test_case& c, const conventions& conv) {
  // Inputs `project` rejects (a flat or inverted volume) and halves that would round: the
  // exact command of the case itself.
  const double* x = c.inputs.data();
  const bool proper = x[0] > 0 && x[1] > 0 && x[2] != x[3] && (!perspective || (x[2] > 0 && x[3] > 0)) &&
                      x[0] / 2 * 2 == x[0] && x[1] / 2 * 2 == x[1] && x[0] / 2 != 0 && x[1] / 2 != 0 &&
                      std::fabs(x[0]) >= std::numeric_limits<double>::min() * 4 &&
                      std::fabs(x[1]) >= std::numeric_limits<double>::min() * 4;
  if (!proper) return exact_command(c, conv);
  test_case box = c;
  box.inputs = {-c.inputs[0] / 2, c.inputs[0] / 2, -c.inputs[1] / 2, c.inputs[1] / 2, c.inputs[2], c.inputs[3]};
  return box_reproducer(perspective ? "frustum" : "ortho", box, conv);
}

template <bool perspective>
operation_spec make() {
  operation_spec s{};
  s.op = perspective ? operation::perspective_size : operation::ortho_size;
  s.name = perspective ? "perspective-size" : "ortho-size";
  s.summary = perspective ? "size[4] = width, height (at the near plane), n, f -> symmetric perspective frustum, 16 entries"
                          : "size[4] = width, height, n, f -> symmetric orthographic projection, 16 entries";
  s.signature = make_signature({{"size", 4}}, 16, 4);
  s.generate = generate;
  s.closeness = closeness;
  s.exact_rational = exact<rational, perspective>;
  s.exact_ival32 = exact<ival32, perspective>;
  s.exact_ival64 = exact<ival64, perspective>;
  s.derivatives_ival32 = exact<dual<ival32>, perspective>;
  s.derivatives_ival64 = exact<dual<ival64>, perspective>;
  s.derivatives_rational = exact<dual<rational>, perspective>;
  s.stable_constant = 6;
  s.sentinel_outputs = matrix_sentinels;
  s.reproducer = reproducer<perspective>;
  s.invalid = never_invalid;
  return s;
}

}  // namespace

const operation_spec& ortho_size_spec() {
  static const operation_spec s = make<false>();
  return s;
}

const operation_spec& perspective_size_spec() {
  static const operation_spec s = make<true>();
  return s;
}

}  // namespace shadowproof::detail
