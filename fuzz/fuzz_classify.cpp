// Fuzz target: exact classification, and the float instance of the same formula against it.
// Invariants: (1) the exact class agrees with where the exact image sits on the ray from the
// light (an independent characterisation); (2) whenever float arithmetic reproduces s = P·L and
// t = P·V exactly, the float classifier returns the exact class. Set SHADOWPROOF_FUZZ_STRICT=1
// to also stop at the first plain float misclassification (a counterexample for the naive code).
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "shadowproof/constructions/classify.h"
#include "byte_source.h"
#include "shadowproof/constructions/shadow.h"

namespace {

using shadowproof::rational;

template <class F>
bool all_finite(const shadowproof::generated_case<F>& c) {
  for (F x : c.plane) if (!std::isfinite(x)) return false;
  for (F x : c.light) if (!std::isfinite(x)) return false;
  for (F x : c.point) if (!std::isfinite(x)) return false;
  return true;
}

// Ray parameter u of the image on ℓ + u (V − ℓ): u > 1 shadow, 0 < u < 1 behind, u < 0 beyond.
void check_against_ray(const shadowproof::plane<rational>& P, const shadowproof::light<rational>& L,
                       const shadowproof::vec4<rational>& V, shadowproof::point_class c) {
  using namespace shadowproof;
  if (L.is_directional() || dot(P.p, L.l) == 0) return;
  const auto Q = shadow_matrix(P, L) * V;
  if (Q[3] == 0 || is_zero(Q)) {
    if (c != point_class::at_infinity && c != point_class::at_light) std::abort();
    return;
  }
  const vec4<rational> ell = rational(1) / L.l[3] * L.l;
  std::size_t axis = 0;
  while (axis < 3 && V[axis] == ell[axis]) ++axis;
  if (axis == 3) std::abort();  // V = ℓ must have given the zero image
  const rational u = (Q[axis] / Q[3] - ell[axis]) / (V[axis] - ell[axis]);
  const point_class expected = u == 1 ? point_class::on_receiver
                               : u > 1 ? point_class::shadow
                               : u > 0 ? point_class::behind_receiver
                                       : point_class::beyond_light;
  if (c != expected) std::abort();
}

template <class F>
void check_case(const shadowproof::generated_case<F>& c, bool strict) {
  using namespace shadowproof;
  if (!all_finite(c)) return;
  if (c.plane[0] == 0 && c.plane[1] == 0 && c.plane[2] == 0) return;
  if (c.light[0] == 0 && c.light[1] == 0 && c.light[2] == 0 && c.light[3] == 0) return;
  const auto P = make_plane<rational>(rational(c.plane[0]), rational(c.plane[1]), rational(c.plane[2]), rational(c.plane[3]));
  const auto L = make_light<rational>(rational(c.light[0]), rational(c.light[1]), rational(c.light[2]), rational(c.light[3]));
  const auto V = make_point<rational>(rational(c.point[0]), rational(c.point[1]), rational(c.point[2]));
  const point_class exact = classify_point(P, L, V);
  check_against_ray(P, L, V, exact);

  const auto Pf = make_plane<F>(c.plane[0], c.plane[1], c.plane[2], c.plane[3]);
  const auto Lf = make_light<F>(c.light[0], c.light[1], c.light[2], c.light[3]);
  const auto Vf = make_point<F>(c.point[0], c.point[1], c.point[2]);
  const point_class naive = classify_point(Pf, Lf, Vf);
  const F s = dot(Pf.p, Lf.l), t = dot(Pf.p, Vf), wt = Lf.l[3] * t;
  const bool float_exact = std::isfinite(s) && std::isfinite(wt) && rational(s) == dot(P.p, L.l) &&
                           rational(t) == dot(P.p, V) && rational(wt) == L.l[3] * dot(P.p, V);
  // at_light compares V·w with L coordinate-wise: also exact only when those products are.
  bool products_exact = true;
  for (int i = 0; i < 3; ++i)
    products_exact = products_exact && std::isfinite(Vf[i] * Lf.l[3]) && rational(Vf[i] * Lf.l[3]) == V[i] * L.l[3];
  if (float_exact && products_exact && naive != exact) std::abort();
  if (strict && naive != exact) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool strict = std::getenv("SHADOWPROOF_FUZZ_STRICT") != nullptr;
  shadowproof::byte_source src(data, size);
  if (src.byte() % 2 == 0) check_case(shadowproof::decode_shadow_case<float>(src), strict);
  else check_case(shadowproof::decode_shadow_case<double>(src), strict);
  return 0;
}
