#pragma once
// The scale λ of a result graded up to scale (a homogeneous matrix), chosen exactly over the
// oracle's number type N (rational, or an interval that throws `undecided`).
//
// For an exact entry e ≠ 0 and an output g, the λ with round(λ e) = g form an interval: the
// real numbers that round to g, [ (g + g⁻)/2, (g + g⁺)/2 ] with g⁻, g⁺ its neighbours, divided by
// e (ends swapped when e < 0; taken closed, which only matters for a λ exactly on an end). The
// pivot k (the largest |e_k|, first on ties) fixes the first interval; every other entry, in
// order of decreasing magnitude, narrows it when the intersection stays non-empty and is passed
// over otherwise (an output that overflowed to ±Inf narrows it to a half-line: λ·e at or beyond
// the overflow threshold); λ is the midpoint of what remains. If some λ₀ rounds every entry to the output,
// no entry is passed over and λ lies in every interval: every entry grades 0 ulps. An entry in
// error is graded against λ·e and shows its error in full.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include "exact_outputs.h"

namespace shadowproof::detail {

// The real numbers that round to the finite F value g: [(g + g⁻)/2, (g + g⁺)/2] with g⁻, g⁺ its
// neighbours; beyond the largest finite value, the overflow threshold g + (g − g⁻)/2. Midpoints
// of F values are exact in the oracle's types (they have more bits than F).
template <class N, class F>
void rounding_interval(F g, N& low, N& high) {
  const double x = static_cast<double>(g);
  const F below = std::nextafter(g, -std::numeric_limits<F>::infinity());
  const F above = std::nextafter(g, std::numeric_limits<F>::infinity());
  const double gap_below = std::isinf(below) ? static_cast<double>(above) - x : x - static_cast<double>(below);
  const double gap_above = std::isinf(above) ? x - static_cast<double>(below) : static_cast<double>(above) - x;
  low = from_double<N>(x) - from_double<N>(gap_below) / N(2);
  high = from_double<N>(x) + from_double<N>(gap_above) / N(2);
}

// The λ for which round(λ e) = g (e ≠ 0 of sign s): an interval for a finite g; for g = ±Inf a
// half-line, λ e at or beyond the overflow threshold (an unbounded end is nothing).
template <class N>
struct scale_range {
  std::optional<N> lo, hi;
};

template <class N, class F>
scale_range<N> scale_interval(const N& e, int s, F g) {
  N low, high;
  if (std::isinf(g)) {
    rounding_interval<N, F>(std::numeric_limits<F>::max(), low, high);  // high: the overflow threshold
    const N threshold = g > 0 ? high : N(-high);
    // λ e ≥ T (g = +Inf) or λ e ≤ −T (g = −Inf): divided by e, the inequality turns with its sign.
    const bool at_least = (g > 0) == (s > 0);
    return at_least ? scale_range<N>{N(threshold / e), std::nullopt} : scale_range<N>{std::nullopt, N(threshold / e)};
  }
  rounding_interval<N, F>(g, low, high);
  return s > 0 ? scale_range<N>{N(low / e), N(high / e)} : scale_range<N>{N(high / e), N(low / e)};
}

/// The pivot and the scale λ for exact entries `e` (n of them, `defined` marks those that exist)
/// and outputs `got` (values of type F widened to double). The pivot is the entry of largest
/// exact magnitude (first on ties) among those whose output is finite and non-zero, or, when every
/// such output overflowed, the largest entry whose output is ±Inf. Nothing when no entry gives a
/// scale: the caller grades with λ = 1.
template <class N, class F>
std::optional<N> choose_scale(const std::array<N, 16>& e, const std::array<bool, 16>& defined, std::size_t n,
                              const double* got, std::size_t& pivot) {
  // Entries that constrain λ: an exact value ≠ 0 and an output that is not NaN.
  std::array<std::size_t, 16> order{};
  std::array<F, 16> size{};
  std::size_t m = 0;
  for (std::size_t j = 0; j < n; ++j) {
    if (!defined[j] || std::isnan(got[j]) || sign_n(e[j]) == 0) continue;
    size[j] = std::fabs(round_exact<F>(e[j]));
    order[m++] = j;
  }
  // By decreasing magnitude (of the correct roundings, which every oracle mode computes alike,
  // so that the order and λ do not depend on the mode), finite non-zero outputs first.
  const auto finite = [&](std::size_t j) { return std::isfinite(got[j]) && got[j] != 0; };
  std::stable_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(m), [&](std::size_t a, std::size_t b) {
    if (finite(a) != finite(b)) return finite(a);
    return size[a] > size[b];
  });
  if (m == 0 || (!finite(order[0]) && std::isfinite(got[order[0]]))) {
    pivot = 0;
    return std::nullopt;
  }
  // The pivot: the largest exact magnitude, the first index on ties. Rounding is monotone, so
  // only entries whose rounded magnitude ties with the first can be larger.
  std::size_t k = order[0];
  for (std::size_t t = 1; t < m && finite(order[t]) == finite(order[0]) && size[order[t]] == size[order[0]]; ++t) {
    const int d = sign_n(N(abs_n(e[order[t]]) - abs_n(e[k])));
    if (d > 0 || (d == 0 && order[t] < k)) k = order[t];
  }
  pivot = k;
  scale_range<N> range = scale_interval<N, F>(e[k], sign_n(e[k]), static_cast<F>(got[k]));
  for (std::size_t t = 0; t < m; ++t) {
    const std::size_t j = order[t];
    if (j == k) continue;
    const scale_range<N> r = scale_interval<N, F>(e[j], sign_n(e[j]), static_cast<F>(got[j]));
    scale_range<N> next = range;
    if (r.lo && (!range.lo || sign_n(N(*r.lo - *range.lo)) > 0)) next.lo = r.lo;
    if (r.hi && (!range.hi || sign_n(N(*r.hi - *range.hi)) < 0)) next.hi = r.hi;
    if (!next.lo || !next.hi || sign_n(N(*next.hi - *next.lo)) >= 0) range = next;
  }
  if (range.lo && range.hi) return N((*range.lo + *range.hi) / N(2));
  // Only overflowed outputs: a half-line away from 0; twice its end lies well inside.
  return N(N(2) * (range.lo ? *range.lo : *range.hi));
}

}  // namespace shadowproof::detail
