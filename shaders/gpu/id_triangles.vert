#version 460
// Vertex pulling for the ID render target: clip-space positions from a storage buffer.
layout(std430, set = 0, binding = 0) readonly buffer Positions { vec4 clip_position[]; };

void main() { gl_Position = clip_position[gl_VertexIndex]; }
