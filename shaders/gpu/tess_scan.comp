#version 460
// The compute tessellator's scan: exclusive prefix sums of every patch's point and index
// counts into offsets, and the totals, in one workgroup (each invocation sums a run of
// consecutive patches, a shared-memory Hillis-Steele scan joins the runs). Bindings as
// tessellate.comp's; the patches, points and indices are not touched.

const uint kThreads = 256u;
layout(local_size_x = 256) in;

layout(std430, set = 0, binding = 1) readonly buffer Counts { uvec4 counts[]; };
layout(std430, set = 0, binding = 2) writeonly buffer Offsets { uvec2 offsets[]; };
layout(std430, set = 0, binding = 3) buffer Status {
  uint total_points;
  uint total_index_words;
  uint errors;
} status;

layout(push_constant) uniform Params { uint patch_count; } params;

shared uvec2 run_sum[kThreads];

void main() {
  const uint t = gl_LocalInvocationID.x;
  const uint per_thread = (params.patch_count + kThreads - 1u) / kThreads;
  const uint first = min(t * per_thread, params.patch_count);
  const uint end = min(first + per_thread, params.patch_count);
  uvec2 sum = uvec2(0u);
  for (uint p = first; p < end; ++p) sum += counts[p].xy;
  run_sum[t] = sum;
  barrier();
  for (uint stride = 1u; stride < kThreads; stride *= 2u) {
    const uvec2 add = t >= stride ? run_sum[t - stride] : uvec2(0u);
    barrier();
    run_sum[t] += add;
    barrier();
  }
  uvec2 offset = run_sum[t] - sum;  // exclusive: the runs before this one
  for (uint p = first; p < end; ++p) {
    offsets[p] = offset;
    offset += counts[p].xy;
  }
  if (t == kThreads - 1u) {
    status.total_points = run_sum[t].x;
    status.total_index_words = run_sum[t].y;
  }
}
