#include "harness/measures/common/isa/isa_worker.h"

#include <exception>
#include <istream>
#include <memory>
#include <ostream>
#include <string>

#include "core/gpu/compiler_device.h"
#include "core/gpu/pipeline_executables.h"
#include "harness/measures/common/isa/isa_request.h"
#include "shaders/embedded_shaders.h"

namespace tb::measures::isa {
namespace {

CompileOutcome compile(VkDevice device, const std::string& line) {
  CompileOutcome outcome;
  try {
    const PipelineRequest request = requestFromLine(line);
    for (const auto& [path, words] : request.plugin_shaders) gpu::registerShader(path, words);
    outcome.executables =
        request.kind == PipelineRequest::Kind::kPatchProgram
            ? gpu::patchProgramExecutables(device, request.program, request.build,
                                           request.representations)
            : gpu::computePassExecutables(device, request.pass, request.representations);
  } catch (const std::exception& error) {
    outcome.executables.clear();
    outcome.error = error.what();
  }
  return outcome;
}

}  // namespace

int serveRequests(std::istream& in, std::ostream& out) {
  auto created = gpu::CompilerDevice::create();
  WorkerHello hello;
  std::unique_ptr<gpu::CompilerDevice> device;
  if (!created) {
    hello.error = created.error();
  } else {
    device = std::move(created.value());
    hello.device = device->info().device_name;
    hello.driver = device->info().driver_name + " " + device->info().driver_info;
  }
  out << toLine(hello) << '\n' << std::flush;
  if (!hello.error.empty()) return 1;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    out << toLine(compile(device->device(), line)) << '\n' << std::flush;
  }
  return 0;
}

}  // namespace tb::measures::isa
