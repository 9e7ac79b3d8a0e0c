#version 460
// The displacement map seed 003 renders from: normal (xyz) and height (w) per node, the
// normal from central differences of the height map (one-sided at the border).
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Height { float height[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Displacement { vec4 displacement[]; };
layout(push_constant) uniform Params {
  uint nodes;
  float spacing;  // m
} params;

void main() {
  const uint c = gl_GlobalInvocationID.x;
  const uint n = params.nodes;
  if (c >= n * n) return;
  const uint i = c % n, j = c / n;
  const uint i0 = i > 0u ? i - 1u : i, i1 = i + 1u < n ? i + 1u : i;
  const uint j0 = j > 0u ? j - 1u : j, j1 = j + 1u < n ? j + 1u : j;
  const float dhdx = (height[j * n + i1] - height[j * n + i0]) / (float(i1 - i0) * params.spacing);
  const float dhdy = (height[j1 * n + i] - height[j0 * n + i]) / (float(j1 - j0) * params.spacing);
  displacement[c] = vec4(normalize(vec3(-dhdx, -dhdy, 1.0)), height[c]);
}
