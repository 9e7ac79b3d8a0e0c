#version 460
// The compute path's indirect commands from the compute tessellator's totals (its prefix
// sum, tess_scan.comp), so nothing is read back between the passes and the draw
// (core/gpu/compute_path.h): the evaluate pass's dispatch and the indexed draw.
layout(local_size_x = 1) in;

layout(std430, set = 0, binding = 0) readonly buffer Status {
  uint total_points;
  uint total_index_words;
  uint errors;
} status;
// Words 0..2: VkDispatchIndirectCommand (workgroups of 64 points); words 4..8:
// VkDrawIndexedIndirectCommand (index count, 1 instance, first index 0, vertex offset 0,
// first instance 0).
layout(std430, set = 0, binding = 1) writeonly buffer Indirect { uint indirect[]; };

void main() {
  // A kernel error (TessErrors) leaves the counts unreliable: nothing is evaluated or drawn.
  const bool ok = status.errors == 0u;
  indirect[0] = ok ? (status.total_points + 63u) / 64u : 0u;
  indirect[1] = 1u;
  indirect[2] = 1u;
  indirect[3] = 0u;
  indirect[4] = ok ? status.total_index_words : 0u;
  indirect[5] = 1u;
  indirect[6] = 0u;
  indirect[7] = 0u;
  indirect[8] = 0u;
}
