#version 460
// Clears the splat accumulators before this step's splat.
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) writeonly buffer Grid { int accum[]; };
layout(push_constant) uniform Params { uint node_count; } params;
void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i < params.node_count) accum[i] = 0;
}
