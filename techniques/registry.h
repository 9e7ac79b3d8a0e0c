// The list of techniques: built-in ones register themselves at static
// initialisation (TB_REGISTER_TECHNIQUE), out-of-tree ones through loadPlugin.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/mesh/registry.h"
#include "techniques/plugin.h"
#include "techniques/technique.h"

namespace tb::techniques {

// add, find and all() (sorted by id): mesh::Registry.
class TechniqueRegistry : public mesh::Registry<Technique> {
 public:
  static TechniqueRegistry& instance();
};

// Loads a plug-in (techniques/plugin.h): asks its ABI first and refuses one built against
// another kTessbenchPluginAbi before calling anything else; then lets it register into a
// staging host and adds its techniques and shaders only when all of them fit (no id or
// shader name taken). Throws std::runtime_error with one line naming the file on failure;
// the registry is then unchanged.
void loadPlugin(const std::string& path);

}  // namespace tb::techniques

#define TB_REGISTER_TECHNIQUE_CONCAT2(a, b) a##b
#define TB_REGISTER_TECHNIQUE_CONCAT(a, b) TB_REGISTER_TECHNIQUE_CONCAT2(a, b)
// One line in a technique's .cpp: TB_REGISTER_TECHNIQUE(PhongTechnique);
#define TB_REGISTER_TECHNIQUE(Class)                                                          \
  static const bool TB_REGISTER_TECHNIQUE_CONCAT(tb_registered_, __LINE__) [[maybe_unused]] = \
      ::tb::techniques::TechniqueRegistry::instance().add(std::make_unique<Class>())
