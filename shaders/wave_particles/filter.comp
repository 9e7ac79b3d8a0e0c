#version 460
// The filter (Yuksel et al. 2007, section 5): the splatted points convolved with the
// particle shape, 1/2 (cos(pi d / r) + 1) sampled at node offsets within the radius (the
// kernel comes from the CPU). Writes the height map.
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Grid { int accum[]; };
layout(std430, set = 0, binding = 1) readonly buffer Kernel { float kernel_weights[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Height { float height[]; };
layout(push_constant) uniform Params {
  uint nodes;
  int reach;        // kernel half-width in nodes
  float inv_scale;  // metres per fixed-point unit
} params;

void main() {
  const uint c = gl_GlobalInvocationID.x;
  if (c >= params.nodes * params.nodes) return;
  const int i = int(c % params.nodes), j = int(c / params.nodes), n = int(params.nodes);
  const int width = 2 * params.reach + 1;
  float sum = 0.0;
  for (int dj = -params.reach; dj <= params.reach; ++dj) {
    const int jj = j - dj;
    if (jj < 0 || jj >= n) continue;
    for (int di = -params.reach; di <= params.reach; ++di) {
      const int ii = i - di;
      if (ii < 0 || ii >= n) continue;
      const int value = accum[jj * n + ii];
      if (value != 0) {
        sum += float(value) * kernel_weights[(dj + params.reach) * width + di + params.reach];
      }
    }
  }
  height[c] = sum * params.inv_scale;
}
