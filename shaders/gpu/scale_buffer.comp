#version 460
// data[i] *= factor, for i < count. Used to check the compute path end to end.
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) buffer Data { float data[]; };
layout(push_constant) uniform Params {
  uint count;
  float factor;
} params;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i < params.count) data[i] *= params.factor;
}
