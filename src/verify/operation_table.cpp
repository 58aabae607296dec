// The operation table in the order of operations.def, and the public functions that read it.
#include "operation_table.h"

#include <array>
#include <cmath>
#include <limits>

#include "shadowproof/core/number.h"
#include "shadowproof/core/ulp.h"

namespace shadowproof {
namespace detail {

const operation_spec& spec_of(operation op) {
  static const std::vector<const operation_spec*> table = {
#define SHADOWPROOF_OPERATION(code) &code##_spec(),
#include "shadowproof/verify/operations.def"
#undef SHADOWPROOF_OPERATION
  };
  return *table[static_cast<std::size_t>(op)];
}

std::string hex_list(const test_case& c, std::size_t first, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += (i ? "," : "") + hex_string(c.inputs[first + i]);
  return s;
}

std::string exact_command(const test_case& c, const conventions& conv) {
  std::string s = "shadowproof exact --op " + std::string(spec_of(c.op).name) + " --type " +
                  std::string(to_string(c.type)) + " --inputs " + hex_list(c, 0, c.inputs.size());
  if (conv.light == light_sign::along_rays) s += " --light along-rays";
  if (conv.depth != depth_convention::gl) s += " --depth " + std::string(to_string(conv.depth));
  if (conv.clamps_behind_receiver) s += " --clamps-behind-receiver";
  if (conv.symmetric_view) s += " --symmetric";
  if (conv.hand == handedness::left) s += " --convention handedness=left";
  if (conv.angle == angle_unit::degrees) s += " --convention angle=degrees";
  return s;
}

operation_signature make_signature(std::vector<input_group> inputs, std::size_t output_count,
                                   std::size_t matrix_size) {
  std::size_t count = 0;
  for (const auto& g : inputs) count += g.size;
  return {std::move(inputs), count, output_count, matrix_size};
}

namespace {
long double norm(const double* x, std::size_t n) {
  long double s = 0;
  for (std::size_t i = 0; i < n; ++i) s += static_cast<long double>(x[i]) * x[i];
  return std::sqrt(s);
}
}  // namespace

double log2_relative_dot(const double* a, const double* b, std::size_t nb) {
  long double d = 0;
  for (std::size_t i = 0; i < nb; ++i) d += static_cast<long double>(a[i]) * b[i];
  if (nb == 3) d += a[3];  // b is a finite point (x, y, z, 1)
  const long double nbn = nb == 3 ? std::sqrt(norm(b, 3) * norm(b, 3) + 1) : norm(b, 4);
  const long double scale = norm(a, 4) * nbn;
  // Far from 0 the long double sum decides; near it the exact sum does (−inf exactly on it).
  if (std::fabs(d) < 0x1p-40L * scale) {
    rational exact = nb == 3 ? exact_value(a[3]) : rational(0);
    for (std::size_t i = 0; i < nb; ++i) exact += exact_value(a[i]) * exact_value(b[i]);
    if (sgn(exact) == 0) return -std::numeric_limits<double>::infinity();
    d = static_cast<long double>(to_nearest_double(exact));
  }
  return static_cast<double>(std::log2(std::fabs(d) / scale));
}

std::string invalid_plane(const double* in) {
  return in[0] == 0 && in[1] == 0 && in[2] == 0 ? "the plane needs a non-zero normal (a, b, c)" : "";
}

std::string invalid_plane_and_light(const double* in) {
  if (std::string why = invalid_plane(in); !why.empty()) return why;
  return in[4] == 0 && in[5] == 0 && in[6] == 0 && in[7] == 0 ? "the light must not be (0, 0, 0, 0)" : "";
}

std::string never_invalid(const double*) { return ""; }

namespace {
bool square_sentinels(sentinel_kind kind, double* out, std::size_t k) {
  if (kind == sentinel_kind::none) return false;
  for (std::size_t i = 0; i < k * k; ++i) out[i] = kind == sentinel_kind::identity && i % (k + 1) == 0 ? 1.0 : 0.0;
  return true;
}
}  // namespace

bool matrix_sentinels(sentinel_kind kind, double* out) { return square_sentinels(kind, out, 4); }
bool matrix3_sentinels(sentinel_kind kind, double* out) { return square_sentinels(kind, out, 3); }
bool point_sentinels(sentinel_kind kind, double* out) {
  if (kind != sentinel_kind::zero) return false;
  out[0] = out[1] = out[2] = 0;
  return true;
}

bool is_sentinel(const operation_spec& spec, const conventions& conv, const double* got, std::size_t n) {
  if (conv.sentinel == sentinel_kind::none || !spec.sentinel_outputs) return false;
  std::array<double, 16> s{};
  if (!spec.sentinel_outputs(conv.sentinel, s.data())) return false;
  for (std::size_t j = 0; j < n; ++j)
    if (!(got[j] == s[canonical_index(j, spec.signature.matrix_size, conv)])) return false;
  return true;
}

double box_closeness(const double* x) {
  double worst = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 6; i += 2) {
    // x[i] and x[i + 1] are doubles: their difference is 0 exactly when they are equal.
    if (x[i + 1] == x[i]) return -std::numeric_limits<double>::infinity();
    const long double extent = std::fabs(static_cast<long double>(x[i + 1]) - x[i]);
    const long double scale = std::fabs(static_cast<long double>(x[i])) + std::fabs(static_cast<long double>(x[i + 1]));
    worst = std::min(worst, static_cast<double>(std::log2(extent / scale)));
  }
  return worst;
}

}  // namespace detail

const std::vector<operation>& all_operations() {
  static const std::vector<operation> ops{
#define SHADOWPROOF_OPERATION(code) operation::code,
#include "shadowproof/verify/operations.def"
#undef SHADOWPROOF_OPERATION
  };
  return ops;
}

std::string_view to_string(operation op) { return detail::spec_of(op).name; }

std::optional<operation> operation_from_string(std::string_view name) {
  for (operation op : all_operations())
    if (to_string(op) == name) return op;
  return std::nullopt;
}

std::string operation_names(std::string_view separator) {
  std::string s;
  for (operation op : all_operations()) s += (s.empty() ? "" : std::string(separator)) + std::string(to_string(op));
  return s;
}

std::string_view summary(operation op) { return detail::spec_of(op).summary; }

const operation_signature& signature(operation op) { return detail::spec_of(op).signature; }

std::string output_name(operation op, std::size_t j) {
  const std::size_t k = signature(op).matrix_size;
  if (k) return "(" + std::to_string(j / k) + "," + std::to_string(j % k) + ")";
  static const char* const coordinates[] = {"x", "y", "z", "w"};
  return j < 4 ? coordinates[j] : std::to_string(j);
}

const operation_symmetries& symmetries(operation op) { return detail::spec_of(op).symmetries; }

std::optional<std::vector<double>> inputs_from_shadow_configuration(operation op, const double* plane,
                                                                    const double* light, const double* point) {
  const detail::operation_spec& spec = detail::spec_of(op);
  if (!spec.from_configuration) return std::nullopt;
  std::vector<double> inputs(spec.signature.input_count);
  spec.from_configuration(plane, light, point, inputs.data());
  return inputs;
}

std::string_view to_string(scalar_type t) { return t == scalar_type::f32 ? "f32" : "f64"; }

bool representable(double x, scalar_type t) {
  return t == scalar_type::f64 ? std::isfinite(x) : representable_in_float(x);
}

std::optional<scalar_type> scalar_type_from_string(std::string_view name) {
  if (name == "f32") return scalar_type::f32;
  if (name == "f64") return scalar_type::f64;
  return std::nullopt;
}

}  // namespace shadowproof
