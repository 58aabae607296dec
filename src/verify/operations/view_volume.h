#pragma once
// What ortho, frustum and perspective share: the exact matrix of a view volume with its flat
// extents marked undefined, and the view-volume reproducer.
#include <array>
#include <string>

#include "../operation_table.h"
#include "shadowproof/constructions/handedness.h"
#include "shadowproof/constructions/project.h"
#include "shadowproof/core/ulp.h"

namespace shadowproof::detail {

/// The exact matrix built by `build(v)` from the box x = (l, r, b, t, n, f). A flat volume
/// (l = r, b = t or n = f) divides by zero only in the entries that scale or centre that axis:
/// row k's diagonal and its offset column (`offset_column(k)`: 3 for ortho and the depth row,
/// 2 for the x and y rows of a frustum). Those are marked undefined; the other entries still
/// exist and are computed with that extent made non-zero (they do not depend on it). A builder
/// declared symmetric (l = −r, b = −t) has a zero centre offset by construction, so for it a
/// flat x or y extent leaves that offset defined as 0. A left-handed convention negates
/// column 2 (handedness.h).
template <class N, class Build, class OffsetColumn>
exact_outputs<N> view_volume_matrix(const std::array<N, 6>& x, const conventions& conv, Build build,
                                    OffsetColumn offset_column) {
  exact_outputs<N> r;
  std::array<N, 6> v = x;
  r.entry_undefined.assign(16, false);
  small_vector<std::size_t> zero_offsets;
  for (std::size_t k = 0; k < 3; ++k)
    if (sign_n(N(x[2 * k + 1] - x[2 * k])) == 0) {
      v[2 * k + 1] = x[2 * k] + N(1);
      const std::size_t offset = offset_column(k);
      r.entry_undefined[k * 4 + k] = true;
      if (conv.symmetric_view && k < 2) zero_offsets.push_back(k * 4 + offset);
      else r.entry_undefined[k * 4 + offset] = true;
    }
  r.set_matrix(with_handedness(build(v), conv.hand));
  for (std::size_t i = 0; i < zero_offsets.n; ++i) r.values[zero_offsets[i]] = N(0);
  return r;
}

/// The six box inputs as numbers of type N.
template <class N>
std::array<N, 6> box_from(const double* in) {
  std::array<N, 6> x;
  for (std::size_t i = 0; i < 6; ++i) x[i] = from_double<N>(in[i]);
  return x;
}

/// " --handedness left" for a left-handed convention, nothing for the default.
inline std::string handedness_flag(const conventions& conv) {
  return conv.hand == handedness::left ? " --handedness left" : "";
}

/// "shadowproof project <kind> --left … --far … --convention <depth>"; `shadowproof exact` for
/// a flat box (and for a frustum with near or far not positive), which `project` rejects.
inline std::string box_reproducer(const char* kind, const test_case& c, const conventions& conv) {
  const double* x = c.inputs.data();
  const bool flat = x[0] == x[1] || x[2] == x[3] || x[4] == x[5];
  const bool behind = std::string(kind) == "frustum" && !(x[4] > 0 && x[5] > 0);
  if (flat || behind) return exact_command(c, conv);
  static const char* const flags[] = {"--left", "--right", "--bottom", "--top", "--near", "--far"};
  std::string s = std::string("shadowproof project ") + kind;
  for (std::size_t i = 0; i < 6; ++i) s += std::string(" ") + flags[i] + " " + hex_string(c.inputs[i]);
  return s + " --convention " + std::string(to_string(conv.depth)) + handedness_flag(conv);
}

}  // namespace shadowproof::detail
