#pragma once
/// Depth-buffer precision of a projection, computed exactly: how many distinct stored depth
/// values an eye-space depth interval gets, and how far apart (in eye space) consecutive stored
/// values are at chosen distances.
///
/// Model. The eye-space point at distance s along the view axis (z_eye = −s) has the exact NDC
/// depth z_ndc(−s) = (a z + b)/(c z + d) (depth_function_of). The quantity held in the format is
///   f32     : the NDC depth z_ndc itself as a binary32 (for d3d and reverse_z this is exactly
///             what a D32_FLOAT buffer stores; for gl it is the float NDC depth in [−1, 1] the
///             pipeline produces before glDepthRange maps it to [0, 1]);
///   unorm24 : the window depth d ∈ [0, 1] as a 24-bit code: d = (z_ndc + 1)/2 for gl
///             (glDepthRange(0, 1)), d = z_ndc for d3d and reverse_z;
/// each rounded to the nearest value of the format (ties to even). This is the ideal pipeline:
/// a real GPU adds the rounding of its own arithmetic, so real precision is at best this.
/// Every representable value v has an exact rational preimage s(v) (the depth function is a
/// Möbius map), so every figure here is an exact rational or integer.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "shadowproof/core/homogeneous.h"
#include "shadowproof/constructions/project.h"

namespace shadowproof {

/// Depth-buffer formats: f32 = IEEE binary32 (D32_FLOAT); unorm24 = 24-bit fixed point,
/// value k/(2²⁴ − 1) for k = 0 … 2²⁴ − 1 (D24).
enum class depth_format { f32, unorm24 };

/// "f32" or "unorm24".
std::string_view to_string(depth_format f);
/// Parses "f32" or "unorm24"; throws error "depth_precision.format" otherwise.
depth_format parse_depth_format(std::string_view text);

/// Window depth d of an NDC depth: (z + 1)/2 for gl, z otherwise.
rational window_depth(const rational& z_ndc, depth_convention c);
/// Inverse of window_depth: 2 d − 1 for gl, d otherwise.
rational ndc_from_window(const rational& d, depth_convention c);
/// The quantity the format holds for NDC depth z_ndc (see Model): z_ndc for f32, the window
/// depth for unorm24.
rational stored_quantity(const rational& z_ndc, depth_convention c, depth_format format);
/// Inverse of stored_quantity: the NDC depth whose stored quantity is x.
rational ndc_from_stored_quantity(const rational& x, depth_convention c, depth_format format);

/// The representable value of `format` nearest to d (ties to even). For unorm24, d is clamped
/// to [0, 1] first (as the hardware does).
rational nearest_representable(const rational& d, depth_format format);
/// Position of a representable value in the increasing order of all values of the format:
/// unorm24 k/(2²⁴−1) ↦ k; f32 ↦ its bit pattern for v ≥ 0 and −(bits of |v|) for v < 0
/// (so +0 and −0 share index 0). Precondition: v is representable.
std::int64_t representable_index(const rational& v, depth_format format);
/// The neighbour of the representable v one step up (direction > 0) or down (direction < 0),
/// or nothing past the end of the format (f32 infinities, unorm24 outside [0, 1]).
std::optional<rational> neighbour_representable(const rational& v, depth_format format,
                                                int direction);

/// Depth precision at one eye distance s.
struct depth_sample {
  rational distance;                ///< s (z_eye = −s)
  rational depth;                   ///< exact stored quantity x(s) (see Model) before rounding
  rational stored;                  ///< v = nearest representable to x(s)
  std::optional<rational> stored_distance;  ///< s(v): the distance whose exact depth is v
  /// s(v') − s(v) where v' is v's neighbour towards greater distances: the eye-space gap between
  /// consecutive stored depths at s. Nothing when v or v' has no preimage in front of the eye.
  std::optional<rational> spacing;
};

/// The full report for one convention and format over eye distances [from, to].
struct depth_precision_report {
  depth_convention convention;
  depth_format format;
  rational from, to;
  rational depth_from, depth_to;  ///< exact stored quantities x(from), x(to) before rounding
  /// Number of distinct stored values {round(x(s)) : s ∈ [from, to]}: because x is continuous
  /// and monotonic and rounding is monotonic, |index(round x(to)) − index(round x(from))| + 1.
  std::uint64_t distinct_values = 0;
  std::vector<depth_sample> samples;
};

/// Report for the projection M (its depth must depend on z_eye alone and be non-constant)
/// under convention c, for eye distances from < to, at the sample distances `at`.
/// Throws error "depth_precision.not_separable" (depth depends on x or y),
/// "depth_precision.constant_depth" (a d − b c = 0), "depth_precision.interval" (from ≥ to or
/// from ≤ 0), "depth_precision.pole" (c z + d vanishes on the interval), and
/// "depth_precision.outside_volume" (an end of the interval, or a sample, has window depth
/// outside [0, 1], i.e. lies outside the near/far range and would be clipped).
depth_precision_report depth_precision(const mat4<rational>& M, depth_convention c,
                                       depth_format format, const rational& from,
                                       const rational& to, const std::vector<rational>& at);

}  // namespace shadowproof
