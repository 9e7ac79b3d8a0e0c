#version 460
// Copies positions_other to positions (after an odd number of Jacobi iterations in a step).
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) writeonly buffer Positions { vec4 x[]; };
layout(std430, set = 0, binding = 1) readonly buffer Other { vec4 x_other[]; };
layout(push_constant) uniform Params { uint vertex_count; } params;
void main() {
  const uint v = gl_GlobalInvocationID.x;
  if (v < params.vertex_count) x[v] = x_other[v];
}
