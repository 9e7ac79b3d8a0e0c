#version 460
// Compute runner test: sizes the next step's indirect dispatch from this step's output
// count (64 invocations a group) and clears the counter the next step appends to.
layout(local_size_x = 1) in;
layout(std430, set = 0, binding = 0) buffer CountIn { uint dispatch_in[3]; uint count_in; };
layout(std430, set = 0, binding = 1) buffer CountOut { uint dispatch_out[3]; uint count_out; };

void main() {
  dispatch_out[0] = (count_out + 63u) / 64u;
  dispatch_out[1] = 1u;
  dispatch_out[2] = 1u;
  count_in = 0u;
  dispatch_in[0] = 0u;
}
