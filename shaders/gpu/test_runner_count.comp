#version 460
// Compute runner test: adds 1 to a counter per dispatch (repeats_per_step).
layout(local_size_x = 1) in;
layout(std430, set = 0, binding = 0) buffer Total { uint total; };
void main() { total += 1u; }
