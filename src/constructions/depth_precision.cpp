#include "shadowproof/constructions/depth_precision.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "shadowproof/core/error.h"

namespace shadowproof {
namespace {

// 2²⁴ − 1: the largest unorm24 code, which stands for depth 1.
const mpz_class unorm24_max = (mpz_class(1) << 24) - 1;

int sign(const rational& q) { return sgn(q); }

std::uint32_t float_bits(float f) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}

// The float that v is, exactly; precondition v representable in binary32.
float as_float(const rational& v) { return to_nearest_float(v); }

// Exact preimage of stored quantity v in eye distance, on the side of the pole where the
// interval lies (`side` = sign of c z + d there). Nothing when v is not reached there.
std::optional<rational> preimage(const depth_function<rational>& df, depth_convention c,
                                 depth_format format, const rational& v, int side) {
  const rational z_ndc = ndc_from_stored_quantity(v, c, format);
  // z_ndc (c z + d) = a z + b  ⇔  z (c z_ndc − a) = b − d z_ndc.
  const rational denominator = df.c * z_ndc - df.a;
  if (denominator == 0) return std::nullopt;
  const rational z = (df.b - df.d * z_ndc) / denominator;
  const rational s = -z;
  if (!(s > 0) || sign(rational(df.c * z + df.d)) != side) return std::nullopt;
  return s;
}

}  // namespace

std::string_view to_string(depth_format f) {
  return f == depth_format::f32 ? "f32" : "unorm24";
}

depth_format parse_depth_format(std::string_view text) {
  if (text == "f32") return depth_format::f32;
  if (text == "unorm24") return depth_format::unorm24;
  throw error(errc::depth_precision_format,
              "unknown depth format '" + std::string(text) + "': expected f32 or unorm24");
}

rational window_depth(const rational& z_ndc, depth_convention c) {
  if (c == depth_convention::gl) return rational((z_ndc + 1) / 2);
  return z_ndc;
}

rational ndc_from_window(const rational& d, depth_convention c) {
  if (c == depth_convention::gl) return rational(2 * d - 1);
  return d;
}

rational stored_quantity(const rational& z_ndc, depth_convention c, depth_format format) {
  return format == depth_format::f32 ? z_ndc : window_depth(z_ndc, c);
}

rational ndc_from_stored_quantity(const rational& x, depth_convention c, depth_format format) {
  return format == depth_format::f32 ? x : ndc_from_window(x, c);
}

rational nearest_representable(const rational& d, depth_format format) {
  if (format == depth_format::f32) return exact_value(static_cast<double>(to_nearest_float(d)));
  rational x = d;
  if (x < 0) x = 0;
  if (x > 1) x = 1;
  x *= unorm24_max;
  mpz_class k;
  mpz_fdiv_q(k.get_mpz_t(), x.get_num_mpz_t(), x.get_den_mpz_t());
  const rational fraction = x - rational(k);
  // Round half to even: a tie goes to the even code.
  if (fraction > rational(1, 2) || (fraction == rational(1, 2) && mpz_odd_p(k.get_mpz_t()))) ++k;
  rational code(k, unorm24_max);
  code.canonicalize();
  return code;
}

std::int64_t representable_index(const rational& v, depth_format format) {
  if (format == depth_format::f32) {
    const std::uint32_t bits = float_bits(as_float(v));
    const std::int64_t magnitude = bits & 0x7fffffffu;
    return (bits & 0x80000000u) ? -magnitude : magnitude;
  }
  const rational k = v * unorm24_max;
  return k.get_num().get_si();
}

std::optional<rational> neighbour_representable(const rational& v, depth_format format,
                                                int direction) {
  if (format == depth_format::f32) {
    const float inf = std::numeric_limits<float>::infinity();
    const float next = std::nextafter(as_float(v), direction > 0 ? inf : -inf);
    if (std::isinf(next)) return std::nullopt;
    return exact_value(static_cast<double>(next));
  }
  const mpz_class k = mpz_class(v.get_num() * (unorm24_max / v.get_den())) + (direction > 0 ? 1 : -1);
  if (k < 0 || k > unorm24_max) return std::nullopt;
  rational code(k, unorm24_max);
  code.canonicalize();
  return code;
}

depth_precision_report depth_precision(const mat4<rational>& M, depth_convention c,
                                       depth_format format, const rational& from,
                                       const rational& to, const std::vector<rational>& at) {
  const auto df = depth_function_of(M);
  if (!df)
    throw error(errc::depth_precision_not_separable,
                "the projection's depth depends on x or y, not on the eye depth alone");
  if (df->determinant() == 0)
    throw error(errc::depth_precision_constant_depth,
                "the projection maps every eye depth to the same NDC depth (a d - b c = 0)");
  if (!(from > 0) || !(from < to))
    throw error(errc::depth_precision_interval, "the eye-distance interval [" + to_string(from) +
                                                ", " + to_string(to) +
                                                "] must satisfy 0 < from < to");
  // The pole of z_ndc(−s) is at s = d/c; the interval must lie on one side of it.
  if (df->c != 0) {
    const rational pole = df->d / df->c;
    if (from <= pole && pole <= to)
      throw error(errc::depth_precision_pole, "the interval [" + to_string(from) + ", " +
                                              to_string(to) + "] contains the distance " +
                                              to_string(pole) + " where w_clip = 0");
  }
  const int side = sign(rational(-df->c * from + df->d));

  auto depth_at = [&](const rational& s, const char* what) {
    if (!(s > 0) || sign(rational(-df->c * s + df->d)) != side)
      throw error(errc::depth_precision_outside_volume,
                  std::string(what) + ": distance " + to_string(s) +
                      " is not in front of the eye on the side of the interval");
    const rational z_ndc = (*df)(rational(-s));
    const rational d = window_depth(z_ndc, c);
    if (d < 0 || d > 1)
      throw error(errc::depth_precision_outside_volume,
                  std::string(what) + ": distance " + to_string(s) + " has NDC depth " +
                      to_string(z_ndc) + ", outside the near/far range of " +
                      std::string(to_string(c)) + ": it would be clipped");
    return stored_quantity(z_ndc, c, format);
  };

  depth_precision_report r{c, format, from, to, depth_at(from, "interval start"), depth_at(to, "interval end"),
                           0, {}};
  const std::int64_t i0 = representable_index(nearest_representable(r.depth_from, format), format);
  const std::int64_t i1 = representable_index(nearest_representable(r.depth_to, format), format);
  r.distinct_values = static_cast<std::uint64_t>(i1 > i0 ? i1 - i0 : i0 - i1) + 1;

  // d is monotonic in s; this is the direction of increasing distance in stored values.
  const int direction = r.depth_to > r.depth_from ? 1 : -1;
  for (const rational& s : at) {
    depth_sample sample{s, depth_at(s, "sample"), 0, std::nullopt, std::nullopt};
    sample.stored = nearest_representable(sample.depth, format);
    sample.stored_distance = preimage(*df, c, format, sample.stored, side);
    const auto next = neighbour_representable(sample.stored, format, direction);
    if (next && sample.stored_distance) {
      const auto next_distance = preimage(*df, c, format, *next, side);
      if (next_distance) sample.spacing = *next_distance - *sample.stored_distance;
    }
    r.samples.push_back(std::move(sample));
  }
  return r;
}

}  // namespace shadowproof
