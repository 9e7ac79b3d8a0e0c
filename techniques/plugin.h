// What an out-of-tree technique library (a plug-in) exports, and what the host hands it.
// TB_PLUGIN defines two C entry points: tessbench_plugin_abi() returns the
// kTessbenchPluginAbi it was compiled with (the host calls it first and refuses a plug-in
// whose number is not its own, before any other of its code runs);
// tessbench_register_plugin(host) adds its techniques and SPIR-V shaders to `host`, which
// commits them only when the whole call succeeded. A plug-in never registers from a static
// initialiser (that would run at dlopen, before the handshake). Guide: docs/PLUGINS.md.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "techniques/technique.h"

// Bumped whenever a header a plug-in compiles against (the ones `cmake --install` puts
// under include/tessbench) changes a class layout, a virtual function or an entry point.
// The history of the bumps is in docs/PLUGINS.md ("ABI versions").
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
