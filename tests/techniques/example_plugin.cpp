// An out-of-tree technique: a flat (linear) triangle surface, enough to prove
// the plug-in path end to end.
#include "techniques/registry.h"

namespace {

class FlatTechnique final : public tb::Technique {
 public:
  const tb::TechniqueInfo& info() const override {
    static const tb::TechniqueInfo kInfo{"example_flat", tb::TechniqueFamily::kSurface,
                                         "Flat triangles (example plug-in)", "none", "triangles"};
    return kInfo;
  }
  std::vector<tb::VariantInfo> variants() const override { return {{"default", "flat", {}}}; }
  std::string checkSupport(const tb::Mesh&) const override { return "example_flat: builds nothing"; }
  std::unique_ptr<tb::TechniqueInstance> build(const tb::TechniqueInput&,
                                               const tb::VariantInfo&) const override {
    throw tb::UnsupportedInput("example_flat: builds nothing");
  }
};

}  // namespace

extern "C" int tessbench_register_techniques(tb::TechniqueRegistry* registry) {
  registry->add(std::make_unique<FlatTechnique>());
  return kTessbenchPluginAbi;
}
