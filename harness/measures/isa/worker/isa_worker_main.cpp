// tessbench-isa-worker: one GPU compiler for the ISA measure. Started by
// harness/measures/common/isa/isa_compilers.cpp with one Vulkan driver in its environment
// (RADV's null device for one AMD family); reads PipelineRequest lines on stdin and answers
// each with a CompileOutcome line on stdout.
#include <iostream>

#include "harness/measures/common/isa/isa_worker.h"

int main() {
  std::ios::sync_with_stdio(false);
  return tb::measures::isa::serveRequests(std::cin, std::cout);
}
