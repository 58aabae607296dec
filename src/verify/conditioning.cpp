// Verdicts from the exact partial derivatives, and the conditioning report of a case.
//
// For an output with exact value f (times the scale λ when graded up to scale) and output g:
//   D = Σ_j |∂f/∂x_j| |x_j|       what the inputs contribute to f: perturbing every input by a
//                                  relative ε moves f by at most ε D (to first order);
//   η = |g − f| / (|f| + D)        the mixed backward error: g = f(x + Δx) + Δf with
//                                  |Δx_j| ≤ η |x_j| and |Δf| ≤ η |f| (to first order).
// Forward error ≤ condition × backward error: |g − f| / |f| ≤ η (1 + κ) with κ = D / |f|.
#include "conditioning.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "dual.h"
#include "operation_table.h"
#include "scale.h"
#include "sensitivity.h"
#include "shadowproof/core/error.h"

namespace shadowproof {
namespace detail {
namespace {

template <class F>
constexpr double unit() {
  return std::numeric_limits<F>::epsilon() / 2;
}

template <class B>
exact_outputs<dual<B>> derivatives(const operation_spec& spec, const test_case& c, const conventions& conv,
                                   derivative_context& context) {
  const derivative_scope scope(context);
  if constexpr (std::is_same_v<B, rational>) return spec.derivatives_rational(c.inputs.data(), conv);
  else if constexpr (std::is_same_v<B, ival32>) return spec.derivatives_ival32(c.inputs.data(), conv);
  else return spec.derivatives_ival64(c.inputs.data(), conv);
}

template <class F>
derivative_context context_for(const operation_spec& spec, const test_case& c) {
  derivative_context context;
  context.inputs = c.inputs.data();
  context.count = std::min(c.inputs.size(), max_derivative_inputs);
  context.singular_threshold = spec.stable_constant * unit<F>();
  context.max_finite = static_cast<double>(std::numeric_limits<F>::max());
  context.min_normal = static_cast<double>(std::numeric_limits<F>::min());
  return context;
}

// A note or a comparison that must be decided: undecided throws, and the caller redoes the case
// with rationals.
bool certain(noted fact) {
  if (fact == noted::undecided) throw undecided{};
  return fact == noted::yes;
}

// The exact values f and sizes D of the outputs, in the implementation's layout and scale.
template <class B>
struct scaled_outputs {
  std::array<B, 16> value;
  std::array<B, 16> sensitivity;
  std::array<bool, 16> defined;
  std::array<noted, 16> near_singular;
  std::array<noted, 16> out_of_range;
  std::size_t count = 0;
};

template <class B, class F>
scaled_outputs<B> scale_outputs(const operation_spec& spec, const test_case& c, const conventions& conv,
                                const double* got, const exact_outputs<dual<B>>& e) {
  scaled_outputs<B> s;
  const std::size_t n = spec.signature.output_count, k = spec.signature.matrix_size;
  s.count = n;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = canonical_index(j, k, conv);
    s.defined[j] = e.defined && (e.entry_undefined.empty() || !e.entry_undefined[i]);
    s.value[j] = e.values[i].value();
    s.near_singular[j] = e.values[i].near_singular();
    s.out_of_range[j] = e.values[i].out_of_range();
    B size(0);
    for (std::size_t q = 0; q < e.values[i].lanes() && q < c.inputs.size(); ++q)
      size += magnitude_of(e.values[i].derivative(q)) * magnitude_of(base_from(c.inputs[q], static_cast<const B*>(nullptr)));
    s.sensitivity[j] = size;
  }
  if (graded_up_to_scale(spec, conv) && e.defined) {
    std::size_t pivot = 0;
    if (const auto lambda = choose_scale<B, F>(s.value, s.defined, n, got, pivot)) {
      const B size = magnitude_of(*lambda);
      for (std::size_t j = 0; j < n; ++j) {
        s.value[j] = *lambda * s.value[j];
        s.sensitivity[j] = size * s.sensitivity[j];
      }
    }
  }
  return s;
}

// f outside the normal range of F: beyond the largest finite value, or nonzero below the
// smallest normal one.
template <class B, class F>
bool value_out_of_range(const B& f) {
  const B size = magnitude_of(f);
  const B top = base_from(static_cast<double>(std::numeric_limits<F>::max()), static_cast<const B*>(nullptr));
  if (certain(exceeds(size, top))) return true;
  int s = 0;
  if (!decided_sign_of(f, s)) throw undecided{};
  if (s == 0) return false;
  const B bottom = base_from(static_cast<double>(std::numeric_limits<F>::min()), static_cast<const B*>(nullptr));
  return certain(exceeds(bottom, size));
}

// x² beyond the largest finite value of F (high) or below its smallest normal value (low),
// decided from the exponent and exactly near the boundary.
template <class F>
bool square_leaves_range(double x, bool high) {
  const int e = std::ilogb(x);  // |x| ∈ [2^e, 2^(e+1)), x² ∈ [2^2e, 2^(2e+2))
  const int top = std::numeric_limits<F>::max_exponent;  // max < 2^top, max ≥ 2^(top−1)
  const int bottom = std::numeric_limits<F>::min_exponent - 1;  // smallest normal 2^bottom
  if (high ? 2 * e >= top : 2 * e + 2 <= bottom) return true;
  if (high ? 2 * e + 2 <= top - 1 : 2 * e >= bottom) return false;
  const rational square = exact_value(x) * exact_value(x);
  return high ? square > exact_value(static_cast<double>(std::numeric_limits<F>::max()))
              : square < exact_value(static_cast<double>(std::numeric_limits<F>::min()));
}

// Some product of two inputs (a square included) leaves the normal range of F: any evaluation
// that multiplies them, or normalises a vector of them, over- or underflows.
template <class F>
bool inputs_out_of_range(const test_case& c) {
  double top = 0, bottom = std::numeric_limits<double>::infinity();
  for (double x : c.inputs)
    if (x != 0) {
      top = std::max(top, std::fabs(x));
      bottom = std::min(bottom, std::fabs(x));
    }
  return top != 0 && (square_leaves_range<F>(top, true) || square_leaves_range<F>(bottom, false));
}

template <class B, class F, class RangeLimited>
verdict decide(pending_kind kind, double got, const B& f, const B& sensitivity, noted near_singular,
               const RangeLimited& case_out_of_range, int stable_constant, double tau) {
  const auto from = [](double x) { return base_from(x, static_cast<const B*>(nullptr)); };
  const auto out_of_range = [&] { return case_out_of_range() || value_out_of_range<B, F>(f); };
  if (kind != pending_kind::finite) {
    if (certain(near_singular)) return verdict::stable;
    if (out_of_range()) return verdict::range;
    return kind == pending_kind::nonfinite ? verdict::nonfinite : verdict::wrong;
  }
  const B error = magnitude_of(B(from(got) - f));
  const B scale = magnitude_of(f) + sensitivity;
  if (!certain(exceeds(error, B(from(stable_constant * unit<F>()) * scale)))) return verdict::stable;
  if (out_of_range()) return verdict::range;
  if (!certain(exceeds(error, B(from(tau) * scale)))) return verdict::unstable;
  return verdict::wrong;
}

template <class B, class F>
void decide_with(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                 const pending_outputs& pending) {
  const operation_spec& spec = spec_of(c.op);
  derivative_context context = context_for<F>(spec, c);
  const exact_outputs<dual<B>> e = derivatives<B>(spec, c, conv, context);
  const scaled_outputs<B> s = scale_outputs<B, F>(spec, c, conv, got, e);
  const double tau = wrong_threshold(c.type);
  // The range: anything the evaluation met, or a product of two inputs; decided lazily, only an
  // output that is not stable asks.
  std::optional<bool> case_out_of_range;
  const auto range_limited = [&] {
    if (!case_out_of_range) case_out_of_range = inputs_out_of_range<F>(c) || certain(context.out_of_range);
    return *case_out_of_range;
  };
  std::array<verdict, 16> decided{};
  for (std::size_t t = 0; t < pending.count; ++t) {
    const std::size_t j = pending.index[t];
    if (!s.defined[j]) throw internal_error("an output whose exact value does not exist waits for its derivatives");
    decided[t] = decide<B, F>(pending.kind[t], got[j], s.value[j], s.sensitivity[j], s.near_singular[j],
                              range_limited, spec.stable_constant, tau);
  }
  // Only now, when every verdict is decided: an undecided interval leaves g untouched.
  for (std::size_t t = 0; t < pending.count; ++t) g.outputs[pending.index[t]].v = decided[t];
}

template <class F, class I>
void decide_filtered(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                     const pending_outputs& pending, oracle_mode mode) {
  if (mode == oracle_mode::filtered) {
    try {
      decide_with<I, F>(g, c, conv, got, pending);
      return;
    } catch (const undecided&) {
    }
  }
  decide_with<rational, F>(g, c, conv, got, pending);
}

double to_double(const rational& q) { return to_nearest_double(q); }

// Operations without derivatives over dual numbers (exact values with square roots or
// cotangents, computed as correctly rounding rational representatives): D_i estimated from the
// exact oracle itself, D_i ≈ Σ_j max |f_i(x ± δ_j e_j) − f_i(x)| |x_j| / |δ_j| over both sides
// and |δ_j| ≈ 2^-20, 2^-34 and 2^-48 |x_j| (exactly the difference of the two double inputs):
// near a singularity a bounded output (a unit vector) saturates over the longer steps, so the
// shorter ones see the slope. A representative is within a double's ulp of f_i, so a quotient
// is within 2^-4 |f_i| of the difference quotient even at 2^-48: it can only enlarge D by a
// fraction of |f_i|, which moves η by a few percent; every maximum errs towards a larger D (a
// verdict towards stable). A perturbed input on which some output stops
// existing, or a quotient that does not settle, counts as D = ∞: the problem is singular within
// 2^-20, and any output there is `stable`.
// An enclosure of the representative the rational oracle holds for an output whose exact value
// lies in v (constructions/irrational.h): the lower end of an MPFR enclosure at p ≥ 64 bits
// whose ends round alike. A point v is exact, and so is the representative (Ziv's loop returns
// the common end; exact square roots are caught first). Otherwise either the representative is
// s√q's lower end RNDD(√RNDD(q)) ≥ √q (1 − 2^(1−p))², within 2^-62 |f| of f, or it lies in the
// 64-bit enclosure of cot(fovy/2) (over aspect) that the interval oracle itself returns
// (the enclosures nest as p grows): widening v by 2^-62 of its magnitude covers both.
ival64 representative_enclosure(const ival64& v) {
  if (v.is_point()) return v;
  const long double w = ival64::up(ival64::up(std::fabs(v.mid()) + v.radius()) * 0x1p-62L);
  return v + ival64::between(-w, w);
}

// Every pending output certainly `stable` with D no larger than the part of the sum enclosed in
// `partial`: the terms still to come are non-negative, so D can only grow and the verdict holds.
bool all_stable_already(const pending_outputs& pending, const std::array<bool, 16>& unbounded,
                        const std::array<ival64, 16>& value, const std::array<ival64, 16>& partial,
                        const double* got, double stable_constant_u) {
  const ival64 stable = ival64::point(stable_constant_u);
  for (std::size_t t = 0; t < pending.count; ++t) {
    if (unbounded[t]) continue;
    const ival64 size = magnitude(value[t]);
    if (pending.kind[t] != pending_kind::finite) {
      // D > 0 and c·u·D ≥ |f| for every point.
      if (exceeds(partial[t], ival64(0)) != noted::yes || exceeds(size, ival64(stable * partial[t])) != noted::no)
        return false;
    } else {
      const ival64 error = magnitude(ival64(ival64::point(got[pending.index[t]]) - value[t]));
      if (exceeds(error, ival64(stable * ival64(size + partial[t]))) != noted::no) return false;
    }
  }
  return true;
}

// decide_generic's verdicts from long double intervals, without a rational evaluation: every
// representative f_i(x) and f_i(x ± δ_j e_j) is enclosed (representative_enclosure), so D_i
// lies in [D_lo, D_hi] and η in the matching range, and a verdict is given only when it is the
// same over the whole range: the verdict decide_generic reaches over rationals. False (g
// untouched) when an interval cannot decide which outputs exist or some verdict.
template <class F>
bool decide_generic_enclosed(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                             const pending_outputs& pending) {
  const operation_spec& spec = spec_of(c.op);
  if (!spec.exact_ival64) return false;
  const std::size_t k = spec.signature.matrix_size;
  try {
    const exact_outputs<ival64> e = spec.exact_ival64(c.inputs.data(), conv);
    if (!e.defined) return false;  // the rational path says what is wrong
    std::array<std::size_t, 16> at{};
    std::array<ival64, 16> value{}, sensitivity{};
    std::array<bool, 16> unbounded{};
    for (std::size_t t = 0; t < pending.count; ++t) {
      at[t] = canonical_index(pending.index[t], k, conv);
      if (!e.entry_undefined.empty() && e.entry_undefined[at[t]]) return false;
      value[t] = representative_enclosure(e.values[at[t]]);
    }
    std::vector<double> x = c.inputs;
    for (std::size_t j = 0; j < x.size(); ++j) {
      const double xj = c.inputs[j];
      if (xj == 0) continue;
      // Bounds of max over the steps of |f_i(x + δ) − f_i(x)| |x_j| / |δ|.
      std::array<long double, 16> steepest_lo{}, steepest_hi{};
      for (const double side : {1.0, -1.0})
      for (const int step_exponent : {-20, -34, -48}) {
        const double moved = xj + side * std::ldexp(std::fabs(xj), step_exponent);
        bool settled = moved != xj && std::isfinite(moved);
        exact_outputs<ival64> p;
        if (settled) {
          x[j] = moved;
          p = spec.exact_ival64(x.data(), conv);  // undecided: the rational path decides
          settled = p.defined;
          x[j] = xj;
        }
        if (!settled) {
          for (std::size_t t = 0; t < pending.count; ++t) unbounded[t] = true;
          continue;
        }
        // moved and xj are within a factor 2 of each other: their difference is exact (Sterbenz).
        const ival64 ratio = ival64::point(std::fabs(xj)) / ival64::point(std::fabs(moved - xj));
        for (std::size_t t = 0; t < pending.count; ++t) {
          const std::size_t i = at[t];
          if (!p.entry_undefined.empty() && p.entry_undefined[i]) {
            unbounded[t] = true;
            continue;
          }
          const ival64 d = magnitude(ival64(representative_enclosure(p.values[i]) - value[t])) * ratio;
          steepest_lo[t] = std::max(steepest_lo[t], std::max(0.0L, d.lower()));
          steepest_hi[t] = std::max(steepest_hi[t], d.upper());
        }
      }
      for (std::size_t t = 0; t < pending.count; ++t)
        sensitivity[t] += ival64::between(steepest_lo[t], steepest_hi[t]);
      if (all_stable_already(pending, unbounded, value, sensitivity, got, spec.stable_constant * unit<F>())) {
        for (std::size_t t = 0; t < pending.count; ++t) g.outputs[pending.index[t]].v = verdict::stable;
        return true;
      }
    }
    const ival64 stable = ival64::point(spec.stable_constant * unit<F>());
    const ival64 tau = ival64::point(wrong_threshold(c.type));
    std::optional<bool> inputs_ranged;
    const auto out_of_range = [&](const ival64& f) {
      if (!inputs_ranged) inputs_ranged = inputs_out_of_range<F>(c);
      return *inputs_ranged || value_out_of_range<ival64, F>(f);
    };
    std::array<verdict, 16> decided{};
    for (std::size_t t = 0; t < pending.count; ++t) {
      const std::size_t j = pending.index[t];
      const ival64& f = value[t];
      const ival64 size = magnitude(f);
      verdict v;
      if (pending.kind[t] != pending_kind::finite) {
        // As over rationals: stable when D > 0 and c·u·D ≥ |f|; |f| > c·u·D settles it alone.
        const noted above = exceeds(size, ival64(stable * sensitivity[t]));
        if (unbounded[t] || (above != noted::yes && certain(exceeds(sensitivity[t], ival64(0))) && !certain(above)))
          v = verdict::stable;
        else if (out_of_range(f)) v = verdict::range;
        else v = pending.kind[t] == pending_kind::nonfinite ? verdict::nonfinite : verdict::wrong;
      } else {
        const ival64 error = magnitude(ival64(ival64::point(got[j]) - f));
        const ival64 scale = size + sensitivity[t];
        if (unbounded[t] || !certain(exceeds(error, ival64(stable * scale)))) v = verdict::stable;
        else if (out_of_range(f)) v = verdict::range;
        else if (!certain(exceeds(error, ival64(tau * scale)))) v = verdict::unstable;
        else v = verdict::wrong;
      }
      decided[t] = v;
    }
    for (std::size_t t = 0; t < pending.count; ++t) g.outputs[pending.index[t]].v = decided[t];
    return true;
  } catch (const undecided&) {
    return false;
  }
}

template <class F>
void decide_generic(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                    const pending_outputs& pending) {
  const operation_spec& spec = spec_of(c.op);
  const std::size_t k = spec.signature.matrix_size;
  const exact_outputs<rational> e = spec.exact_rational(c.inputs.data(), conv);
  if (!e.defined) throw internal_error("an output whose exact value does not exist waits for its sensitivity");
  std::array<std::size_t, 16> at{};
  std::array<rational, 16> sensitivity{};
  std::array<bool, 16> unbounded{};
  for (std::size_t t = 0; t < pending.count; ++t) {
    at[t] = canonical_index(pending.index[t], k, conv);
    if (!e.entry_undefined.empty() && e.entry_undefined[at[t]])
      throw internal_error("an output whose exact value does not exist waits for its sensitivity");
  }
  std::vector<double> x = c.inputs;
  for (std::size_t j = 0; j < x.size(); ++j) {
    const double xj = c.inputs[j];
    if (xj == 0) continue;  // a zero input stays zero under relative perturbations
    std::array<rational, 16> steepest{};
    for (const double side : {1.0, -1.0})
    for (const int step_exponent : {-20, -34, -48}) {
      const double moved = xj + side * std::ldexp(std::fabs(xj), step_exponent);
      bool settled = moved != xj && std::isfinite(moved);
      exact_outputs<rational> p;
      if (settled) {
        x[j] = moved;
        try {
          p = spec.exact_rational(x.data(), conv);
          settled = p.defined;
        } catch (const undecided&) {
          settled = false;
        }
        x[j] = xj;
      }
      const rational step = settled ? rational(abs(exact_value(moved) - exact_value(xj))) : rational(1);
      for (std::size_t t = 0; t < pending.count; ++t) {
        const std::size_t i = at[t];
        if (!settled || (!p.entry_undefined.empty() && p.entry_undefined[i])) {
          unbounded[t] = true;
          continue;
        }
        const rational d = abs(p.values[i] - e.values[i]) * abs(exact_value(xj)) / step;
        if (d > steepest[t]) steepest[t] = d;
      }
    }
    for (std::size_t t = 0; t < pending.count; ++t) sensitivity[t] += steepest[t];
  }
  const rational stable = rational(exact_value(spec.stable_constant * unit<F>()));
  const rational tau = rational(exact_value(wrong_threshold(c.type)));
  std::optional<bool> inputs_ranged;
  const auto out_of_range = [&](const rational& f) {
    if (!inputs_ranged) inputs_ranged = inputs_out_of_range<F>(c);
    return *inputs_ranged || value_out_of_range<rational, F>(f);
  };
  for (std::size_t t = 0; t < pending.count; ++t) {
    const std::size_t j = pending.index[t];
    const rational& f = e.values[at[t]];
    const rational size = abs(f);
    verdict v;
    if (pending.kind[t] != pending_kind::finite) {
      // Near singular when a relative c·u of the inputs can move f by |f| (κ ≥ 1/(c·u)).
      if (unbounded[t] || (sgn(sensitivity[t]) > 0 && stable * sensitivity[t] >= size)) v = verdict::stable;
      else if (out_of_range(f)) v = verdict::range;
      else v = pending.kind[t] == pending_kind::nonfinite ? verdict::nonfinite : verdict::wrong;
    } else {
      const rational error = abs(exact_value(got[j]) - f);
      const rational scale = size + sensitivity[t];
      if (unbounded[t] || error <= stable * scale) v = verdict::stable;
      else if (out_of_range(f)) v = verdict::range;
      else if (error <= tau * scale) v = verdict::unstable;
      else v = verdict::wrong;
    }
    g.outputs[j].v = v;
  }
}


template <class B, class F>
bool leaves_range_with(const test_case& c, const conventions& conv) {
  if (inputs_out_of_range<F>(c)) return true;
  const operation_spec& spec = spec_of(c.op);
  if (!spec.derivatives_rational || c.inputs.size() > max_derivative_inputs) {
    // No dual evaluation to watch the intermediates: the exact outputs themselves.
    const exact_outputs<rational> e = spec.exact_rational(c.inputs.data(), conv);
    if (!e.defined) return false;
    for (std::size_t i = 0; i < spec.signature.output_count; ++i)
      if ((e.entry_undefined.empty() || !e.entry_undefined[i]) && value_out_of_range<rational, F>(e.values[i]))
        return true;
    return false;
  }
  derivative_context context = context_for<F>(spec, c);
  const exact_outputs<dual<B>> e = derivatives<B>(spec, c, conv, context);
  if (certain(context.out_of_range)) return true;
  if (!e.defined) return false;
  bool undecided_somewhere = false;
  for (std::size_t i = 0; i < spec.signature.output_count; ++i) {
    if (!e.entry_undefined.empty() && e.entry_undefined[i]) continue;
    try {
      if (value_out_of_range<B, F>(e.values[i].value())) return true;
    } catch (const undecided&) {
      undecided_somewhere = true;
    }
  }
  if (undecided_somewhere) throw undecided{};
  return false;
}

template <class F, class I>
bool leaves_range_filtered(const test_case& c, const conventions& conv) {
  try {
    return leaves_range_with<I, F>(c, conv);
  } catch (const undecided&) {
    return leaves_range_with<rational, F>(c, conv);
  }
}

// Half the larger gap next to ref in the type: the exact value lies within it of ref.
long double half_gap(double ref, scalar_type type) {
  if (type == scalar_type::f32) {
    const float r = std::fabs(static_cast<float>(ref));
    return (static_cast<long double>(std::nextafter(r, std::numeric_limits<float>::infinity())) - r) / 2;
  }
  const double r = std::fabs(ref);
  return (static_cast<long double>(std::nextafter(r, std::numeric_limits<double>::infinity())) - r) / 2;
}

// A long double bound as W, rounded outwards.
template <class W>
W outward(long double x, bool up) {
  W y = static_cast<W>(x);
  if (up ? static_cast<long double>(y) < x : static_cast<long double>(y) > x)
    y = std::nextafter(y, up ? std::numeric_limits<W>::infinity() : -std::numeric_limits<W>::infinity());
  return y;
}

// The verdict of a pending output from a kernel's bounds D ∈ [d_lo, d_hi] and the exact value f
// within the kernel's enclosure (or within half a gap of its correct rounding ref); nothing when
// the bounds cannot decide it. W is double for float cases (every quantity is a float or a
// double bound), long double for double ones.
template <class W, class InRange>
std::optional<verdict> decide_from_bounds(pending_kind kind, double got, double ref, std::size_t index,
                                          const sensitivity_bounds& b, scalar_type type, int stable_constant,
                                          const InRange& in_range) {
  if (kind != pending_kind::finite) {
    if (b.near_singular == noted::yes) return verdict::stable;
    if (b.near_singular == noted::undecided || !in_range()) return std::nullopt;
    return kind == pending_kind::nonfinite ? verdict::nonfinite : verdict::wrong;
  }
  if (!std::isfinite(ref)) return std::nullopt;
  constexpr W down = 1 - W(0x1p-50), up = 1 + W(0x1p-50);
  const W d_lo = b.lo[index], d_hi = b.hi[index];
  W f_lo, f_hi;
  if (b.values) {
    f_lo = outward<W>(b.f_lo[index], false);
    f_hi = outward<W>(b.f_hi[index], true);
  } else {
    const W h = static_cast<W>(half_gap(ref, type));
    f_lo = static_cast<W>(ref) - h;
    f_hi = static_cast<W>(ref) + h;
  }
  const W g = got;
  const W error_lo = g < f_lo ? (f_lo - g) * down : (g > f_hi ? (g - f_hi) * down : W(0));
  const W error_hi = std::max(std::fabs(g - f_lo), std::fabs(g - f_hi)) * up;
  const W size_lo = f_lo > 0 ? f_lo * down : (f_hi < 0 ? -f_hi * down : W(0));
  const W size_hi = std::max(std::fabs(f_lo), std::fabs(f_hi)) * up;
  const W stable = stable_constant * static_cast<W>(unit_roundoff(type));
  const W tau = static_cast<W>(wrong_threshold(type));
  if (!std::isfinite(error_hi) || !std::isfinite(size_hi) || !std::isfinite(d_hi)) return std::nullopt;
  if (error_hi <= stable * (size_lo + d_lo) * down) return verdict::stable;
  if (!(error_lo > stable * (size_hi + d_hi) * up) || !in_range()) return std::nullopt;
  if (error_hi <= tau * (size_lo + d_lo) * down) return verdict::unstable;
  if (error_lo > tau * (size_hi + d_hi) * up) return verdict::wrong;
  return std::nullopt;
}

// The kernel's verdicts for every pending output, or false (g untouched) when it cannot give
// them all.
bool decide_with_kernel(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                        const pending_outputs& pending, const double* reference, std::optional<point_class> cls) {
  const operation_spec& spec = spec_of(c.op);
  if (!spec.sensitivity || graded_up_to_scale(spec, conv)) return false;
  const std::size_t k = spec.signature.matrix_size;
  sensitivity_query q{&c, &conv, reference, cls, {}, spec.stable_constant};
  for (std::size_t t = 0; t < pending.count; ++t) q.wanted.set(canonical_index(pending.index[t], k, conv));
  sensitivity_bounds b;
  if (!spec.sensitivity(q, b)) return false;
  std::array<verdict, 16> decided{};
  std::optional<bool> range_checked;  // asked only for outputs that are not stable
  const auto ranged = [&] {
    if (!range_checked) range_checked = in_range(q, spec.signature.output_count, b);
    return *range_checked;
  };
  for (std::size_t t = 0; t < pending.count; ++t) {
    const std::size_t j = pending.index[t], i = canonical_index(j, k, conv);
    const auto v = c.type == scalar_type::f32
                       ? decide_from_bounds<double>(pending.kind[t], got[j], reference[i], i, b, c.type,
                                                    spec.stable_constant, ranged)
                       : decide_from_bounds<long double>(pending.kind[t], got[j], reference[i], i, b, c.type,
                                                         spec.stable_constant, ranged);
    if (!v) return false;
    decided[t] = *v;
  }
  for (std::size_t t = 0; t < pending.count; ++t) g.outputs[pending.index[t]].v = decided[t];
  return true;
}

}  // namespace

bool leaves_range(const test_case& c, const conventions& conv) {
  return c.type == scalar_type::f32 ? leaves_range_filtered<float, ival32>(c, conv)
                                    : leaves_range_filtered<double, ival64>(c, conv);
}

double unit_roundoff(scalar_type type) { return type == scalar_type::f32 ? unit<float>() : unit<double>(); }

double wrong_threshold(scalar_type type) { return type == scalar_type::f32 ? std::ldexp(1.0, -12) : std::ldexp(1.0, -27); }

void decide_pending(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                    const pending_outputs& pending, oracle_mode mode, const double* reference,
                    std::optional<point_class> cls) {
  if (pending.count == 0) return;
  if (mode == oracle_mode::filtered && decide_with_kernel(g, c, conv, got, pending, reference, cls)) return;
  const operation_spec& spec = spec_of(c.op);
  if (!spec.derivatives_rational || c.inputs.size() > max_derivative_inputs) {
    if (mode == oracle_mode::filtered && (c.type == scalar_type::f32 ? decide_generic_enclosed<float>(g, c, conv, got, pending)
                                                                     : decide_generic_enclosed<double>(g, c, conv, got, pending)))
      return;
    if (c.type == scalar_type::f32) decide_generic<float>(g, c, conv, got, pending);
    else decide_generic<double>(g, c, conv, got, pending);
    return;
  }
  if (c.type == scalar_type::f32) decide_filtered<float, ival32>(g, c, conv, got, pending, mode);
  else decide_filtered<double, ival64>(g, c, conv, got, pending, mode);
}

bool certainly_stable(double got, double ref, scalar_type type, int c) {
  // With h half the larger gap next to ref: |g − f| ≤ |g − ref| + h and |f| ≥ |ref| − h. For float
  // outputs the double difference is exact or within 2^-53 relative, for double ones the long
  // double difference within 2^-64; the margins cover that.
  if (type == scalar_type::f32) {
    const float r = std::fabs(static_cast<float>(ref));
    const double h = (static_cast<double>(std::nextafter(r, std::numeric_limits<float>::infinity())) - r) / 2;
    const double error = (std::fabs(got - ref) + h) * (1 + 0x1p-40);
    return std::isfinite(h) && error <= c * 0x1p-24 * (static_cast<double>(r) - h) * (1 - 0x1p-40);
  }
  const double r = std::fabs(ref);
  const long double gap = static_cast<long double>(std::nextafter(r, std::numeric_limits<double>::infinity())) - r;
  if (!std::isfinite(gap)) return false;
  const long double h = gap / 2;
  const long double error = (std::fabs(static_cast<long double>(got) - static_cast<long double>(ref)) + h) * (1 + 0x1p-40L);
  return error <= static_cast<long double>(c) * 0x1p-53L * (r - h) * (1 - 0x1p-40L);
}

}  // namespace detail

