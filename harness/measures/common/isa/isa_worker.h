// The compiler worker's loop (tessbench-isa-worker, harness/measures/isa/worker): a process
// started with one Vulkan driver in its environment (RADV's null device for one AMD family)
// answers PipelineRequests one line at a time.
#pragma once

#include <iosfwd>

namespace tb::measures::isa {

// Creates a device on whatever Vulkan driver the environment gives, writes a WorkerHello
// line, then answers each request line of `in` with a CompileOutcome line, flushed, until
// `in` ends. Returns the process exit status: 0, or 1 when the device could not be made
// (the hello line says why).
int serveRequests(std::istream& in, std::ostream& out);

}  // namespace tb::measures::isa
