#include "engine_shadow.h"

namespace engine {

void shadow_matrix(const float plane[4], const float light[4], float out[16]) {
  double s = 0;
  for (int i = 0; i < 4; ++i) s += static_cast<double>(plane[i]) * light[i];
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      out[r * 4 + c] = static_cast<float>((r == c ? s : 0.0) - static_cast<double>(light[r]) * plane[c]);
}

void shadow_matrix_with_planted_defect(const float plane[4], const float light[4], float out[16]) {
  shadow_matrix(plane, light, out);
  double s = 0;
  for (int i = 0; i < 4; ++i) s += static_cast<double>(plane[i]) * light[i];
  out[15] = static_cast<float>(s);
}

}  // namespace engine
