// A simulation's Vulkan compute programs as plain data, the compute counterpart of
// GpuPatchProgram (core/gpu/patch_program_desc.h): which embedded shader, which buffers,
// how many workgroups. Techniques fill it without touching Vulkan; core/gpu/compute_runner.h
// records the dispatches (every pass of N steps in one command buffer, no read-back
// inside the step loop). No Vulkan header is needed to include this one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tb::gpu {

// One storage buffer of a compute pass, bound at binding `binding` of set 0.
struct GpuComputeBuffer {
  uint32_t binding = 0;
  std::string name;                     // "particles_in", "append_counter": for reports and errors
  uint64_t size_bytes = 0;              // allocation size; >= 4 * initial_words.size()
  std::vector<uint32_t> initial_words;  // upload, as 32-bit words (floats bit-cast); may be empty
  // Another pass of the same simulation writes it and this one reads it (ping-pong
  // buffers, counters): the runner keeps one allocation per name across passes.
  bool shared_across_passes = true;
  // Ping-pong: on odd steps (0-based step index) this binding gets the buffer named
  // `alternate_with` instead, and that buffer's binding (when the pass binds it too) gets
  // this one. Empty: the same buffer every step. Both names are allocated by the runner.
  std::string alternate_with;
};

// One dispatch per simulation step (or per solver iteration, see repeats_per_step).
struct GpuComputePass {
  std::string shader;                     // embedded path, e.g. "wave_particles/update.comp"
  std::vector<GpuComputeBuffer> buffers;  // bindings of set 0
  std::vector<uint32_t> specialization;   // specialisation constants 0..M-1 (variant switches)
  std::vector<uint32_t> push_constants;   // the push block as 32-bit words; may be empty
  // Workgroups in x, y, z; ignored when indirect_buffer is not empty.
  uint32_t groups_x = 1, groups_y = 1, groups_z = 1;
  // vkCmdDispatchIndirect: the name of the buffer holding VkDispatchIndirectCommand at
  // indirect_offset_bytes (wave particles size the update from the append counter with no
  // CPU read-back). Empty: a direct dispatch.
  std::string indirect_buffer;
  uint64_t indirect_offset_bytes = 0;
  uint32_t repeats_per_step = 1;  // solver iterations per step (Jacobi), >= 1
  // Per-step push constant: the runner writes the 0-based step index (counted over every
  // run of one ComputeRunner) into push_constants[step_index_word] before each step's
  // dispatches; -1: the push block is the same every step. Lets a pass emit on a given
  // step or seed by step without a CPU round trip.
  int32_t step_index_word = -1;
};

// Every pass of one step, in submission order, with a barrier between consecutive passes.
struct GpuComputeProgram {
  std::string name;  // "jacobi", "splat": the program's role in a step
  std::vector<GpuComputePass> passes;
};

}  // namespace tb::gpu
