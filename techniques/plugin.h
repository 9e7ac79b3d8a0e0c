// What an out-of-tree technique library (a plug-in) exports, and what the host hands it.
// A plug-in is a shared library with two C entry points, both defined by TB_PLUGIN:
//
//   tessbench_plugin_abi()          returns the kTessbenchPluginAbi it was compiled with.
//                                   The host calls it first and refuses the plug-in, with
//                                   nothing registered and nothing else called, when the
//                                   number is not its own.
//   tessbench_register_plugin(host) adds the plug-in's techniques (and the SPIR-V of their
//                                   shaders) to `host`. The host stages them and adds them
//                                   to its registry only when the whole call succeeded.
//
// A plug-in never registers from a static initialiser (TB_REGISTER_TECHNIQUE is for
// techniques built into tessbench): that code would run at dlopen, before the handshake.
// docs/PLUGINS.md is the guide.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "techniques/technique.h"

// Bumped whenever a header a plug-in compiles against (the ones `cmake --install` puts
// under include/tessbench) changes a class layout, a virtual function or an entry point.
// 12: GpuPatchProgram gained compute_shader, the technique's compute twin of its TCS and TES
//     (core/gpu/compute_path.h: tessellation without the tessellator; a plug-in ships the
//     .comp like its other shaders).
// 11: PatchCullBounds gained bezier_net, bezier_degree and bezier_mirrored (the
//     tangent_plane culling policy).
// 10: Simulation gained constraintSolver() and waveField() (optional capabilities,
//     techniques/constraint_solver.h, wave_field.h), Technique simulationCapabilities();
//     ConstraintSolverTechnique is gone.
// 8: DataFootprint gained displacement_map_bytes, GpuPatchProgram a displacement map
//    (GpuDisplacement), Scenario its technique, sections and mesh path, SimulationFootprint
//    the alternative a user would pick (alternative_bytes, alternative).
// 7: handshake first (tessbench_plugin_abi, then tessbench_register_plugin(PluginHost*));
//    plug-ins ship shaders through PluginHost::addShader.
// 6: SurfacePatches gained makeBatchPattern() and evaluateBatch() (batched evaluation,
// techniques/batch_eval.h). 5: Technique::build returns a TechniqueInstance (surface() /
// simulation()) instead of buildPatches; SurfacePatches lost domain() and gpuProgram()
// (patchDomain(p) and gpuPrograms() remain). 4: per-patch domains, gpuPrograms().
inline constexpr int kTessbenchPluginAbi = 12;

namespace tb::techniques {

class PluginHost {
 public:
  virtual ~PluginHost() = default;
  // A technique; its id must be new to the host.
  virtual void addTechnique(std::unique_ptr<Technique> technique) = 0;
  // The SPIR-V of a shader the plug-in's GpuPatchProgram names, under that name
  // ("<technique id>/<file>", e.g. "flat/flat.tese"); the name must be new to the host.
  // tessbench_add_plugin(... SHADERS ...) compiles them and generates the calls
  // (docs/PLUGINS.md).
  virtual void addShader(std::string path, std::vector<uint32_t> spirv_words) = 0;
};

}  // namespace tb::techniques

extern "C" {
typedef int (*TessbenchPluginAbiQuery)();
typedef void (*TessbenchPluginEntry)(tb::techniques::PluginHost* host);
}
#define TB_PLUGIN_ABI_NAME "tessbench_plugin_abi"
#define TB_PLUGIN_ENTRY_NAME "tessbench_register_plugin"

// In one .cpp of a plug-in:
//   TB_PLUGIN(host) { host.addTechnique(std::make_unique<MyTechnique>()); }
#define TB_PLUGIN(host_name)                                                        \
  static void tbPluginRegister(::tb::techniques::PluginHost& host_name);            \
  extern "C" __attribute__((visibility("default"))) int tessbench_plugin_abi() {    \
    return kTessbenchPluginAbi;                                                     \
  }                                                                                 \
  extern "C" __attribute__((visibility("default"))) void tessbench_register_plugin( \
      ::tb::techniques::PluginHost* host) {                                         \
    tbPluginRegister(*host);                                                        \
  }                                                                                 \
  static void tbPluginRegister(::tb::techniques::PluginHost& host_name)
