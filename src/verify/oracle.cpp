// The grading oracle: the exact answer for the very same float inputs, decided with interval
// arithmetic when it can be and with exact rationals otherwise. The whole grade is written
// once, generic over the number type N (rational or interval), so the filtered and the naive
// oracle cannot disagree except through an undecided interval, which falls back.
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include "oracle_fast.h"
#include "oracle_interval.h"
#include "shadowproof/constructions/classify.h"
#include "shadowproof/core/error.h"
#include "shadowproof/constructions/normal_matrix.h"
#include "shadowproof/core/number.h"
#include "shadowproof/constructions/project.h"
#include "shadowproof/constructions/reflect.h"
#include "shadowproof/constructions/shadow.h"
#include "shadowproof/core/ulp.h"
#include "shadowproof/verify/operation.h"
#include "shadowproof/verify/conventions.h"
#include "shadowproof/verify/implementation.h"
#include "shadowproof/verify/cases.h"
#include "shadowproof/verify/grade.h"

namespace shadowproof {
namespace {

// Intervals over double decide float outputs (and f32 products are exact in double); double
// outputs need the 64-bit significand of long double.
using ival32 = detail::interval<double>;
using ival64 = detail::interval<long double>;

template <class T>
struct is_interval : std::false_type {};
template <class B>
struct is_interval<detail::interval<B>> : std::true_type {};

// --- the number-type specific pieces -------------------------------------------------------

template <class N>
N from_double(double x) {
  if constexpr (std::is_same_v<N, rational>) return exact_value(x);
  else return N::point(x);
}

template <class F>
F round_exact(const rational& q) {
  F r;
  if constexpr (std::is_same_v<F, float>) r = to_nearest_float(q);
  else r = to_nearest_double(q);
  return r == 0 ? F(0) : r;
}
template <class F, class B>
F round_exact(const detail::interval<B>& x) { return detail::round_to<F>(x); }

int sign_n(const rational& q) { return sgn(q); }
template <class B>
int sign_n(const detail::interval<B>& x) { return detail::sign(x); }

template <class N>
N abs_n(const N& x) { return sign_n(x) < 0 ? N(-x) : x; }

// --- canonical exact outputs -----------------------------------------------------------------

// Fixed-size storage: the oracle's inner loop allocates nothing but the grade itself.
template <class N>
struct small_vector {
  std::array<N, 16> v{};
  std::size_t n = 0;
  void push_back(const N& x) { v[n++] = x; }
  void assign(std::size_t count, const N& x) {
    n = count;
    for (std::size_t i = 0; i < count; ++i) v[i] = x;
  }
  bool empty() const { return n == 0; }
  N& operator[](std::size_t i) { return v[i]; }
  const N& operator[](std::size_t i) const { return v[i]; }
};

template <class N>
struct exact_outputs {
  small_vector<N> values;
  bool defined = true;                  // false: no output exists (undefined image, singular A)
  small_vector<bool> entry_undefined;   // when defined: entries that divide by zero (flat volumes)
  std::optional<point_class> cls;
};

template <class N>
vec4<N> vec_from(const double* x, std::size_t n, const N& last) {
  vec4<N> v;
  for (std::size_t i = 0; i < n; ++i) v[i] = from_double<N>(x[i]);
  if (n == 3) v[3] = last;
  return v;
}

template <class N>
light<N> canonical_light(const double* x, const conventions& conv) {
  light<N> L{vec_from<N>(x, 4, N(0))};
  // A directional light given along its rays is the negation of the canonical one (exact).
  if (conv.light == light_sign::along_rays && x[3] == 0)
    for (std::size_t i = 0; i < 3; ++i) L.l[i] = -L.l[i];
  return L;
}

template <class N>
exact_outputs<N> canonical(const test_case& c, const conventions& conv) {
  exact_outputs<N> r;
  const double* in = c.inputs.data();
  const plane<N> P{vec_from<N>(in, 4, N(0))};
  switch (c.op) {
    case operation::shadow_matrix: {
      const mat4<N> M = shadow_matrix(P, canonical_light<N>(in + 4, conv));
      for (std::size_t i = 0; i < 16; ++i) r.values.push_back(M(i / 4, i % 4));
      break;
    }
    case operation::shadow_point: {
      const light<N> L = canonical_light<N>(in + 4, conv);
      const vec4<N> V = vec_from<N>(in + 8, 3, N(1));
      r.cls = classify_point(P, L, V);
      // A point on the receiver is its own shadow, also when the light is parallel to or on
      // the receiver (then the whole line from V to the light lies in it and the matrix's
      // image is the zero vector, but V is still where the line meets the receiver).
      const bool own_image = *r.cls == point_class::on_receiver || *r.cls == point_class::line_in_plane;
      if (own_image || (conv.clamps_behind_receiver && *r.cls == point_class::behind_receiver)) {
        for (std::size_t i = 0; i < 3; ++i) r.values.push_back(V[i]);
        break;
      }
      const vec4<N> h = shadow_image(P, L, V);
      if (sign_n(h[3]) == 0) {
        r.defined = false;
        r.values.assign(3, N(0));
      } else {
        for (std::size_t i = 0; i < 3; ++i) r.values.push_back(h[i] / h[3]);
      }
      break;
    }
    case operation::reflection_matrix: {
      const mat4<N> M = reflection_matrix(P);
      for (std::size_t i = 0; i < 16; ++i) r.values.push_back(M(i / 4, i % 4));
      break;
    }
    case operation::ortho:
    case operation::frustum: {
      std::array<N, 6> x;
      for (std::size_t i = 0; i < 6; ++i) x[i] = from_double<N>(in[i]);
      auto build = [&](const std::array<N, 6>& v) {
        return c.op == operation::ortho ? orthographic(v[0], v[1], v[2], v[3], v[4], v[5], conv.depth)
                                        : frustum(v[0], v[1], v[2], v[3], v[4], v[5], conv.depth, false);
      };
      if (c.op == operation::frustum && sign_n(x[4]) <= 0) {  // near ≤ 0: no such projection
        r.defined = false;
        r.values.assign(16, N(0));
        break;
      }
      // A flat volume (l = r, b = t or n = f) divides by zero only in the entries that scale
      // or centre that axis: row k's diagonal and its offset column (3 for ortho and for the
      // depth row, 2 for the x and y rows of a frustum). The other entries still exist.
      // A builder declared symmetric (l = −r, b = −t) has a zero centre offset by construction,
      // so for it a flat x or y extent leaves that offset defined as 0.
      std::array<N, 6> v = x;
      r.entry_undefined.assign(16, false);
      small_vector<std::size_t> zero_offsets;
      for (std::size_t k = 0; k < 3; ++k)
        if (sign_n(N(x[2 * k + 1] - x[2 * k])) == 0) {
          v[2 * k + 1] = x[2 * k] + N(1);
          const std::size_t offset = (c.op == operation::frustum && k < 2) ? 2 : 3;
          r.entry_undefined[k * 4 + k] = true;
          if (conv.symmetric_view && k < 2) zero_offsets.push_back(k * 4 + offset);
          else r.entry_undefined[k * 4 + offset] = true;
        }
      const mat4<N> M = build(v);
      for (std::size_t i = 0; i < 16; ++i) r.values.push_back(M(i / 4, i % 4));
      for (std::size_t i = 0; i < zero_offsets.n; ++i) r.values[zero_offsets[i]] = N(0);
      break;
    }
    case operation::normal_matrix: {
      mat4<N> A = identity4<N>();
      for (std::size_t i = 0; i < 9; ++i) A(i / 3, i % 3) = from_double<N>(in[i]);
      try {
        const mat4<N> G = normal_matrix3(A);
        for (std::size_t i = 0; i < 9; ++i) r.values.push_back(G(i / 3, i % 3));
      } catch (const error&) {  // det A = 0: no inverse, no normal matrix
        r.defined = false;
        r.values.assign(9, N(0));
      }
      break;
    }
  }
  return r;
}

// Canonical row-major index of the implementation's output j of a k x k matrix under its
// storage conventions.
std::size_t canonical_index(std::size_t j, std::size_t k, const conventions& conv) {
  // Column-major storage and row vectors each transpose; both together cancel.
  const bool transposed = (conv.storage == storage_order::column_major) != (conv.vectors == vector_side::row);
  if (!transposed) return j;
  if (k == 4) return ((j & 3) << 2) | (j >> 2);  // the common case without a division
  return (j % k) * k + j / k;
}

// Where the float image G lies on the line through the light and V (see image_class).
template <class N>
image_class classify_image(const test_case& c, const conventions& conv, const double* got) {
  for (std::size_t i = 0; i < 3; ++i)
    if (!std::isfinite(got[i])) return image_class::nonfinite;
  const double* in = c.inputs.data();
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

// The image class a correct result must have, for the exact classes where the side matters.
// A point exactly on the receiver (on_receiver, and line_in_plane, whose image is also the
// point itself) is left to the ulps metric: an image one ulp away from it would otherwise
// count as a flipped side.
std::optional<image_class> comparable(point_class e, const conventions& conv) {
  switch (e) {
    case point_class::shadow: return image_class::shadow;
    case point_class::behind_receiver:
      return conv.clamps_behind_receiver ? image_class::on_receiver : image_class::behind_receiver;
    case point_class::beyond_light: return image_class::beyond_light;
    default: return std::nullopt;
  }
}

// P·(G, 1) for the float image G, correctly rounded to double. The value cancels to a few
// ulps of its terms (G is nearly on P), which double intervals rarely decide for double
// inputs; then only this small dot product is redone exactly, not the whole case.
template <class N>
double plane_value(const double* in, const double* got) {
  auto exact = [&](auto tag) {
    using M = decltype(tag);
    const plane<M> P{vec_from<M>(in, 4, M(0))};
    return round_exact<double>(evaluate(P, vec_from<M>(got, 3, M(1))));
  };
  if constexpr (std::is_same_v<N, rational>) {
    return exact(rational());
  } else {
    try {
      return exact(ival64());  // f32 products are exact in its 64-bit significand
    } catch (const detail::undecided&) {
      return exact(rational());
    }
  }
}

// bits_of_error for the small ulp counts that dominate, looked up (the same values).
const std::array<double, 64> bits_table = [] {
  std::array<double, 64> t{};
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = bits_of_error(i);
  return t;
}();
double bits_of(std::uint64_t ulps) { return ulps < bits_table.size() ? bits_table[ulps] : bits_of_error(ulps); }

// ulp_distance without branches on the signs (the same count, ulp.h's definition).
template <class F>
std::uint64_t ulps_between(F a, F b) {
  using bits_t = std::conditional_t<std::is_same_v<F, float>, std::uint32_t, std::uint64_t>;
  constexpr int shift = std::is_same_v<F, float> ? 31 : 63;
  auto position = [](F x) {
    bits_t raw;
    std::memcpy(&raw, &x, sizeof raw);
    const auto magnitude = static_cast<std::int64_t>(raw & ~(bits_t(1) << shift));
    const std::int64_t negative = -static_cast<std::int64_t>(raw >> shift);  // 0 or −1
    return (magnitude ^ negative) - negative;
  };
  const std::int64_t x = position(a), y = position(b);
  const std::uint64_t d = static_cast<std::uint64_t>(x) - static_cast<std::uint64_t>(y);
  return x >= y ? d : std::uint64_t(0) - d;
}

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
  bool all_defined = true;
  std::optional<point_class> cls;
  std::optional<std::size_t> pivot;
};

bool graded_up_to_scale(const test_case& c, const conventions& conv) {
  return signature(c.op).matrix_size &&
         (conv.homogeneous || (conv.normalises_plane && c.op == operation::shadow_matrix));
}

template <class N, class F>
references exact_references(const test_case& c, const conventions& conv, const double* got) {
  references r;
  const exact_outputs<N> e = canonical<N>(c, conv);
  r.all_defined = e.defined;
  r.cls = e.cls;
  const auto& sig = signature(c.op);
  const std::size_t n = sig.output_count;

  std::array<N, 16> ref;
  std::array<bool, 16> defined;
  defined.fill(e.defined);
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = sig.matrix_size ? canonical_index(j, sig.matrix_size, conv) : j;
    ref[j] = e.values[i];
    if (!e.entry_undefined.empty() && e.entry_undefined[i]) defined[j] = false;
  }
  if (graded_up_to_scale(c, conv) && e.defined) {
    // Pivot: the defined entry of largest exact magnitude, the first one on ties.
    std::size_t k = 0;
    while (k + 1 < n && !defined[k]) ++k;
    N best = abs_n(ref[k]);
    for (std::size_t j = k + 1; j < n; ++j) {
      if (!defined[j]) continue;
      N a = abs_n(ref[j]);
      if (sign_n(N(a - best)) > 0) { best = a; k = j; }
    }
    r.pivot = k;
    // λ = got[k] / exact[k]; without a usable got[k] the scale stays 1 and the grade shows it.
    if (std::isfinite(got[k]) && got[k] != 0 && sign_n(ref[k]) != 0) {
      const N lambda = from_double<N>(got[k]) / ref[k];
      for (std::size_t j = 0; j < n; ++j) ref[j] = lambda * ref[j];
    }
  }
  for (std::size_t j = 0; j < n; ++j) {
    r.defined[j] = defined[j];
    if (defined[j]) r.value[j] = static_cast<double>(round_exact<F>(ref[j]));
  }
  return r;
}

// Everything but the shadow-point class fields, from the references.
template <class F>
void grade_outputs(case_grade& g, const test_case& c, std::size_t n, const double* got, const references& r) {
  g.id = c.id;
  g.cls = c.cls;
  g.scale_pivot = r.pivot;
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

void set_point_class(case_grade& g, const references& r, const conventions& conv, image_class got_class,
                     std::optional<double> plane_value) {
  g.exact_class = r.cls;
  g.got_class = got_class;
  if (const auto want = comparable(*r.cls, conv)) g.misclassified = got_class != *want;
  else if (r.all_defined) g.misclassified = got_class == image_class::nonfinite;
  g.plane_value = plane_value;
}

template <class N, class F>
case_grade grade_with(const test_case& c, const conventions& conv, const double* got) {
  const references r = exact_references<N, F>(c, conv, got);
  case_grade g;
  grade_outputs<F>(g, c, signature(c.op).output_count, got, r);
  if (c.op == operation::shadow_point) {
    const image_class got_class = classify_image<N>(c, conv, got);
    std::optional<double> value;
    if (got_class != image_class::nonfinite) value = plane_value<N>(c.inputs.data(), got);
    set_point_class(g, r, conv, got_class, value);
  }
  return g;
}

// The dedicated kernels (oracle_fast.h): shadow-matrix, shadow-point and reflection-matrix for
// float cases, shadow-matrix and shadow-point for double cases; false when they do not cover or
// decide the case.
template <class F>
bool grade_fast(const test_case& c, const conventions& conv, const double* got, case_grade& out) {
  if (c.op != operation::shadow_matrix && c.op != operation::shadow_point && c.op != operation::reflection_matrix)
    return false;
  const bool matrix = c.op != operation::shadow_point;
  if (matrix && (conv.homogeneous || (conv.normalises_plane && c.op == operation::shadow_matrix))) return false;
  detail::fast_reference fast;
  if constexpr (std::is_same_v<F, float>) {
    if (!detail::fast_reference_f32(c.op, c.inputs.data(), conv, fast)) return false;
  } else {
    if (!detail::fast_reference_f64(c.op, c.inputs.data(), conv, fast)) return false;
  }
  references r;
  r.all_defined = fast.defined;
  r.cls = fast.cls;
  for (std::size_t j = 0; j < fast.count; ++j) {
    r.value[j] = fast.value[matrix ? canonical_index(j, 4, conv) : j];
    r.defined[j] = fast.defined;
  }
  grade_outputs<F>(out, c, fast.count, got, r);
  if (c.op == operation::shadow_point) {
    const double* in = c.inputs.data();
    using ival = std::conditional_t<std::is_same_v<F, float>, ival32, ival64>;
    image_class got_class;
    bool decided = false;
    if constexpr (std::is_same_v<F, float>) decided = detail::fast_image_class_f32(in, conv, got, got_class);
    else decided = detail::fast_image_class_f64(in, conv, got, got_class);
    if (!decided) {
      try {
        got_class = classify_image<ival>(c, conv, got);
      } catch (const detail::undecided&) {
        got_class = classify_image<rational>(c, conv, got);
      }
    }
    std::optional<double> value;
    if (got_class != image_class::nonfinite) {
      double v;
      const bool fast_value = std::is_same_v<F, float> ? detail::fast_plane_value_f32(in, got, v)
                                                       : detail::fast_plane_value_f64(in, got, v);
      value = fast_value ? v : plane_value<ival>(in, got);
    }
    set_point_class(out, r, conv, got_class, value);
  }
  return true;
}

}  // namespace

case_grade grade_case(const test_case& c, const conventions& conv, const double* outputs,
                      oracle_mode mode, oracle_counters* counters) {
  if (mode == oracle_mode::filtered) {
    case_grade fast;
    if (c.type == scalar_type::f32 ? grade_fast<float>(c, conv, outputs, fast)
                                   : grade_fast<double>(c, conv, outputs, fast)) {
      if (counters) ++counters->decided_by_intervals;
      return fast;
    }
    try {
      case_grade g = c.type == scalar_type::f32 ? grade_with<ival32, float>(c, conv, outputs)
                                                : grade_with<ival64, double>(c, conv, outputs);
      if (counters) ++counters->decided_by_intervals;
      return g;
    } catch (const detail::undecided&) {
      if (counters) ++counters->fell_back_to_rationals;
    }
  }
  return c.type == scalar_type::f32 ? grade_with<rational, float>(c, conv, outputs)
                                    : grade_with<rational, double>(c, conv, outputs);
}

}  // namespace shadowproof
