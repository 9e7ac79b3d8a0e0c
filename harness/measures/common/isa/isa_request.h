// One pipeline to compile for its statistics, as plain data that crosses a process
// boundary: the ISA measure's compiler workers (isa_compilers.h) each run one RADV null
// device, and a request names embedded shaders, never SPIR-V, so the worker (the same
// build) compiles exactly what the suite would.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/gpu/compute_program_desc.h"
#include "core/gpu/patch_program_desc.h"
#include "core/gpu/patch_program_pipeline.h"
#include "core/gpu/pipeline_executables.h"

namespace tb::measures::isa {

struct PipelineRequest {
  enum class Kind : uint8_t { kPatchProgram, kComputePass };
  Kind kind = Kind::kPatchProgram;
  // kPatchProgram: the program (storage buffer contents left empty: only their count
  // shapes the pipeline layout) and its build switches.
  gpu::GpuPatchProgram program;
  gpu::ProgramBuild build;
  // kComputePass: the pass (buffers only by binding; push block only by size).
  gpu::GpuComputePass pass;
  bool representations = false;  // also the executables' assembly
  // The SPIR-V of the stages a plug-in registered (gpu::isRegisteredShader), by path: the
  // worker loads no plug-in, so it registers them before compiling. Built-in shaders go by
  // name alone (the worker is the same build).
  std::vector<std::pair<std::string, std::vector<uint32_t>>> plugin_shaders;
};

// Attaches the SPIR-V of the request's plug-in shaders (PipelineRequest::plugin_shaders).
void attachPluginShaders(PipelineRequest* request);

// The request as one line of JSON (keys sorted, so equal requests give equal lines: the
// compile cache's key) and back. fromLine throws std::runtime_error on a malformed line.
std::string toLine(const PipelineRequest& request);
PipelineRequest requestFromLine(const std::string& line);

// A worker's answer: the executables, or why there are none.
struct CompileOutcome {
  std::vector<gpu::PipelineExecutable> executables;
  std::string error;  // empty when compiled
};
std::string toLine(const CompileOutcome& outcome);
CompileOutcome outcomeFromLine(const std::string& line);

// The worker's first line: the device it compiles for, or why it has none.
struct WorkerHello {
  std::string device;  // "AMD RADV NAVI21" (the null device's name)
  std::string driver;  // "radv Mesa 22.3.6": VkPhysicalDeviceDriverProperties
  std::string error;   // non-empty: the worker has no usable device
};
std::string toLine(const WorkerHello& hello);
WorkerHello helloFromLine(const std::string& line);

}  // namespace tb::measures::isa
