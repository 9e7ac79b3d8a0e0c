#version 460
// Transform-feedback capture of gl_TessCoord, bit for bit (as uint so nothing can
// canonicalise it). The harness rewrites the domain, spacing, winding and point-mode
// execution modes per pipeline (core/gpu/spirv_patch.cpp).
layout(triangles, equal_spacing, ccw) in;

layout(location = 0, xfb_buffer = 0, xfb_stride = 12, xfb_offset = 0) out flat uvec3 tess_coord_bits;

void main() {
  tess_coord_bits = floatBitsToUint(gl_TessCoord);
  gl_Position = vec4(gl_TessCoord, 1.0);
}
