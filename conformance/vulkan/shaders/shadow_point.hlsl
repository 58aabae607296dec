// The same shadow as shadow_point.comp, written in HLSL as a Unity shader writes it (seed
// 001 is one), compiled by glslang's HLSL front end: unit light direction l, receiver
// through p0 with unit normal n, t = dot(p0 − X, n) / dot(l, n), shadow = X + t l.
// Case layout (shadow-point): plane[4], light[4] (w = 0), point[3] -> shadow[3].
[[vk::binding(0)]] StructuredBuffer<float> inputs;
[[vk::binding(1)]] RWStructuredBuffer<float> outputs;
struct Count { uint count; };
[[vk::push_constant]] Count pc;

[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint i = id.x;
  if (i >= pc.count) return;
  uint b = 11 * i;
  float3 abc = float3(inputs[b], inputs[b + 1], inputs[b + 2]);
  float d = inputs[b + 3];
  float3 lightDir = normalize(float3(inputs[b + 4], inputs[b + 5], inputs[b + 6]));
  float3 worldPos = float3(inputs[b + 8], inputs[b + 9], inputs[b + 10]);
  float3 p0 = -d * abc / dot(abc, abc);
  float3 n = normalize(abc);
  float t = dot(p0 - worldPos, n) / dot(lightDir, n);
  float3 shadowPos = worldPos + t * lightDir;
  outputs[3 * i] = shadowPos.x;
  outputs[3 * i + 1] = shadowPos.y;
  outputs[3 * i + 2] = shadowPos.z;
}
