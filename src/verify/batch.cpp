// Grading many cases of one operation at once (batch.h): the kernels' batch filter over whole
// columns, the kernel for one case where it does not decide, the generic oracle where that
// declines; then the grades, column by column.
#include "shadowproof/verify/batch.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

#include "batch_ranges.h"
#include "kernels/batch.h"
#include "operation_table.h"
#include "oracle_fast.h"
#include "ulps_between.h"
#include "shadowproof/core/error.h"
#include "shadowproof/core/number.h"
#include "shadowproof/core/ulp.h"

namespace shadowproof {

namespace {

using detail::exact_outputs;
using detail::ival32;
using detail::ival64;

// The position, in the implementation's layout, of canonical output i of a k x k matrix
// (oracle.cpp's canonical_index: transposition is its own inverse).
std::size_t layout_index(std::size_t i, std::size_t k, const conventions& conv) {
  const bool transposed = (conv.storage == storage_order::column_major) != (conv.vectors == vector_side::row);
  if (k == 0 || !transposed) return i;
  return (i % k) * k + i / k;
}

// The canonical outputs of one case from the generic oracle with number type N (intervals,
// which throw `undecided`, or rationals): grade_case's path when the kernels decline.
template <class F, class N>
void generic_reference(const detail::operation_spec& spec, const double* in, const conventions& conv,
                       detail::fast_reference& r) {
  exact_outputs<N> e;
  if constexpr (std::is_same_v<N, rational>) e = spec.exact_rational(in, conv);
  else if constexpr (std::is_same_v<N, ival32>) e = spec.exact_ival32(in, conv);
  else e = spec.exact_ival64(in, conv);
  r = detail::fast_reference{};
  r.count = spec.signature.output_count;
  r.defined = e.defined;
  r.cls = e.cls;
  for (std::size_t i = 0; i < r.count; ++i) {
    const bool undefined = !e.defined || (!e.entry_undefined.empty() && e.entry_undefined[i]);
    if (e.defined && undefined) r.undefined |= std::uint32_t(1) << i;
    r.value[i] = undefined ? 0.0 : static_cast<double>(detail::round_exact<F>(e.values[i]));
  }
}

// Writes a fast_reference into the columns of case i, in the implementation's layout.
void store_reference(const detail::fast_reference& r, std::size_t i, std::size_t k, const conventions& conv,
                     batch_references& out) {
  const std::size_t n = r.count, count = out.count;
  std::uint32_t undefined = 0;
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t j = layout_index(c, k, conv);
    out.values[j * count + i] = r.value[c];
    if (!r.defined || ((r.undefined >> c) & 1)) undefined |= std::uint32_t(1) << j;
  }
  out.undefined[i] = undefined;
  out.point_class[i] = r.cls ? static_cast<std::int8_t>(*r.cls) : std::int8_t(-1);
}

using detail::ulps_between;

// One output, every case (grade_case's grade_output): ulps and flags.
template <class F>
void grade_output(const double* got, const double* ref, bool defined, std::uint64_t& ulps, std::uint8_t& flags) {
  const F got_f = static_cast<F>(*got);
  const F ref_f = static_cast<F>(*ref);
  ulps = 0;
  if (!defined) {
    flags = batch_grades::exact_undefined | (std::isfinite(*got) ? batch_grades::garbage_output : 0);
    return;
  }
  if (std::isfinite(got_f) && std::isfinite(ref_f)) {
    ulps = ulps_between<F>(got_f, ref_f);
    flags = batch_grades::counted;
    return;
  }
  if (!std::isfinite(got_f)) {  // an overflow to the same infinity is the correctly rounded answer
    const bool same_infinity = std::isinf(ref_f) && got_f == ref_f;
    flags = same_infinity ? std::uint8_t{0} : batch_grades::nonfinite_output;  // not counted, as output_grade
    return;
  }
  // The exact value overflows the type: count one step past the largest finite value.
  ulps = ulp_distance<F>(got_f, std::copysign(std::numeric_limits<F>::max(), ref_f)) + 1;
  flags = batch_grades::counted;
}

// Whether grade_case grades this operation up to scale under conv (oracle.cpp).
bool graded_up_to_scale(operation op, const conventions& conv) {
  const detail::operation_spec& spec = detail::spec_of(op);
  return spec.signature.matrix_size &&
         (conv.homogeneous || (conv.normalises_plane && spec.symmetries.plane_degree > 0));
}

// The summary fields of a case_grade into the columns of case i.
void store_case_grade(const case_grade& g, std::size_t i, batch_grades& out) {
  const std::size_t count = out.count;
  for (std::size_t j = 0; j < g.outputs.size(); ++j) {
    const output_grade& o = g.outputs[j];
    out.ulps[j * count + i] = o.counted() ? o.ulps : 0;
    out.flags[j * count + i] = static_cast<std::uint8_t>(
        (o.counted() ? batch_grades::counted : 0) | (o.nonfinite ? batch_grades::nonfinite_output : 0) |
        (o.garbage ? batch_grades::garbage_output : 0) | (o.exact_defined ? 0 : batch_grades::exact_undefined));
  }
  out.max_ulps[i] = g.max_ulps;
  out.worst_output[i] = static_cast<std::uint8_t>(g.worst_output);
  out.nonfinite[i] = static_cast<std::uint8_t>(g.nonfinite);
  out.garbage[i] = static_cast<std::uint8_t>(g.garbage);
  out.misclassified[i] = g.misclassified ? 1 : 0;
  out.got_class[i] = g.got_class ? static_cast<std::int8_t>(*g.got_class) : std::int8_t(-1);
  out.plane_value[i] = g.plane_value ? *g.plane_value : std::numeric_limits<double>::quiet_NaN();
}

// Copies case i's inputs into a reused test_case and its outputs into `got`.
void load_case(const case_batch& b, std::size_t i, test_case& c, double* got) {
  const auto& sig = signature(b.op);
  c.id = b.ids.empty() ? i : b.ids[i];
  c.op = b.op;
  c.type = b.type;
  c.cls = b.classes.empty() ? input_class::regular : b.classes[i];
  c.inputs.resize(sig.input_count);
  for (std::size_t k = 0; k < sig.input_count; ++k) c.inputs[k] = b.inputs[k * b.count + i];
  for (std::size_t j = 0; j < sig.output_count; ++j) got[j] = b.outputs[j * b.count + i];
}

// One output column over cases [first, end): every output whose exact value is defined and
// whose float value and reference are finite (the common case) gets its ulps and the counted
// flag, without a branch; the others get `special`, for grade_special. The case's maximum and
// worst output follow (the first output reaching the maximum, as grade_case keeps it).
template <class F>
bool grade_column(const double* __restrict got, const double* __restrict ref, const std::uint32_t* __restrict undefined,
                  std::size_t j, std::size_t first, std::size_t end, std::uint64_t* __restrict ulps,
                  std::uint8_t* __restrict flags, std::uint64_t* __restrict max_ulps, std::uint8_t* __restrict worst) {
  constexpr std::uint8_t special = 0x80;
  bool any_special = false;
  for (std::size_t i = first; i < end; ++i) {
    const F got_f = static_cast<F>(got[i]), ref_f = static_cast<F>(ref[i]);
    const bool common = !((undefined[i] >> j) & 1) & std::isfinite(got_f) & std::isfinite(ref_f);
    const std::uint64_t d = common ? ulps_between<F>(got_f, ref_f) : 0;
    ulps[i] = d;
    flags[i] = common ? batch_grades::counted : special;
    const bool worse = d > max_ulps[i];
    max_ulps[i] = worse ? d : max_ulps[i];
    worst[i] = worse ? static_cast<std::uint8_t>(j) : worst[i];
    any_special |= !common;
  }
  return any_special;
}

// The classes of the float images of cases [first, end) and of their references, and the
// plane values of the float images: the image filter (batch.h) over the columns.
struct image_columns {
  std::vector<double> plane_value, plane_value_decided, reference_decided;  // 1 where decided
  std::vector<std::int8_t> classes;  // class(G) + 4 class(reference)
  std::vector<std::uint8_t> decided;  // G's class
  image_class got_class(std::size_t r) const { return static_cast<image_class>(classes[r] % 4); }
  image_class reference_class(std::size_t r) const { return static_cast<image_class>(classes[r] / 4); }
};
void filter_images(const case_batch& b, const conventions& conv, const batch_references& refs, std::size_t first,
                   std::size_t end, bool use_avx2, image_columns& r) {
  const std::size_t count = b.count, n = end - first;
  // The filter writes `decided` for every case and the rest wherever it decides G's class
  // (the only cases whose other columns are read).
  r.plane_value.resize(n);
  r.plane_value_decided.resize(n);
  r.reference_decided.resize(n);
  r.classes.resize(n);
  r.decided.assign(n, 0);
  // The filter reads the light as given and V as a point: any handedness or layout (a point has
  // no matrix to transpose).
  const detail::batch_filter filter = use_avx2 ? detail::avx2_image_filter(b.type) : detail::generic_image_filter(b.type);
  if (!filter) return;
  const double* columns[17];
  for (std::size_t c = 0; c < 11; ++c) columns[c] = b.inputs.data() + c * count + first;
  for (std::size_t c = 0; c < 3; ++c) {
    columns[11 + c] = b.outputs.data() + c * count + first;
    columns[14 + c] = refs.values.data() + c * count + first;
  }
  double* values[3] = {r.plane_value.data(), r.plane_value_decided.data(), r.reference_decided.data()};
  filter(columns, n, conv, {values, r.decided.data(), r.classes.data()});
}

// What a shadow-point case's outputs mean beyond their values (grade_case's grade_meaning): the
// class of the float image, its plane value, and whether it lies on another side than the
// correctly rounded image. Decided from the image filter where it decides the image (and, when
// the two differ, the reference); the operation's own grade_meaning otherwise. A case graded
// whole by grade_case has them already; every other case has every exact output defined and
// every output and reference finite.
void grade_images_range(const case_batch& b, const conventions& conv, const batch_references& refs,
                        batch_grades& out, std::size_t first, std::size_t end,
                        const std::vector<std::uint8_t>& graded_whole, bool use_avx2) {
  const detail::operation_spec& spec = detail::spec_of(b.op);
  const std::size_t count = b.count, n = spec.signature.output_count;
  // Kept from one range to the next on each thread: fresh columns for every range of a few
  // thousand cases cost more in page faults than the filter itself.
  thread_local image_columns images;
  filter_images(b, conv, refs, first, end, use_avx2, images);
  const bool f32 = b.type == scalar_type::f32;
  double in[16];
  test_case scratch;
  double got[16];
  case_grade g;
  g.outputs.resize(n);
  for (std::size_t i = first; i < end; ++i) {
    const std::size_t r = i - first;
    if (!graded_whole.empty() && graded_whole[r]) continue;
    // The common case, from the filter's columns alone: both classes decided and equal, and
    // the plane value decided. The image is then misclassified neither when it equals its
    // reference nor when it differs (rejected or not), and nothing else is read.
    if (images.decided[r] && images.reference_decided[r] != 0 && images.plane_value_decided[r] != 0 &&
        images.got_class(r) == images.reference_class(r)) {
      out.got_class[i] = static_cast<std::int8_t>(images.got_class(r));
      out.plane_value[i] = images.plane_value[r];
      out.misclassified[i] = 0;
      continue;
    }
    bool all_exact = true, same = true;
    for (std::size_t j = 0; j < n; ++j) {
      got[j] = b.outputs[j * count + i];
      all_exact = all_exact && out.ulps[j * count + i] == 0;
      same = same && refs.values[j * count + i] == got[j];
    }
    // assign_verdicts' rule; it matters only where the image differs from the reference.
    const bool rejected = !same && !all_exact && detail::is_sentinel(spec, conv, got, n);
    if (images.decided[r] && (same || rejected || images.reference_decided[r] != 0)) {
      // The plane value where the filter left its rounding to the exact sum (G within a few
      // ulps of P): the kernel for one case, which declines only inputs out of its range.
      double plane_value = images.plane_value[r];
      bool decided = images.plane_value_decided[r] != 0;
      if (!decided) {
        for (std::size_t k = 0; k < 4; ++k) in[k] = b.inputs[k * count + i];
        decided = f32 ? detail::fast_plane_value_f32(in, got, plane_value) : detail::fast_plane_value_f64(in, got, plane_value);
      }
      if (decided) {
        // The filter decides only sides (shadow, behind the receiver, beyond the light): the
        // case is misclassified when the reference lies on another one.
        out.got_class[i] = static_cast<std::int8_t>(images.got_class(r));
        out.plane_value[i] = plane_value;
        out.misclassified[i] = !same && !rejected && images.reference_class(r) != images.got_class(r);
        continue;
      }
    }
    load_case(b, i, scratch, got);
    for (std::size_t j = 0; j < n; ++j) {
      g.outputs[j].exact_defined = true;
      g.outputs[j].reference = refs.values[j * count + i];
    }
    g.rejected = rejected;
    g.got_class.reset();
    g.reference_class.reset();
    g.plane_value.reset();
    g.misclassified = false;
    spec.grade_meaning(g, scratch, conv, got, true, oracle_mode::filtered);
    out.misclassified[i] = g.misclassified ? 1 : 0;
    out.got_class[i] = g.got_class ? static_cast<std::int8_t>(*g.got_class) : std::int8_t(-1);
    out.plane_value[i] = g.plane_value ? *g.plane_value : std::numeric_limits<double>::quiet_NaN();
  }
}

template <class F>
void grade_columns_range(const case_batch& b, const conventions& conv, const batch_references& refs, batch_grades& out,
                         std::size_t first, std::size_t end, batch_path path) {
  const std::size_t count = b.count, n = signature(b.op).output_count;
  test_case scratch;
  double got[16];
  if (graded_up_to_scale(b.op, conv)) {  // the scale comes from the outputs: grade_case's own code
    for (std::size_t i = first; i < end; ++i) {
      load_case(b, i, scratch, got);
      store_case_grade(grade_case(scratch, conv, got), i, out);
    }
    return;
  }
  std::uint64_t* max_ulps = out.max_ulps.data();
  std::uint8_t* worst = out.worst_output.data();
  for (std::size_t i = first; i < end; ++i) {
    max_ulps[i] = 0;
    worst[i] = 0;
    out.nonfinite[i] = out.garbage[i] = out.misclassified[i] = 0;
    out.got_class[i] = -1;
    out.plane_value[i] = std::numeric_limits<double>::quiet_NaN();
  }
  // Output by output over the cases, the common case without a branch (AVX2 where chosen).
  const bool use_avx2 = path != batch_path::generic && avx2_batch_available();
  const detail::grade_column_function grade = use_avx2 ? detail::avx2_grade_column(b.type) : grade_column<F>;
  bool any_special = false;
  for (std::size_t j = 0; j < n; ++j)
    any_special |= grade(b.outputs.data() + j * count, refs.values.data() + j * count, refs.undefined.data(), j,
                                   first, end, out.ulps.data() + j * count, out.flags.data() + j * count, max_ulps, worst);
  // The cases with a non-finite, garbage or undefined output: grade_case itself, case by case
  // (rejections as a whole, undefined entries, overflows to the right infinity).
  const detail::operation_spec& spec = detail::spec_of(b.op);
  std::vector<std::uint8_t> graded_whole;  // per case of the range: 1 when grade_case graded it
  if (any_special) {
    graded_whole.assign(end - first, 0);
    for (std::size_t i = first; i < end; ++i) {
      bool special = false;
      for (std::size_t j = 0; j < n; ++j) special |= (out.flags[j * count + i] & 0x80) != 0;
      if (!special) continue;
      load_case(b, i, scratch, got);
      store_case_grade(grade_case(scratch, conv, got), i, out);
      graded_whole[i - first] = 1;
    }
  }
  if (spec.grade_meaning) grade_images_range(b, conv, refs, out, first, end, graded_whole, use_avx2);
}

}  // namespace

