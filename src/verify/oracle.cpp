// The grading oracle: the exact answer for the very same float inputs, decided by the
// operation's dedicated error-free kernels when it has them, then by interval arithmetic, and
// by exact rationals otherwise. The grade is written once, generic over the number type N
// (rational or interval), and the exact outputs come from the operation's own entry in the
// table (operations/<op>.cpp), so the filtered and the naive oracle cannot disagree except
// through an undecided interval, which falls back.
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include "conditioning.h"
#include "operation_table.h"
#include "scale.h"
#include "ulps_between.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"
#include "shadowproof/core/ulp.h"
#include "shadowproof/verify/grade.h"

namespace shadowproof {

std::string_view to_string(image_class c) {
  switch (c) {
    case image_class::on_receiver: return "on_receiver";
    case image_class::shadow: return "shadow";
    case image_class::behind_receiver: return "behind_receiver";
    case image_class::beyond_light: return "beyond_light";
    case image_class::nonfinite: return "nonfinite";
    case image_class::other: return "other";
  }
  return "unknown";
}

std::string_view to_string(verdict v) {
  switch (v) {
    case verdict::exact: return "exact";
    case verdict::faithful: return "faithful";
    case verdict::stable: return "stable";
    case verdict::unstable: return "unstable";
    case verdict::range: return "range";
    case verdict::wrong: return "wrong";
    case verdict::nonfinite: return "nonfinite";
    case verdict::garbage: return "garbage";
  }
  return "unknown";
}

const std::vector<verdict>& all_verdicts() {
  static const std::vector<verdict> all{verdict::exact,  verdict::faithful, verdict::stable,    verdict::unstable,
                                        verdict::range,  verdict::wrong,    verdict::nonfinite, verdict::garbage};
  return all;
}

std::optional<verdict> verdict_from_string(std::string_view name) {
  for (verdict v : all_verdicts())
    if (to_string(v) == name) return v;
  return std::nullopt;
}

std::string output_name(operation op, std::size_t j, const conventions& conv) {
  return output_name(op, detail::canonical_index(j, signature(op).matrix_size, conv));
}

bool sentinel_applies(operation op, sentinel_kind s) {
  const detail::operation_spec& spec = detail::spec_of(op);
  std::array<double, 16> outputs{};
  return s == sentinel_kind::none || (spec.sentinel_outputs && spec.sentinel_outputs(s, outputs.data()));
}

namespace {

using detail::abs_n;
using detail::exact_outputs;
using detail::from_double;
using detail::ival32;
using detail::ival64;
using detail::round_exact;
using detail::sign_n;

// The operation's exact outputs with number type N.
template <class N>
exact_outputs<N> exact_outputs_of(const test_case& c, const conventions& conv) {
  const detail::operation_spec& spec = detail::spec_of(c.op);
  if constexpr (std::is_same_v<N, rational>) return spec.exact_rational(c.inputs.data(), conv);
  else if constexpr (std::is_same_v<N, ival32>) return spec.exact_ival32(c.inputs.data(), conv);
  else return spec.exact_ival64(c.inputs.data(), conv);
}

// bits_of_error for the small ulp counts that dominate, looked up (the same values).
const std::array<double, 64> bits_table = [] {
  std::array<double, 64> t{};
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = bits_of_error(i);
  return t;
}();
double bits_of(std::uint64_t ulps) { return ulps < bits_table.size() ? bits_table[ulps] : bits_of_error(ulps); }

using detail::ulps_between;

template <class F>
void grade_output(output_grade& g, double got_d, bool defined, F ref) {
  g.got = got_d;
  const F got_f = static_cast<F>(got_d);
  if (defined && std::isfinite(got_f) && std::isfinite(ref)) {  // the common case
    g.exact_defined = true;
    g.reference = static_cast<double>(ref);
    g.ulps = ulps_between<F>(got_f, ref);
    if (g.ulps == 0) return;  // bits and relative stay 0
    g.bits = bits_of(g.ulps);
    g.relative = ref == 0 ? std::numeric_limits<double>::infinity()
                          : std::fabs((static_cast<double>(got_f) - g.reference) / g.reference);
    return;
  }
  g.exact_defined = defined;
  if (!defined) {
    g.garbage = std::isfinite(got_d);
    return;
  }
  g.reference = static_cast<double>(ref);
  const F got = static_cast<F>(got_d);
  if (!std::isfinite(got)) {
    // An overflow to the same infinity is the correctly rounded answer.
    g.nonfinite = !(std::isinf(ref) && got == ref);
    return;
  }
  F target = ref;
  std::uint64_t extra = 0;
  if (std::isinf(ref)) {  // exact value overflows the type; count one step past the largest
    target = std::copysign(std::numeric_limits<F>::max(), ref);
    extra = 1;
  }
  g.ulps = ulp_distance<F>(got, target) + extra;
  g.bits = g.ulps ? bits_of(g.ulps) : 0.0;
  if (g.ulps == 0) g.relative = 0;
  else if (ref == 0) g.relative = std::numeric_limits<double>::infinity();
  else g.relative = std::fabs((static_cast<double>(got) - g.reference) / g.reference);
}

// The reference of every output in the implementation's layout (and scale, when graded up to
// scale), already rounded to the output type.
struct references {
  std::array<double, 16> value;  // set where defined
  std::array<bool, 16> defined;  // set for every output
  bool all_defined = true;       // the exact outputs exist as a whole
  bool any_undefined = false;    // some output does not exist: the problem has no full answer
  std::optional<point_class> cls;
  std::optional<std::size_t> pivot;
  std::optional<double> scale;
};

template <class N, class F>
references exact_references(const test_case& c, const conventions& conv, const double* got) {
  references r;
  const exact_outputs<N> e = exact_outputs_of<N>(c, conv);
  r.all_defined = e.defined;
  r.cls = e.cls;
  const detail::operation_spec& spec = detail::spec_of(c.op);
  const std::size_t n = spec.signature.output_count;

  std::array<N, 16> ref;
  std::array<bool, 16> defined;
  defined.fill(e.defined);
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = detail::canonical_index(j, spec.signature.matrix_size, conv);
    ref[j] = e.values[i];
    if (!e.entry_undefined.empty() && e.entry_undefined[i]) defined[j] = false;
    r.any_undefined = r.any_undefined || !defined[j];
  }
  if (detail::graded_up_to_scale(spec, conv) && e.defined) {
    std::size_t pivot = 0;
    const std::optional<N> lambda = detail::choose_scale<N, F>(ref, defined, n, got, pivot);
    if (lambda) {
      r.pivot = pivot;
      for (std::size_t j = 0; j < n; ++j) ref[j] = *lambda * ref[j];
      r.scale = static_cast<double>(round_exact<F>(*lambda));
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    r.defined[j] = defined[j];
    r.value[j] = defined[j] ? static_cast<double>(round_exact<F>(ref[j])) : std::numeric_limits<double>::quiet_NaN();
  }
  return r;
}

// Everything but the shadow-point class fields, from the references.
template <class F>
void grade_outputs(case_grade& g, const test_case& c, std::size_t n, const double* got, const references& r) {
  g.id = c.id;
  g.cls = c.cls;
  g.scale_pivot = r.pivot;
  g.scale = r.scale;
  g.outputs.resize(n);
  std::optional<std::size_t> first_bad;
  std::uint64_t max_ulps = 0;  // kept in registers, stored once
  std::size_t worst = 0;
  output_grade* const outputs = g.outputs.data();
  for (std::size_t j = 0; j < n; ++j) {
    auto& o = outputs[j];
    const F got_f = static_cast<F>(got[j]);
    const F ref = static_cast<F>(r.value[j]);
    if (__builtin_expect(r.defined[j] && std::isfinite(got_f) && std::isfinite(ref), 1)) {
      // grade_output's common case, with fewer branches (the same values; for ref = 0 and
      // got ≠ 0 the quotient below is ±inf, as there).
      o.got = got[j];
      o.reference = r.value[j];
      const std::uint64_t d = ulps_between<F>(got_f, ref);
      o.ulps = d;
      o.bits = bits_of(d);  // bits_of(0) = 0
      const double relative = std::fabs((static_cast<double>(got_f) - r.value[j]) / r.value[j]);
      std::uint64_t bits;  // relative when d ≠ 0, +0 otherwise (0/0 is NaN), without a branch
      std::memcpy(&bits, &relative, sizeof bits);
      bits &= std::uint64_t(0) - static_cast<std::uint64_t>(d != 0);
      std::memcpy(&o.relative, &bits, sizeof bits);
      const bool worse = d > max_ulps;
      max_ulps = worse ? d : max_ulps;
      worst = worse ? j : worst;
      continue;
    }
    if (r.defined[j]) grade_output<F>(o, got[j], true, ref);
    else grade_output<F>(o, got[j], false, F(0));
    if (o.nonfinite) ++g.nonfinite;
    if (o.garbage) ++g.garbage;
    if ((o.nonfinite || o.garbage) && !first_bad) first_bad = j;
    if (o.counted() && o.ulps > max_ulps) {
      max_ulps = o.ulps;
      worst = j;
    }
  }
  g.max_ulps = max_ulps;
  g.worst_output = worst;
  // A non-finite or garbage output is worse than any finite error.
  if (first_bad) g.worst_output = *first_bad;
  g.max_bits = g.max_ulps ? bits_of(g.max_ulps) : 0.0;
}

// The verdict of every output and of the case (grade.h, docs/verdicts.md). What the ulps and the
// relative error decide is decided here; the rest waits for the derivatives.
template <class F>
void assign_verdicts(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                     const references& r, std::size_t n, oracle_mode mode) {
  const detail::operation_spec& spec = detail::spec_of(c.op);
  bool all_nonfinite = true, all_exact = true;
  for (std::size_t j = 0; j < n; ++j) {
    all_nonfinite = all_nonfinite && !std::isfinite(got[j]);
    all_exact = all_exact && r.defined[j] && g.outputs[j].ulps == 0 && !g.outputs[j].nonfinite &&
                (std::isfinite(got[j]) || got[j] == r.value[j]);
  }
  const bool sentinel = !all_exact && detail::is_sentinel(spec, conv, got, n);
  if (r.any_undefined && (all_nonfinite || sentinel)) {
    // A problem without (a full) answer, rejected as a whole: the correct answer.
    g.rejected = true;
    g.nonfinite = g.garbage = 0;
    for (std::size_t j = 0; j < n; ++j) {
      output_grade& o = g.outputs[j];
      o.nonfinite = o.garbage = false;
      o.ulps = 0;
      o.bits = o.relative = 0;
      o.v = verdict::exact;
    }
    g.max_ulps = 0;
    g.max_bits = 0;
    g.worst_output = 0;
    g.v = verdict::exact;
    g.verdict_output = 0;
    return;
  }
  detail::pending_outputs pending;
  g.rejected = sentinel;  // a sentinel for a problem that has an answer
  for (std::size_t j = 0; j < n; ++j) {
    output_grade& o = g.outputs[j];
    if (!r.defined[j]) {
      o.v = o.garbage ? verdict::garbage : verdict::exact;
    } else if (sentinel) {
      if (o.ulps == 0 && !o.nonfinite && std::isfinite(got[j])) o.v = verdict::exact;
      else pending.add(j, detail::pending_kind::rejection);
    } else if (!std::isfinite(got[j])) {
      if (o.nonfinite) pending.add(j, detail::pending_kind::nonfinite);
      else o.v = verdict::exact;  // an overflow to the same infinity
    } else if (o.ulps == 0) {
      o.v = verdict::exact;
    } else if (o.ulps == 1) {
      o.v = verdict::faithful;
    } else if (std::isfinite(o.reference) && o.reference != 0 &&
               detail::certainly_stable(got[j], o.reference, c.type, spec.stable_constant)) {
      o.v = verdict::stable;
    } else {
      pending.add(j, detail::pending_kind::finite);
    }
  }
  if (pending.count) {
    // The kernels read the references in canonical order: the implementation's order unless
    // its layout transposes.
    std::array<double, 16> canonical;
    const std::size_t k = spec.signature.matrix_size;
    const bool transposed = k && detail::canonical_index(1, k, conv) != 1;
    if (transposed)
      for (std::size_t j = 0; j < n; ++j) canonical[detail::canonical_index(j, k, conv)] = r.value[j];
    detail::decide_pending(g, c, conv, got, pending, mode, transposed ? canonical.data() : r.value.data(), r.cls);
  }
  g.v = verdict::exact;
  g.verdict_output = 0;
  for (std::size_t j = 0; j < n; ++j)
    if (g.outputs[j].v > g.v) {
      g.v = g.outputs[j].v;
      g.verdict_output = j;
    }
}

// The grade of a case from its references, and what its outputs mean beyond their values.
template <class F>
void finish_grade(case_grade& g, const test_case& c, const conventions& conv, const double* got,
                  const references& r, std::size_t n, oracle_mode mode, grade_depth depth) {
  grade_outputs<F>(g, c, n, got, r);
  if (depth == grade_depth::verdicts) assign_verdicts<F>(g, c, conv, got, r, n, mode);
  const detail::operation_spec& spec = detail::spec_of(c.op);
  if (spec.grade_meaning) {
    g.exact_class = r.cls;
    spec.grade_meaning(g, c, conv, got, r.all_defined, mode);
  }
}

template <class N, class F>
case_grade grade_with(const test_case& c, const conventions& conv, const double* got, oracle_mode mode,
                      grade_depth depth) {
  const references r = exact_references<N, F>(c, conv, got);
  case_grade g;
  finish_grade<F>(g, c, conv, got, r, signature(c.op).output_count, mode, depth);
  return g;
}

// The operation's dedicated kernels (oracle_fast.h); false when it has none for this type, the
// case is graded up to scale, or they cannot decide it.
template <class F>
bool grade_fast(const test_case& c, const conventions& conv, const double* got, case_grade& out, grade_depth depth) {
  const detail::operation_spec& spec = detail::spec_of(c.op);
  const auto kernel = std::is_same_v<F, float> ? spec.fast_f32 : spec.fast_f64;
  // The kernels compute right-handed matrices (but those that read the handedness); a
  // left-handed convention (column 2 negated) goes to the generic oracle, whose exact templates
  // apply it.
  if (!kernel || detail::graded_up_to_scale(spec, conv) ||
      (conv.hand == handedness::left && !spec.fast_kernels_read_handedness))
    return false;
  detail::fast_reference fast;
  if (!kernel(c.inputs.data(), conv, fast)) return false;
  const std::size_t k = spec.signature.matrix_size;
  references r;
  r.all_defined = fast.defined;
  r.any_undefined = !fast.defined;
  r.cls = fast.cls;
  for (std::size_t j = 0; j < fast.count; ++j) {
    const std::size_t i = detail::canonical_index(j, k, conv);
    r.defined[j] = fast.defined && !((fast.undefined >> i) & 1);
    r.value[j] = r.defined[j] ? fast.value[i] : std::numeric_limits<double>::quiet_NaN();
    r.any_undefined = r.any_undefined || !r.defined[j];
  }
  finish_grade<F>(out, c, conv, got, r, fast.count, oracle_mode::filtered, depth);
  return true;
}

}  // namespace

case_grade grade_case(const test_case& c, const conventions& conv, const double* outputs,
                      oracle_mode mode, oracle_counters* counters, grade_depth depth) {
  if (mode == oracle_mode::filtered) {
    case_grade fast;
    if (c.type == scalar_type::f32 ? grade_fast<float>(c, conv, outputs, fast, depth)
                                   : grade_fast<double>(c, conv, outputs, fast, depth)) {
      if (counters) ++counters->decided_by_intervals;
      return fast;
    }
    try {
      case_grade g = c.type == scalar_type::f32 ? grade_with<ival32, float>(c, conv, outputs, mode, depth)
                                                : grade_with<ival64, double>(c, conv, outputs, mode, depth);
      if (counters) ++counters->decided_by_intervals;
      return g;
    } catch (const detail::undecided&) {
      if (counters) ++counters->fell_back_to_rationals;
    }
  }
  return c.type == scalar_type::f32 ? grade_with<rational, float>(c, conv, outputs, mode, depth)
                                    : grade_with<rational, double>(c, conv, outputs, mode, depth);
}

}  // namespace shadowproof
