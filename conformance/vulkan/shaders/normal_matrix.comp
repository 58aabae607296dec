#version 450
// The normal matrix (A⁻¹)ᵀ with GLSL's built-in inverse() and transpose(), as shaders compute
// it when the application does not upload one: what the driver's inverse() makes of it.
// Case layout (normal-matrix): matrix[9] (A row by row) -> (A⁻¹)ᵀ[9] row by row.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { float x[]; } inputs;
layout(std430, binding = 1) writeonly buffer Outputs { float y[]; } outputs;
layout(push_constant) uniform Count { uint count; } pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  mat3 A;
  for (uint r = 0u; r < 3u; ++r)
    for (uint c = 0u; c < 3u; ++c) A[c][r] = inputs.x[9u * i + 3u * r + c];
  mat3 G = transpose(inverse(A));
  for (uint r = 0u; r < 3u; ++r)
    for (uint c = 0u; c < 3u; ++c) outputs.y[9u * i + 3u * r + c] = G[c][r];
}
