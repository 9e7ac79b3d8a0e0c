#include "techniques/registry.h"

#include <dlfcn.h>

#include <algorithm>
#include <stdexcept>

namespace tb {

TechniqueRegistry& TechniqueRegistry::instance() {
  static TechniqueRegistry registry;
  return registry;
}

bool TechniqueRegistry::add(std::unique_ptr<Technique> technique) {
  if (find(technique->info().id) != nullptr) return false;
  techniques_.push_back(std::move(technique));
  return true;
}

const Technique* TechniqueRegistry::find(std::string_view id) const {
  for (const auto& technique : techniques_) {
    if (technique->info().id == id) return technique.get();
  }
  return nullptr;
}

std::vector<const Technique*> TechniqueRegistry::all() const {
  std::vector<const Technique*> result;
  for (const auto& technique : techniques_) result.push_back(technique.get());
  std::sort(result.begin(), result.end(),
            [](const Technique* a, const Technique* b) { return a->info().id < b->info().id; });
  return result;
}

void loadPlugin(const std::string& path) {
  // The handle is kept open for the life of the process: the techniques'
  // vtables live in the library.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* reason = dlerror();
    throw std::runtime_error(path + ": cannot load plug-in: " + (reason ? reason : "unknown"));
  }
  auto entry = reinterpret_cast<TessbenchPluginEntry>(dlsym(handle, TB_PLUGIN_ENTRY_NAME));
  if (entry == nullptr) {
    throw std::runtime_error(path + ": not a tessbench plug-in (no " TB_PLUGIN_ENTRY_NAME ")");
  }
  const int abi = entry(&TechniqueRegistry::instance());
  if (abi != kTessbenchPluginAbi) {
    throw std::runtime_error(path + ": plug-in ABI " + std::to_string(abi) + ", expected " +
                             std::to_string(kTessbenchPluginAbi));
  }
}

const char* toString(TechniqueFamily family) {
  return family == TechniqueFamily::kSurface ? "surface" : "simulation";
}

const char* toString(PatchDomain domain) {
  return domain == PatchDomain::kTriangle ? "triangle" : "quad";
}

}  // namespace tb
