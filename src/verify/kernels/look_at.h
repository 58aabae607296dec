#pragma once
// The filter of look-at and target-to (constructions/look_at.h), written once over the real
// type R (lanes.h): one case (R = double, the kernels of camera.cpp) or four (the AVX2 batch
// filter), with the filter numbers of the output type (bounded for f32 cases, double-double
// bounded_pair for f64 ones). No branch on the values within a vector: each step narrows a
// mask of the lanes still decided (the one branch, per vector, is whether any lane needs the
// second pass below), and a lane left undecided goes to the kernel for one case, then to the
// generic oracle.
//
// Every entry is q/√s. The frame W = ±(eye − target) (exact as a pair: TwoSum; in double
// within u |W_i|), X = up × W, Y = W × X, the squared lengths |X|², |W|²|X|², |W|² and the
// translations −(axis · eye), in filter arithmetic. A product with an exact zero factor is an
// exact zero (its bound 0, not underflow_slack), so the zero entries of a frame with an
// axis-aligned up stay exact and round to 0 without a bound to straddle it. √s by `root`
// (its bound below), the quotient by the kernels' certified quotient rounding (rounding.h).
// Where up is close to the view direction, X = up × w cancels and its bound no longer
// decides: the lanes left open are evaluated once more in double-double with X as exact sums
// (accurate_cross), for f32 cases too.
#include <cmath>
#include <type_traits>