case_batch make_batch(const std::vector<test_case>& cases) {
  case_batch b;
  if (cases.empty()) return b;
  b.op = cases.front().op;
  b.type = cases.front().type;
  b.count = cases.size();
  const auto& sig = signature(b.op);
  b.inputs.assign(sig.input_count * b.count, 0.0);
  b.outputs.assign(sig.output_count * b.count, 0.0);
  b.ids.resize(b.count);
  b.classes.resize(b.count);
  for (std::size_t i = 0; i < b.count; ++i) {
    const test_case& c = cases[i];
    if (c.op != b.op || c.type != b.type || c.inputs.size() != sig.input_count)
      throw internal_error("make_batch: case " + std::to_string(c.id) + " is not of the batch's operation and type");
    for (std::size_t k = 0; k < sig.input_count; ++k) b.inputs[k * b.count + i] = c.inputs[k];
    b.ids[i] = c.id;
    b.classes[i] = c.cls;
  }
  return b;
}

test_case case_at(const case_batch& batch, std::size_t i) {
  test_case c;
  double got[16];
  load_case(batch, i, c, got);
  return c;
}

void run_implementation(const implementation& impl, case_batch& batch) {
  detail::run_implementation_range(impl, batch, 0, batch.count);
}

bool avx2_batch_available() {
  return detail::avx2_supported() && detail::avx2_batch_filter(operation::shadow_matrix, scalar_type::f32) != nullptr;
}

