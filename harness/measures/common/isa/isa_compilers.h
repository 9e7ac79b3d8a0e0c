// The GPU compilers the ISA measure asks: one worker process per AMD family, each running
// RADV's null device (VK_ICD_FILENAMES naming the radeon ICD, RADV_FORCE_FAMILY the
// family), which compiles real pipelines with ACO and executes nothing. A process holds
// one driver for its life, so each family gets its own, started at its first request and
// kept for the run; every distinct request is compiled once per family per process.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "harness/measures/common/isa/isa_request.h"

namespace tb::measures::isa {

// An AMD family as RADV_FORCE_FAMILY spells it, with its generation.
struct Family {
  std::string_view name;        // "navi21"
  std::string_view generation;  // "RDNA2"
};
// polaris10 (GCN4), vega10 (GCN5), navi10 (RDNA1), navi21 (RDNA2), gfx1100 (RDNA3).
std::span<const Family> defaultFamilies();
// The default families, then raven (GCN5 APU) and gfx1103_r1 (RDNA3 APU): --suite full.
std::span<const Family> fullSuiteFamilies();

// The radeon ICD manifest to give the workers, or empty with `why` set: the process's own
// VK_ICD_FILENAMES / VK_DRIVER_FILES, when set, must name one (they are how a user hides
// drivers); otherwise the first radeon_icd*.json of the loader's system folders.
std::string radeonIcd(std::string* why);

// The worker executable (tessbench-isa-worker): $TB_ISA_WORKER, else beside the running
// executable, else where this build put it; empty with `why` set when none exists.
std::string workerExecutable(std::string* why);

// What one family's compiler made of one request.
struct FamilyCompile {
  std::shared_ptr<const CompileOutcome> outcome;  // null: the family has no compiler
  std::string driver;                             // "radv Mesa 22.3.6" (the worker's hello)
  std::string unavailable;                        // why there is no compiler (outcome null)
};

// Compiles `request` on `family`'s worker, starting it at the first call; answers repeat
// requests from the cache. Thread-safe: one request at a time per family.
FamilyCompile compileOn(std::string_view family, const PipelineRequest& request);

}  // namespace tb::measures::isa
