#version 460
// Writes the tessellation levels exactly as the host gives them. The host passes raw
// float bits, so NaN, negative and denormal levels reach the tessellator unchanged.
layout(vertices = 1) out;

layout(push_constant) uniform PatchLevels {
  uvec4 outer_bits;  // gl_TessLevelOuter[0..3] as float bits
  uvec2 inner_bits;  // gl_TessLevelInner[0..1] as float bits
} levels;

void main() {
  gl_out[gl_InvocationID].gl_Position = vec4(0.0);
  if (gl_InvocationID == 0) {
    gl_TessLevelOuter[0] = uintBitsToFloat(levels.outer_bits.x);
    gl_TessLevelOuter[1] = uintBitsToFloat(levels.outer_bits.y);
    gl_TessLevelOuter[2] = uintBitsToFloat(levels.outer_bits.z);
    gl_TessLevelOuter[3] = uintBitsToFloat(levels.outer_bits.w);
    gl_TessLevelInner[0] = uintBitsToFloat(levels.inner_bits.x);
    gl_TessLevelInner[1] = uintBitsToFloat(levels.inner_bits.y);
  }
}
