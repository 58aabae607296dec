#version 450
// The planar projected shadow of seed 001's vertex shader (method 1), as a compute shader:
// a directional light's unit direction l, the receiver through p0 with unit normal n, and
//   t = dot(p0 − X, n) / dot(l, n),   shadow = X + t l.
// Generalised from the ground y = 0 to any plane (a, b, c, d): n = normalize(a, b, c) and
// p0 = −d (a, b, c) / |(a, b, c)|², the receiver's point nearest the origin.
// Case layout (shadow-point): plane[4], light[4] (w = 0), point[3] -> shadow[3].
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { float x[]; } inputs;
layout(std430, binding = 1) writeonly buffer Outputs { float y[]; } outputs;
layout(push_constant) uniform Count { uint count; } pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  uint b = 11u * i;
  vec3 abc = vec3(inputs.x[b], inputs.x[b + 1u], inputs.x[b + 2u]);
  float d = inputs.x[b + 3u];
  vec3 lightDir = normalize(vec3(inputs.x[b + 4u], inputs.x[b + 5u], inputs.x[b + 6u]));
  vec3 worldPos = vec3(inputs.x[b + 8u], inputs.x[b + 9u], inputs.x[b + 10u]);
  vec3 p0 = -d * abc / dot(abc, abc);
  vec3 n = normalize(abc);
  float t = dot(p0 - worldPos, n) / dot(lightDir, n);
  vec3 shadowPos = worldPos + t * lightDir;
  uint o = 3u * i;
  outputs.y[o] = shadowPos.x;
  outputs.y[o + 1u] = shadowPos.y;
  outputs.y[o + 2u] = shadowPos.z;
}
