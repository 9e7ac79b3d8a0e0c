#include "techniques/registry.h"

#include <dlfcn.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "shaders/embedded_shaders.h"

namespace tb::techniques {

TechniqueRegistry& TechniqueRegistry::instance() {
  static TechniqueRegistry registry;
  return registry;
}

namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

// Where a plug-in registers: nothing reaches the real registry until the plug-in's whole
// registration succeeded and fits.
class StagingHost final : public PluginHost {
 public:
  void addTechnique(std::unique_ptr<Technique> technique) override {
    if (technique == nullptr) throw std::runtime_error("addTechnique(nullptr)");
    techniques.push_back(std::move(technique));
  }
  void addShader(std::string path, std::vector<uint32_t> spirv_words) override {
    shaders.emplace_back(std::move(path), std::move(spirv_words));
  }
  std::vector<std::unique_ptr<Technique>> techniques;
  std::vector<std::pair<std::string, std::vector<uint32_t>>> shaders;
};

// The reason the staged registration cannot be added, or empty.
std::string checkStaged(const StagingHost& staged) {
  std::vector<std::string> ids;
  for (const auto& technique : staged.techniques) {
    const std::string& id = technique->info().id;
    if (TechniqueRegistry::instance().find(id) != nullptr ||
        std::find(ids.begin(), ids.end(), id) != ids.end()) {
      return "technique id '" + id + "' is already registered";
    }
    ids.push_back(id);
  }
  if (ids.empty()) return "it registered no technique";
  std::vector<std::string> paths;
  for (const auto& [path, words] : staged.shaders) {
    if (!gpu::embeddedShader(path).empty() ||
        std::find(paths.begin(), paths.end(), path) != paths.end()) {
      return "shader '" + path + "' is already defined";
    }
    if (words.size() < 5 || words[0] != kSpirvMagic) return "shader '" + path + "' is not SPIR-V";
    paths.push_back(path);
  }
  return "";
}

}  // namespace

void loadPlugin(const std::string& path) {
  // The handle is kept open for the life of the process once anything is registered: the
  // techniques' vtables live in the library.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* reason = dlerror();
    throw std::runtime_error(path + ": cannot load plug-in: " + (reason ? reason : "unknown"));
  }
  auto refuse = [&](const std::string& why) {
    dlclose(handle);
    throw std::runtime_error(path + ": " + why);
  };
  // The handshake, before any other code of the plug-in runs.
  auto abi = reinterpret_cast<TessbenchPluginAbiQuery>(dlsym(handle, TB_PLUGIN_ABI_NAME));
  if (abi == nullptr) {
    refuse("not a tessbench plug-in: no " TB_PLUGIN_ABI_NAME
           " entry point (plug-ins built before ABI 7 lack it; see docs/PLUGINS.md)");
  }
  const int plugin_abi = abi();
  if (plugin_abi != kTessbenchPluginAbi) {
    refuse("plug-in ABI " + std::to_string(plugin_abi) + ", this tessbench's ABI " +
           std::to_string(kTessbenchPluginAbi) +
           ": rebuild the plug-in against this tessbench; nothing was registered");
  }
  auto entry = reinterpret_cast<TessbenchPluginEntry>(dlsym(handle, TB_PLUGIN_ENTRY_NAME));
  if (entry == nullptr) refuse("no " TB_PLUGIN_ENTRY_NAME " entry point");
  StagingHost staged;
  try {
    entry(&staged);
  } catch (const std::exception& error) {
    throw std::runtime_error(path + ": the plug-in failed while registering: " + error.what());
  }
  if (const std::string why = checkStaged(staged); !why.empty()) {
    throw std::runtime_error(path + ": " + why + "; nothing was registered");
  }
  for (auto& [shader_path, words] : staged.shaders) {
    gpu::registerShader(shader_path, std::move(words));
  }
  for (auto& technique : staged.techniques) TechniqueRegistry::instance().add(std::move(technique));
}

const char* toString(TechniqueFamily family) {
  return family == TechniqueFamily::kSurface ? "surface" : "simulation";
}

const char* toString(PatchDomain domain) {
  return domain == PatchDomain::kTriangle ? "triangle" : "quad";
}

}  // namespace tb::techniques
