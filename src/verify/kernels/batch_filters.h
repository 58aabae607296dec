#pragma once
// The batch filters of every operation, written once over the real type R (double for the
// generic variant, four doubles for AVX2): a block of cases is copied into local columns (no
// aliasing between inputs and outputs), filtered lane by lane, and copied out.
#include <cstddef>
#include <cstdint>

#include "batch.h"
#include "field_of_view.h"
#include "frustum.h"
#include "look_at.h"
#include "normal_matrix.h"
#include "ortho.h"
#include "perspective.h"
#include "reflection_matrix.h"
#include "shadow_matrix.h"
#include "shadow_point.h"
#include "view_size.h"

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
/// ortho-size and perspective-size through their own forms (view_size.h), in the lanes where
/// w, h ≥ 0 (a negative extent has no projection: the kernel for one case takes those).
template <class Form, class F>
struct size_op {
  static constexpr int inputs = 4, outputs = Form::entries;
  template <class R>
  static auto run(R* x, const conventions& conv, R* values, R&) {
    const auto extents = (x[0] >= R(0.0)) & (x[1] >= R(0.0));
    return extents & filter_lanes<Form, F, R>(x, conv, values);
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

/// look-at (placement false) and target-to (true): the frame over lanes (look_at.h). Graded up
/// to scale, no lane is decided: the kernel for one case refuses the convention.
template <class F, bool placement>
struct frame_op {
  static constexpr int inputs = 9, outputs = 16;
  template <class R>
  SHADOWPROOF_FLATTEN static auto run(R* x, const conventions& conv, R* values, R&) {
    const auto decided = look_at_filter::frame_lanes<F, placement, R>(x, conv, values);
    return conv.homogeneous ? no_lanes(x[0]) : decided;
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
SHADOWPROOF_FLATTEN void filter_block(const double* const* in, std::size_t first, std::size_t n, const conventions& conv,
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
/// vector is left undecided (the kernel for one case takes it). The column pointers are copied
/// first: the byte stores of the masks could otherwise alias them, and every store would
/// reload them. flatten inlines the formula into the loop (no call, no spill of its lanes).
template <class Op, class R>
SHADOWPROOF_FLATTEN void filter_all(const double* const* in, std::size_t count, const conventions& conv,
                                 const batch_filter_out& out) {
  using L = lanes_of<R>;
  if constexpr (L::width == 1) {
    for (std::size_t first = 0; first < count; first += 16)
      filter_block<Op>(in, first, count - first < 16 ? count - first : 16, conv, out);
  } else {
    const double* inputs[Op::inputs];
    double* values[Op::outputs];
    for (int k = 0; k < Op::inputs; ++k) inputs[k] = in[k];
    for (int j = 0; j < Op::outputs; ++j) values[j] = out.values[j];
    std::uint8_t* const decided = out.decided;
    std::int8_t* const classes = out.point_class;
    std::size_t i = 0;
    // With many output columns, blocks of `group` vectors whose outputs are stored column by
    // column, whole cache lines at a time: the columns of a batch of a power-of-two number of
    // cases share cache sets, and storing each column's vector in turn evicts every line
    // between its two halves.
    constexpr std::size_t group = 8, block = group * L::width;
    for (; Op::outputs >= 8 && i + block <= count; i += block) {
      R v[group][Op::outputs];
#pragma GCC unroll 1
      for (std::size_t g = 0; g < group; ++g) {
        const std::size_t at = i + g * L::width;
        R x[Op::inputs], cls = R(0.0);
        SHADOWPROOF_UNROLL
        for (int k = 0; k < Op::inputs; ++k) x[k] = L::load(inputs[k] + at);
        const auto ok = Op::run(x, conv, v[g], cls);
        L::store_mask(decided + at, ok);
        if (classes) L::store_classes(classes + at, cls);
      }
      for (int j = 0; j < Op::outputs; ++j)
        SHADOWPROOF_UNROLL
        for (std::size_t g = 0; g < group; ++g) L::store(values[j] + i + g * L::width, v[g][j]);
    }
    for (; i + L::width <= count; i += L::width) {
      R x[Op::inputs], v[Op::outputs], cls = R(0.0);
      SHADOWPROOF_UNROLL
      for (int k = 0; k < Op::inputs; ++k) x[k] = L::load(inputs[k] + i);
      const auto ok = Op::run(x, conv, v, cls);
      SHADOWPROOF_UNROLL
      for (int j = 0; j < Op::outputs; ++j) L::store(values[j] + i, v[j]);
      L::store_mask(decided + i, ok);
      if (classes) L::store_classes(classes + i, cls);
    }
    for (; i < count; ++i) decided[i] = 0;
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
      return f32 ? filter_all<frame_op<float, false>, R> : filter_all<frame_op<double, false>, R>;
    case operation::target_to:
      return f32 ? filter_all<frame_op<float, true>, R> : filter_all<frame_op<double, true>, R>;
    case operation::ortho_size:
      return f32 ? filter_all<size_op<ortho_size_form, float>, R> : filter_all<size_op<ortho_size_form, double>, R>;
    case operation::perspective_size:
      return f32 ? filter_all<size_op<perspective_size_form, float>, R>
                 : filter_all<size_op<perspective_size_form, double>, R>;
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
