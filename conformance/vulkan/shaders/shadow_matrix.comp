#version 450
// The planar shadow matrix M = (P·L) I − L Pᵀ in GLSL's own vocabulary: dot() and
// outerProduct() (outerProduct(L, P) is the matrix L Pᵀ). Written out row by row.
// Case layout (shadow-matrix): plane[4], light[4] -> M[16] (row-major, column vectors).
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { float x[]; } inputs;
layout(std430, binding = 1) writeonly buffer Outputs { float y[]; } outputs;
layout(push_constant) uniform Count { uint count; } pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  uint b = 8u * i;
  vec4 P = vec4(inputs.x[b], inputs.x[b + 1u], inputs.x[b + 2u], inputs.x[b + 3u]);
  vec4 L = vec4(inputs.x[b + 4u], inputs.x[b + 5u], inputs.x[b + 6u], inputs.x[b + 7u]);
  mat4 M = dot(P, L) * mat4(1.0) - outerProduct(L, P);
  for (uint r = 0u; r < 4u; ++r)
    for (uint c = 0u; c < 4u; ++c) outputs.y[16u * i + 4u * r + c] = M[c][r];  // M[column][row]
}
