// shadow-matrix: plane P[4], light L[4] -> the planar shadow matrix M = (P·L) I − L Pᵀ,
// 16 entries (row-major, column vectors).
// Classes: near-degenerate = light within a relative 2^-4 … 2^-(p−1) of parallel to
// (directional) or of lying on (point) the receiver; degenerate = exactly so, P·L = 0; range =
// P and L scaled so that their products over- or underflow.
// Stable: an entry is −L_i P_j (one rounding) or Σ_{k≠i} P_k L_k (three products, two sums: three
// roundings on its longest path), so c = 2 × 3 = 6 (docs/verdicts.md); the evaluation
// (P·L) − L_i P_i, which rounds P·L first, is not stable where L_i P_i dominates the entry.
#include "shadowproof/constructions/shadow.h"

#include "../operation_table.h"

namespace shadowproof::detail {
namespace {

template <class N>
exact_outputs<N> exact(const double* in, const conventions& conv) {
  exact_outputs<N> r;
  r.set_matrix(shadow_matrix(plane_from<N>(in), canonical_light<N>(in + 4, conv)));
  return r;
}

void generate(case_rng& r, input_class cls, const conventions& requirements, double* in) {
  shadow_inputs(r, cls, requirements, in, in + 4);
}

double closeness(const double* in) { return log2_relative_dot(in, in + 4, 4); }

std::string reproducer(const test_case& c, const conventions& conv) {
  // A directional light given along its rays negates the matrix `shadow` prints.
  if (conv.light == light_sign::along_rays && c.inputs[7] == 0) return exact_command(c, conv);
  return "shadowproof shadow --plane " + hex_list(c, 0, 4) + " --light " + hex_list(c, 4, 4);
}

void from_configuration(const double* plane, const double* light, const double*, double* in) {
  std::copy(plane, plane + 4, in);
  std::copy(light, light + 4, in + 4);
}

operation_spec make() {
  operation_spec s{};
  s.op = operation::shadow_matrix;
  s.name = "shadow-matrix";
  s.summary = "plane[4], light[4] -> M = (P·L) I - L Pᵀ, 16 entries";
  s.signature = make_signature({{"plane", 4}, {"light", 4}}, 16, 4);
  s.generate = generate;
  s.closeness = closeness;
  SHADOWPROOF_EXACT_TEMPLATE(s, exact);
  s.sensitivity = shadow_matrix_sensitivity;
  s.stable_constant = 6;
  s.sentinel_outputs = matrix_sentinels;
  s.fast_f32 = fast_shadow_matrix_f32;
  s.fast_f64 = fast_shadow_matrix_f64;
  s.reproducer = reproducer;
  s.invalid = invalid_plane_and_light;
  s.from_configuration = from_configuration;
  s.symmetries.plane_degree = 1;  // M is linear in P and in L
  s.symmetries.light_degree = 1;
  s.symmetries.swap_xy = true;
  return s;
}

}  // namespace

const operation_spec& shadow_matrix_spec() {
  static const operation_spec s = make();
  return s;
}

}  // namespace shadowproof::detail