void compute_references(const case_batch& batch, const conventions& conv, batch_references& out,
                        oracle_counters* counters, batch_path path) {
  detail::prepare_references(batch, out);
  detail::compute_references_range(batch, conv, out, 0, batch.count, counters, path);
}

void grade_batch(const case_batch& batch, const conventions& conv, const batch_references& refs, batch_grades& out,
                 batch_path path) {
  detail::prepare_grades(batch, out);
  detail::grade_range(batch, conv, refs, out, 0, batch.count, path);
}

namespace detail {

// Every element is written by the range functions, so resizing (which keeps a batch's storage
// from one call to the next) is enough.
void prepare_references(const case_batch& batch, batch_references& out) {
  const std::size_t n = signature(batch.op).output_count;
  out.count = batch.count;
  out.values.resize(n * batch.count);
  out.undefined.resize(batch.count);
  out.point_class.resize(batch.count);
  out.decided_by.resize(batch.count);
}

void prepare_grades(const case_batch& batch, batch_grades& out) {
  const std::size_t n = signature(batch.op).output_count;
  out.count = batch.count;
  out.outputs_per_case = n;
  out.ulps.resize(n * batch.count);
  out.flags.resize(n * batch.count);
  out.max_ulps.resize(batch.count);
  out.worst_output.resize(batch.count);
  out.nonfinite.resize(batch.count);
  out.garbage.resize(batch.count);
  out.misclassified.resize(batch.count);
  out.got_class.resize(batch.count);
  out.plane_value.resize(batch.count);
}

void run_implementation_range(const implementation& impl, case_batch& batch, std::size_t first, std::size_t end) {
  const auto& sig = signature(batch.op);
  double in[16], got[16];
  for (std::size_t i = first; i < end; ++i) {
    for (std::size_t k = 0; k < sig.input_count; ++k) in[k] = batch.inputs[k * batch.count + i];
    for (std::size_t j = 0; j < sig.output_count; ++j) got[j] = 0;
    impl.run(in, got);
    for (std::size_t j = 0; j < sig.output_count; ++j) batch.outputs[j * batch.count + i] = got[j];
  }
}

void compute_references_range(const case_batch& batch, const conventions& conv, batch_references& out,
                              std::size_t first, std::size_t end, oracle_counters* counters, batch_path path) {
  if (first >= end) return;
  const operation_spec& spec = spec_of(batch.op);
  const auto& sig = spec.signature;
  const std::size_t count = batch.count, k = sig.matrix_size, n = sig.output_count;
  const bool f32 = batch.type == scalar_type::f32;
  // The filter over the range: columns offset to its first case.
  const double* in_columns[16];
  double* out_columns[16];
  for (std::size_t c = 0; c < sig.input_count; ++c) in_columns[c] = batch.inputs.data() + c * count + first;
  for (std::size_t c = 0; c < n; ++c) out_columns[c] = out.values.data() + layout_index(c, k, conv) * count + first;
  const bool use_avx2 = path != batch_path::generic && avx2_batch_available();
  const batch_filter filter = use_avx2 ? avx2_batch_filter(batch.op, batch.type) : generic_batch_filter(batch.op, batch.type);
  std::uint8_t* decided = out.decided_by.data() + first;  // 1 = decided, turned into decided_by below
  const bool point = batch.op == operation::shadow_point;
  // The filters and kernels compute right-handed matrices: a left-handed convention (column 2
  // negated) goes to the generic oracle, whose exact templates apply it.
  const bool right_handed = conv.hand == handedness::right;
  if (right_handed && filter) filter(in_columns, end - first, conv, {out_columns, decided, point ? out.point_class.data() + first : nullptr});
  else std::fill(decided, decided + (end - first), std::uint8_t{0});
  const fast_kernel kernel =
      right_handed || spec.fast_kernels_read_handedness ? (f32 ? spec.fast_f32 : spec.fast_f64) : nullptr;
  // The cases the filter decided have every output defined and no class (but shadow-point's,
  // from the filter): written for every case in passes without a branch, the others' overwritten
  // below. decided_by becomes 0 where the filter decided, 1 where not (until the case is).
  std::fill(out.undefined.begin() + static_cast<std::ptrdiff_t>(first),
            out.undefined.begin() + static_cast<std::ptrdiff_t>(end), std::uint32_t{0});
  if (!point)
    std::fill(out.point_class.begin() + static_cast<std::ptrdiff_t>(first),
              out.point_class.begin() + static_cast<std::ptrdiff_t>(end), std::int8_t{-1});
  std::uint64_t intervals = 0, rationals = 0;
  for (std::size_t i = first; i < end; ++i) {
    intervals += decided[i - first];
    out.decided_by[i] ^= 1;
  }
  double in[16];
  fast_reference r;
  for (std::size_t i = first; i < end; ++i) {
    // Eight cases at a time while the filter decided all of them (eight zero bytes).
    if (i + 8 <= end) {
      std::uint64_t eight;
      std::memcpy(&eight, out.decided_by.data() + i, sizeof eight);
      if (eight == 0) {
        i += 7;
        continue;
      }
    }
    if (out.decided_by[i] == 0) continue;
    for (std::size_t c = 0; c < sig.input_count; ++c) in[c] = batch.inputs[c * count + i];
    if (kernel && kernel(in, conv, r)) {
      out.decided_by[i] = 1;
      ++intervals;
    } else {
      try {
        if (f32) generic_reference<float, ival32>(spec, in, conv, r);
        else generic_reference<double, ival64>(spec, in, conv, r);
        out.decided_by[i] = 2;
        ++intervals;
      } catch (const undecided&) {
        if (f32) generic_reference<float, rational>(spec, in, conv, r);
        else generic_reference<double, rational>(spec, in, conv, r);
        out.decided_by[i] = 3;
        ++rationals;
      }
    }
    store_reference(r, i, k, conv, out);
  }
  if (counters) {
    counters->decided_by_intervals += intervals;
    counters->fell_back_to_rationals += rationals;
  }
}

void grade_range(const case_batch& batch, const conventions& conv, const batch_references& refs, batch_grades& out,
                 std::size_t first, std::size_t end, batch_path path) {
  if (batch.type == scalar_type::f32) grade_columns_range<float>(batch, conv, refs, out, first, end, path);
  else grade_columns_range<double>(batch, conv, refs, out, first, end, path);
}

}  // namespace detail

}  // namespace shadowproof
