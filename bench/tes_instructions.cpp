// x86 instructions per TES invocation on lavapipe (docs/MEASURES.md): lavapipe has
// no pipeline-executable statistics and Mesa's debug dumps are compiled out, but
// callgrind sees the JIT code. This program runs a technique's GPU program at each level
// given, with callgrind counting only the timed run (a discarded dump before it resets the
// counters, a dump after it); bench/callgrind_tes.sh runs it under valgrind and takes the slope
// between two levels, which removes the per-draw and per-submission overhead.
//   tes_instructions TECHNIQUE ASSET [VARIANT] [LEVEL...]
#include <valgrind/callgrind.h>

#include <cstdio>
#include <string>
#include <vector>

#include "core/gpu/context.h"
#include "core/gpu/patch_program.h"
#include "harness/suite/asset_catalog.h"
#include "techniques/registry.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s TECHNIQUE ASSET [VARIANT] [LEVEL...]\n", argv[0]);
    return 2;
  }
  try {
    const tb::techniques::Technique* technique =
        tb::techniques::TechniqueRegistry::instance().find(argv[1]);
    if (technique == nullptr) throw std::runtime_error(std::string("unknown technique ") + argv[1]);
    const tb::mesh::Mesh mesh = tb::suite::loadAsset(tb::suite::resolveAsset(argv[2]));
    tb::techniques::VariantInfo variant = technique->variants()[0];
    for (const tb::techniques::VariantInfo& v : technique->variants()) {
      if (argc > 3 && v.name == argv[3]) variant = v;
    }
    std::vector<float> levels;
    for (int i = 4; i < argc; ++i) levels.push_back(std::stof(argv[i]));
    if (levels.empty()) levels = {8, 16};
    const auto patches = tb::techniques::buildSurface(*technique, mesh, variant);
    // The first program only: callgrind_tes.sh takes the slope between exactly two dumps.
    // Patches that mix domains have one program per domain; the others are not counted.
    const auto programs = patches->gpuPrograms();
    if (programs.empty()) throw std::runtime_error(std::string(argv[1]) + " has no GPU program");
    const tb::gpu::GpuPatchProgram* program = &programs.front();
    if (programs.size() > 1) {
      std::fprintf(stderr, "tes_instructions: %zu programs; counting the %s one (%s) only\n",
                   programs.size(), std::string(tb::tess::toString(program->domain)).c_str(),
                   program->evaluation_shader.c_str());
    }
    auto context = tb::gpu::Context::create();
    if (!context) throw std::runtime_error("no usable Vulkan device: " + context.error());

    tb::gpu::PatchProgramOptions options;
    options.capture = false;
    options.patch_count = 16;  // enough invocations for a slope; valgrind is ~50x slower
    options.patches_per_draw = 4;
    for (float level : levels) {
      tb::tess::Levels uniform;
      uniform.outer = {level, level, level, level};
      uniform.inner = {level, level};
      tb::gpu::runPatchProgram(*context.value(), *program, uniform, options);  // JIT warm-up
      CALLGRIND_DUMP_STATS_AT("discard");  // a dump also resets the counters
      const auto run = tb::gpu::runPatchProgram(*context.value(), *program, uniform, options);
      const std::string label = "level " + std::to_string(level) + " tes_invocations " +
                                std::to_string(run.stats.tes_invocations);
      CALLGRIND_DUMP_STATS_AT(label.c_str());
      std::printf("%s %s %s %s\n", argv[1], variant.name.c_str(), argv[2], label.c_str());
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "tes_instructions: %s\n", error.what());
    return 1;
  }
  return 0;
}
