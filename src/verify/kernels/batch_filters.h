#pragma once
// The batch filters of every operation, written once over the real type R (double for the
// generic variant, four doubles for AVX2): a block of cases is copied into local columns (no
// aliasing between inputs and outputs), filtered lane by lane, and copied out.
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "batch.h"
#include "field_of_view.h"
#include "frustum.h"
#include "normal_matrix.h"
#include "ortho.h"
#include "perspective.h"
#include "reflection_matrix.h"
#include "shadow_matrix.h"
#include "shadow_point.h"

namespace shadowproof::detail {
inline namespace SHADOWPROOF_KERNEL_TARGET {

/// How a lane type loads and stores: R::width cases at a time from contiguous columns.
/// batch_avx2.cpp specialises it for its vector; double is one case (the generic filter then
/// works on blocks of local columns instead, see filter_block).
template <class R>
struct lanes_of {
  static constexpr std::size_t width = 1;
};

// One fraction form over the cases of one vector, from the columns: `values` gets the outputs.
template <class Form, class F>
struct fraction_op {
  static constexpr int inputs = Form::inputs, outputs = Form::entries;
  template <class R>
  static auto run(R* x, const conventions& conv, R* values, R&) {
    return filter_lanes<Form, F, R>(x, conv, values);
  }
};
/// ortho-size and perspective-size through a box form, as their kernels (view_size.cpp): the
/// box (−w/2, w/2, −h/2, h/2, n, f) with symmetric_view set, in the lanes where w, h ≥ 0 and
/// halving them is exact in F (the others are left to the kernel for one case).
template <class Form, class F>
struct size_op {
  static constexpr int inputs = 4, outputs = Form::entries;
  template <class R>
  static R doubled_in_type(R half) {
    if constexpr (std::is_same_v<F, float>) return round_to_float_value(half) * R(2.0);
    else return half * R(2.0);
  }
  template <class R>
  static auto run(R* x, const conventions& conv, R* values, R&) {
    const R half_w = x[0] * R(0.5), half_h = x[1] * R(0.5);
    const auto exact_halves = (x[0] >= R(0.0)) & (x[1] >= R(0.0)) & (doubled_in_type(half_w) == x[0]) &
                              (doubled_in_type(half_h) == x[1]);
    R box[6] = {-half_w, half_w, -half_h, half_h, x[2], x[3]};
    conventions symmetric = conv;
    symmetric.symmetric_view = true;
    return exact_halves & filter_lanes<Form, F, R>(box, symmetric, values);
  }
};

template <class F>
struct shadow_point_op {
  static constexpr int inputs = 11, outputs = 3;
  template <class R>
  static auto run(R* x, const conventions& conv, R* values, R& cls) {
    return shadow_point_lanes<F, R>(x, conv, values, cls);
  }
};

template <class F>
struct shadow_image_op {
  static constexpr int inputs = 17, outputs = 3;
  template <class R>
  static auto run(R* x, const conventions& conv, R* values, R& cls) {
    return shadow_image_lanes<F, R>(x, conv, values, cls);
  }
};

/// Cases [first, first + n), n ≤ block, on doubles: copied into local columns (which alias
/// nothing), filtered by a loop whose body has no branch on the values (the compiler
/// vectorises it: flatten inlines the whole formula into it), copied out.
template <class Op>
[[gnu::flatten]] void filter_block(const double* const* in, std::size_t first, std::size_t n, const conventions& conv,
                  const batch_filter_out& out) {
  constexpr std::size_t block = 16;
  double xs[Op::inputs][block], vs[Op::outputs][block], classes[block];
  bool decided[block];
  for (int k = 0; k < Op::inputs; ++k)
    for (std::size_t b = 0; b < block; ++b) xs[k][b] = in[k][first + (b < n ? b : 0)];
  for (std::size_t b = 0; b < block; ++b) {
    double x[Op::inputs], v[Op::outputs], cls = 0;
    SHADOWPROOF_UNROLL
    for (int k = 0; k < Op::inputs; ++k) x[k] = xs[k][b];
    decided[b] = Op::run(x, conv, v, cls);
    classes[b] = cls;
    SHADOWPROOF_UNROLL
    for (int j = 0; j < Op::outputs; ++j) vs[j][b] = v[j];
  }
  for (int j = 0; j < Op::outputs; ++j)
    for (std::size_t b = 0; b < n; ++b) out.values[j][first + b] = vs[j][b];
  for (std::size_t b = 0; b < n; ++b) {
    out.decided[first + b] = decided[b] ? 1 : 0;
    if (out.point_class) out.point_class[first + b] = static_cast<std::int8_t>(classes[b]);
  }
}

/// The filter of one operation over all cases, R lanes at a time; a tail shorter than a
/// vector is left undecided (the kernel for one case takes it).
template <class Op, class R>
void filter_all(const double* const* in, std::size_t count, const conventions& conv, const batch_filter_out& out) {
  using L = lanes_of<R>;
  if constexpr (L::width == 1) {
    for (std::size_t first = 0; first < count; first += 16)
      filter_block<Op>(in, first, count - first < 16 ? count - first : 16, conv, out);
  } else {
    std::size_t i = 0;
    for (; i + L::width <= count; i += L::width) {
      R x[Op::inputs], v[Op::outputs], cls = R(0.0);
      for (int k = 0; k < Op::inputs; ++k) x[k] = L::load(in[k] + i);
      const auto ok = Op::run(x, conv, v, cls);
      for (int j = 0; j < Op::outputs; ++j) L::store(out.values[j] + i, v[j]);
      L::store_mask(out.decided + i, ok);
      if (out.point_class) L::store_classes(out.point_class + i, cls);
    }
    for (; i < count; ++i) out.decided[i] = 0;
  }
}

/// The filter of (op, type) over lanes R.
template <class R>
batch_filter batch_filter_over(operation op, scalar_type type) {
  const bool f32 = type == scalar_type::f32;
  switch (op) {
    case operation::shadow_matrix:
      return f32 ? filter_all<fraction_op<shadow_matrix_form, float>, R> : filter_all<fraction_op<shadow_matrix_form, double>, R>;
    case operation::shadow_point:
      return f32 ? filter_all<shadow_point_op<float>, R> : filter_all<shadow_point_op<double>, R>;
    case operation::reflection_matrix:
      return f32 ? filter_all<fraction_op<reflection_matrix_form, float>, R>
                 : filter_all<fraction_op<reflection_matrix_form, double>, R>;
    case operation::ortho:
      return f32 ? filter_all<fraction_op<ortho_form, float>, R> : filter_all<fraction_op<ortho_form, double>, R>;
    case operation::frustum:
      return f32 ? filter_all<fraction_op<frustum_form, float>, R> : filter_all<fraction_op<frustum_form, double>, R>;
    case operation::normal_matrix:
      return f32 ? filter_all<fraction_op<normal_matrix_form, float>, R>
                 : filter_all<fraction_op<normal_matrix_form, double>, R>;
    case operation::perspective:
      return f32 ? filter_all<fraction_op<perspective_form, float>, R> : filter_all<fraction_op<perspective_form, double>, R>;
    case operation::perspective_fov:
      return f32 ? filter_all<field_of_view_lanes::field_of_view_op<float, false>, R>
                 : filter_all<field_of_view_lanes::field_of_view_op<double, false>, R>;
    case operation::perspective_fov_infinite:
      return f32 ? filter_all<field_of_view_lanes::field_of_view_op<float, true>, R>
                 : filter_all<field_of_view_lanes::field_of_view_op<double, true>, R>;
    case operation::look_at:
    case operation::target_to:
      return nullptr;  // no batch filter: the kernel for one case, or the generic oracle, case by case
    case operation::ortho_size:
      return f32 ? filter_all<size_op<ortho_form, float>, R> : filter_all<size_op<ortho_form, double>, R>;
    case operation::perspective_size:
      return f32 ? filter_all<size_op<frustum_form, float>, R> : filter_all<size_op<frustum_form, double>, R>;
  }
  return nullptr;
}

/// The shadow-point image filter of `type` over lanes R (batch.h's image_filter).
template <class R>
batch_filter image_filter_over(scalar_type type) {
  return type == scalar_type::f32 ? filter_all<shadow_image_op<float>, R> : filter_all<shadow_image_op<double>, R>;
}

}  // namespace SHADOWPROOF_KERNEL_TARGET
}  // namespace shadowproof::detail