#include "bounded.h"
#include "fraction_form.h"
#include "lanes.h"
#include "rounding.h"
#include "shadowproof/verify/conventions.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {
namespace look_at_filter {

/// The range of the inputs, lane by lane: 0 or a magnitude within [2^-60, 2^60] (f32) or
/// [2^-100, 2^100] (f64). Every product of up to six of them and of their differences then
/// stays far above underflow and below overflow in the filter arithmetic.
template <class F, class R>
auto inputs_in_range(const R* x) {
  constexpr double smallest = std::is_same_v<F, float> ? 0x1p-60 : 0x1p-100;
  constexpr double largest = std::is_same_v<F, float> ? 0x1p60 : 0x1p100;
  auto ok = !no_lanes(x[0]);
  SHADOWPROOF_UNROLL
  for (int i = 0; i < 9; ++i) {
    const R a = magnitude(x[i]);
    ok = ok & ((x[i] == R(0.0)) | ((a >= R(smallest)) & (a <= R(largest))));
  }
  return ok;
}

/// a − b for two inputs: exact as a pair (TwoSum); in double within u |a − b| (0 exactly when
/// a = b).
template <class B, class R>
B difference(R a, R b) {
  if constexpr (std::is_same_v<B, basic_bounded_pair<R>>) {
    B r;
    two_sum(a, -b, r.hi, r.lo);
    return r;
  } else {
    return B(a) - B(b);
  }
}

template <class B>
struct vector3 {
  B c[3];
};

template <class B>
[[gnu::always_inline]] inline vector3<B> cross(const vector3<B>& a, const vector3<B>& b) {
  return {{zero_preserving_product(a.c[1], b.c[2]) - zero_preserving_product(a.c[2], b.c[1]),
           zero_preserving_product(a.c[2], b.c[0]) - zero_preserving_product(a.c[0], b.c[2]),
           zero_preserving_product(a.c[0], b.c[1]) - zero_preserving_product(a.c[1], b.c[0])}};
}

template <class B>
[[gnu::always_inline]] inline B dot(const vector3<B>& a, const vector3<B>& b) {
  return zero_preserving_product(a.c[0], b.c[0]) + zero_preserving_product(a.c[1], b.c[1]) +
         zero_preserving_product(a.c[2], b.c[2]);
}

/// √S for every S within s ± s.e, in the lanes where that range is positive (the mask).
///  double: r = fl(√s), |√s − r| ≤ u r; |√S − √s| = |S − s|/(√S + √s) ≤ e/(2L) for any
///  L ≤ √(s − e) (both roots are at least L).
template <class R>
auto root(const basic_bounded<R>& s, basic_bounded<R>& r) {
  const R lower = (s.v - s.e * R(inflate)) * R(1 - 0x1p-50);
  const R L = square_root(lower) * R(1 - 0x1p-50);  // NaN where lower < 0: masked
  r.v = square_root(s.v);
  r.e = (s.e * R(inflate) / (R(2.0) * L) + R(unit_roundoff) * r.v) * R(1 + 0x1p-45);
  return lower > R(0.0);
}
///  double-double: r1 = fl(√hi), D = s − r1² = (hi − p) − p' + lo with r1² = p + p' exactly
///  (TwoProduct; hi − p exact by Sterbenz), d = D rounded twice, |D − d| ≤ u (|t1| + |d|);
///  r2 = fl(d/(2 r1)). Since √s = r1 + D/(√s + r1),
///    |√s − r1 − D/(2 r1)| = D² / ((√s + r1)² 2 r1) ≤ (|D|/L)² / (8 L)   (L ≤ √s, L ≤ r1),
///  then |D − d|/(2 r1) and |r2 − d/(2 r1)| ≤ u |r2|, and e/(2L) for the range of S. The
///  bound's own dozen roundings on non-negative terms are covered by (1 + 2^-45).
template <class R>
auto root(const basic_bounded_pair<R>& s, basic_bounded_pair<R>& r) {
  const R lower = (s.hi - magnitude(s.lo) - s.e * R(inflate)) * R(1 - 0x1p-50);
  const R r1 = square_root(s.hi);
  const R lower_root = square_root(lower);  // NaN where lower < 0: masked
  const R L = select(r1 < lower_root, r1, lower_root) * R(1 - 0x1p-50);
  R p, p_low;
  two_product(r1, r1, p, p_low);
  const R t1 = (s.hi - p) - p_low;
  const R d = t1 + s.lo;
  const R d_error = R(unit_roundoff) * (magnitude(t1) + magnitude(d));
  const R r2 = d / (R(2.0) * r1);
  const R q = (magnitude(d) + d_error) / L;
  two_sum(r1, r2, r.hi, r.lo);
  r.e = (s.e * R(inflate) / (R(2.0) * L) + q * q / (R(8.0) * L) + d_error / (R(2.0) * r1) +
         R(unit_roundoff) * magnitude(r2)) *
            R(1 + 0x1p-45) +
        R(underflow_slack);
  return lower > R(0.0);
}

/// W = ±(eye − target) (+ right-handed: the camera looks down −z) and up, from the inputs
/// x = eye[3], target[3], up[3].
template <class B, class R>
void view_axis_and_up(const R* x, const conventions& conv, vector3<B>& W, vector3<B>& up) {
  const bool right = conv.hand == handedness::right;
  SHADOWPROOF_UNROLL
  for (int i = 0; i < 3; ++i) {
    W.c[i] = right ? difference<B>(x[i], x[3 + i]) : difference<B>(x[3 + i], x[i]);
    up.c[i] = B(x[6 + i]);
  }
}

/// num/den correctly rounded to F, in the lanes the bounds decide: the kernels' certified
/// quotient rounding of the filter number's own type, or, for an f32 case evaluated in
/// double-double (the second pass below), the pair quotient q1 + q2 within E (rounding.h)
/// summed to y = fl(q1 + q2), within E + u |y| of num/den, and that interval's float rounding.
template <class F, class N, class D, class R>
auto round_entry(const N& num, const D& den, R& out) {
  if constexpr (std::is_same_v<F, float> && std::is_same_v<N, basic_bounded_pair<R>>) {
    R q1, q2, E;
    pair_quotient(num, den, q1, q2, E);
    const R y = q1 + q2;
    return den.usable() & round_interval_to_float(y, (E + R(unit_roundoff) * magnitude(y)) * R(inflate), out);
  } else {
    return round_quotient(num, den, out);
  }
}

/// The 16 canonical entries (row-major) of the view matrix (placement false) or of the
/// placement (true) from the frame's W and X = up × W, in the lanes where every bound decides
/// (the mask): rows (x, −x·eye), (y, −y·eye), (z, −z·eye), (0, 0, 0, 1) of the view matrix,
/// columns x, y, z, (eye, 1) of the placement; where |X|² or |W|² is not certainly positive,
/// undecided (the generic oracle says which entries exist).
template <class F, bool placement, class B, class R>
auto frame_entries(const R* x, const vector3<B>& W, const vector3<B>& X, R* values) {
  const vector3<B> Y = cross(W, X);
  const B ww = dot(W, W), xx = dot(X, X);
  B lengths[3];
  auto ok = root(xx, lengths[0]) & root(zero_preserving_product(ww, xx), lengths[1]) & root(ww, lengths[2]);
  const vector3<B>* axes[3] = {&X, &Y, &W};
  vector3<B> eye;
  SHADOWPROOF_UNROLL
  for (int i = 0; i < 3; ++i) eye.c[i] = B(x[i]);
  SHADOWPROOF_UNROLL
  for (int r = 0; r < 3; ++r) {
    const auto d = prepare(lengths[r]);
    SHADOWPROOF_UNROLL
    for (int c = 0; c < 3; ++c) ok = ok & round_entry<F>(axes[r]->c[c], d, values[placement ? c * 4 + r : r * 4 + c]);
    if constexpr (!placement) ok = ok & round_entry<F>(-dot(*axes[r], eye), d, values[r * 4 + 3]);
  }
  if constexpr (placement) {
    // The eye itself, rounded to F (an f32 case's eye is a float: itself), +0 for 0.
    SHADOWPROOF_UNROLL
    for (int r = 0; r < 3; ++r) {
      const R e = std::is_same_v<F, float> ? round_to_float_value(x[r]) : x[r];
      values[r * 4 + 3] = select(e == R(0.0), R(0.0), e);
    }
  }
  SHADOWPROOF_UNROLL
  for (int c = 0; c < 3; ++c) values[12 + c] = R(0.0);
  values[15] = R(1.0);
  return ok;
}

// ===========================================================================================
// The lanes the first pass leaves open, where up × w cancels (up close to the view direction)

/// Σ t[0..n) of n exact doubles as a pair within a bound: three sweeps of TwoSum
/// (rounding.h's swept_sum), errors of the order u³ Σ|t|. All zero: an exact zero.
template <int n, class R>
basic_bounded_pair<R> exact_sum(R* t) {
  basic_bounded_pair<R> r;
  swept_sum<n, 3>(t, r.hi, r.lo, r.e);
  return r;
}

/// up × W with every component accurate to about 2^-106 of itself however much it cancels:
/// a_i b_j − a_j b_i as the exact sum of eight TwoProducts (a = up is exact, b = W an exact
/// pair: their bounds are 0).
template <class R>
vector3<basic_bounded_pair<R>> accurate_cross(const vector3<basic_bounded_pair<R>>& a,
                                              const vector3<basic_bounded_pair<R>>& b) {
  vector3<basic_bounded_pair<R>> r;
  SHADOWPROOF_UNROLL
  for (int c = 0; c < 3; ++c) {
    const int i = (c + 1) % 3, j = (c + 2) % 3;
    R t[8];
    two_product(a.c[i].hi, b.c[j].hi, t[0], t[1]);
    two_product(a.c[i].hi, b.c[j].lo, t[2], t[3]);
    two_product(-a.c[j].hi, b.c[i].hi, t[4], t[5]);
    two_product(-a.c[j].hi, b.c[i].lo, t[6], t[7]);
    r.c[c] = exact_sum<8>(t);
  }
  return r;
}

// ===========================================================================================
// The filter

/// The filter of look-at (placement false) or target-to (true) for inputs x = eye[3],
/// target[3], up[3]: the 16 canonical entries in `values`, and the mask of the lanes where
/// every one is decided (inputs in range, |X|² and |W|² certainly positive, every rounding
/// certified). Where a lane in range is left open (near up ∥ w the components of X cancel),
/// the vector is evaluated once more in double-double, f32 cases too, with X accurate
/// (accurate_cross): such near-degenerate frames are decided as well.
template <class F, bool placement, class R>
auto frame_lanes(const R* x, const conventions& conv, R* values) {
  using B = filter_number_of<F, R>;
  vector3<B> W, up;
  view_axis_and_up(x, conv, W, up);
  const auto in_range = inputs_in_range<F>(x);
  auto ok = in_range & frame_entries<F, placement>(x, W, cross(up, W), values);
  const auto open = in_range & !ok;
  if (any_lane(open)) {
    using P = basic_bounded_pair<R>;
    vector3<P> W2, up2;
    view_axis_and_up(x, conv, W2, up2);
    R again[16];
    const auto decided = open & frame_entries<F, placement>(x, W2, accurate_cross(up2, W2), again);
    SHADOWPROOF_UNROLL
    for (int j = 0; j < 16; ++j) values[j] = select(decided, again[j], values[j]);
    ok = ok | decided;
  }
  return ok;
}

}  // namespace look_at_filter
}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
