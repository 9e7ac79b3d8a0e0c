// The list of techniques: built-in ones register themselves at static
// initialisation (TB_REGISTER_TECHNIQUE), out-of-tree ones through loadPlugin.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "techniques/technique.h"

namespace tb {

class TechniqueRegistry {
 public:
  static TechniqueRegistry& instance();

  // Ignores a second technique with an id already present and returns false.
  bool add(std::unique_ptr<Technique> technique);
  const Technique* find(std::string_view id) const;
  // Sorted by id, so every listing and every run has the same order.
  std::vector<const Technique*> all() const;

 private:
  std::vector<std::unique_ptr<Technique>> techniques_;
};

// Loads a shared library that exports the C entry point below and lets it add
// its techniques. Throws std::runtime_error naming the file on failure.
void loadPlugin(const std::string& path);

}  // namespace tb

// Entry point a plug-in library exports. It receives the host's registry, adds
// its techniques and returns kTessbenchPluginAbi; any other value rejects the
// plug-in (built against another technique.h).
// 6: SurfacePatches gained makeBatchPattern() and evaluateBatch() (batched evaluation,
// techniques/batch_eval.h). 5: Technique::build returns a TechniqueInstance (surface() / simulation()) instead of
// buildPatches; SurfacePatches lost domain() and gpuProgram() (patchDomain(p) and
// gpuPrograms() remain). 4: per-patch domains, gpuPrograms().
inline constexpr int kTessbenchPluginAbi = 6;
extern "C" {
typedef int (*TessbenchPluginEntry)(tb::TechniqueRegistry* registry);
}
#define TB_PLUGIN_ENTRY_NAME "tessbench_register_techniques"

#define TB_REGISTER_TECHNIQUE_CONCAT2(a, b) a##b
#define TB_REGISTER_TECHNIQUE_CONCAT(a, b) TB_REGISTER_TECHNIQUE_CONCAT2(a, b)
// One line in a technique's .cpp: TB_REGISTER_TECHNIQUE(PhongTechnique);
#define TB_REGISTER_TECHNIQUE(Class)                                                          \
  static const bool TB_REGISTER_TECHNIQUE_CONCAT(tb_registered_, __LINE__) [[maybe_unused]] = \
      ::tb::TechniqueRegistry::instance().add(std::make_unique<Class>())
