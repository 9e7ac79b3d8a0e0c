#version 460
// Compute runner test (tests/gpu/compute_runner_test.cpp): every element of the input list
// is appended to the output list plus kAdd (a specialisation constant); invocation 0 also
// appends the step index (a per-step push constant). Dispatched indirectly from the
// input counter; the lists ping-pong between steps.
layout(local_size_x = 64) in;
layout(constant_id = 0) const uint kAdd = 0;

layout(std430, set = 0, binding = 0) readonly buffer In { uint values_in[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Out { uint values_out[]; };
// groups_x, groups_y, groups_z (VkDispatchIndirectCommand), then the element count.
layout(std430, set = 0, binding = 2) readonly buffer CountIn { uint dispatch_in[3]; uint count_in; };
layout(std430, set = 0, binding = 3) buffer CountOut { uint dispatch_out[3]; uint count_out; };
layout(push_constant) uniform Params { uint step; } params;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i < count_in) values_out[atomicAdd(count_out, 1u)] = values_in[i] + kAdd;
  if (i == 0) values_out[atomicAdd(count_out, 1u)] = params.step;
}