case_conditioning conditioning(const test_case& c, const conventions& conv, const double* outputs) {
  using namespace detail;
  const operation_spec& spec = spec_of(c.op);
  case_conditioning r;
  r.unit_roundoff = unit_roundoff(c.type);
  r.stable_constant = spec.stable_constant;
  if (!spec.derivatives_rational || c.inputs.size() > max_derivative_inputs) {
    // No derivatives over dual numbers: the range alone (inputs and exact outputs).
    r.out_of_range = leaves_range(c, conv);
    return r;
  }
  derivative_context context =
      c.type == scalar_type::f32 ? context_for<float>(spec, c) : context_for<double>(spec, c);
  const exact_outputs<dual<rational>> e = derivatives<rational>(spec, c, conv, context);
  r.out_of_range = context.out_of_range == noted::yes ||
                   (c.type == scalar_type::f32 ? inputs_out_of_range<float>(c) : inputs_out_of_range<double>(c));
  const scaled_outputs<rational> s = c.type == scalar_type::f32
                                         ? scale_outputs<rational, float>(spec, c, conv, outputs, e)
                                         : scale_outputs<rational, double>(spec, c, conv, outputs, e);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  rational max_value(0), max_sensitivity(0), max_error(0);
  bool all_finite = true, any_defined = false;
  for (std::size_t j = 0; j < s.count; ++j) {
    output_conditioning o;
    o.defined = s.defined[j];
    if (o.defined) {
      r.near_singular = r.near_singular || s.near_singular[j] == noted::yes;
      any_defined = true;
      const rational& f = s.value[j];
      const rational& d = s.sensitivity[j];
      const rational size = abs(f);
      o.value = to_double(f);
      o.sensitivity = to_double(d);
      o.condition = sgn(d) == 0 ? 0.0 : (sgn(f) == 0 ? inf : to_double(rational(d / size)));
      if (std::isfinite(outputs[j])) {
        const rational error = abs(rational(exact_value(outputs[j]) - f));
        o.relative_error = sgn(error) == 0 ? 0.0 : (sgn(f) == 0 ? inf : to_double(rational(error / size)));
        const rational scale = size + d;
        o.backward_error = sgn(error) == 0 ? 0.0
                           : sgn(scale) == 0 ? inf
                                             : to_double(rational(error / scale / exact_value(r.unit_roundoff)));
        if (error > max_error) max_error = error;
      } else {
        o.relative_error = o.backward_error = nan;
        all_finite = false;
      }
      if (size > max_value) max_value = size;
      if (d > max_sensitivity) max_sensitivity = d;
    }
    r.outputs.push_back(o);
  }
  if (any_defined) {
    r.normwise_condition = sgn(max_sensitivity) == 0 ? 0.0
                           : sgn(max_value) == 0 ? inf
                                                 : to_double(rational(max_sensitivity / max_value));
    if (!all_finite) {
      r.normwise_error = r.normwise_backward_error = r.normwise_ulps = nan;
    } else {
      r.normwise_error = sgn(max_error) == 0 ? 0.0 : (sgn(max_value) == 0 ? inf : to_double(rational(max_error / max_value)));
      const rational scale = max_value + max_sensitivity;
      r.normwise_backward_error =
          sgn(max_error) == 0 ? 0.0 : (sgn(scale) == 0 ? inf : to_double(rational(max_error / scale / exact_value(r.unit_roundoff))));
      // ulps of the largest entry: its spacing in the type (the subnormal spacing near 0).
      const double top = c.type == scalar_type::f32 ? static_cast<double>(to_nearest_float(max_value))
                                                    : to_nearest_double(max_value);
      double spacing;
      if (c.type == scalar_type::f32) {
        const float t = static_cast<float>(top);
        spacing = std::isfinite(t) ? static_cast<double>(std::nextafter(t, std::numeric_limits<float>::infinity())) - top : inf;
      } else {
        spacing = std::isfinite(top) ? std::nextafter(top, inf) - top : inf;
      }
      r.normwise_ulps = std::isfinite(spacing) ? to_double(rational(max_error / exact_value(spacing))) : nan;
    }
  }
  return r;
}

}  // namespace shadowproof
