#version 460
// The compute path's draw: vertex pulling from the evaluate pass's 10-word records
// (shaders/common/compute_surface.glsl); clip position (position, 1) as tbEmitVertex sets it.
layout(std430, set = 0, binding = 0) readonly buffer Vertices { uint vertex_words[]; };

void main() {
  const uint base = uint(gl_VertexIndex) * 10u;
  gl_Position = vec4(uintBitsToFloat(vertex_words[base + 4u]),
                     uintBitsToFloat(vertex_words[base + 5u]),
                     uintBitsToFloat(vertex_words[base + 6u]), 1.0);
}
