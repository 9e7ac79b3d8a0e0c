#version 460
// Colour is a hash of the ID for eyeballing; the ID attachment holds the exact value.
layout(std430, set = 0, binding = 1) readonly buffer TriangleIds { uint triangle_id[]; };

layout(location = 0) out vec4 color;
layout(location = 1) out uint id;

void main() {
  const uint tri_id = triangle_id[gl_PrimitiveID];
  const uint h = tri_id * 2654435761u;
  color = vec4(float(h & 255u), float((h >> 8) & 255u), float((h >> 16) & 255u), 255.0) / 255.0;
  id = tri_id;
}
