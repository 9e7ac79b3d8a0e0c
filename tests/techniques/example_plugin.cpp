// An out-of-tree technique built the way a plug-in is (a MODULE seeing only the plug-in
// headers), registering through TB_PLUGIN: enough to prove loading and the handshake.
// The measured example, with shaders, is examples/plugin/.
#include "techniques/plugin.h"

namespace {

class FlatTechnique final : public tb::Technique {
 public:
  const tb::TechniqueInfo& info() const override {
    static const tb::TechniqueInfo kInfo{"example_flat", tb::TechniqueFamily::kSurface,
                                         "Flat triangles (example plug-in)", "none", "triangles"};
    return kInfo;
  }
  std::vector<tb::VariantInfo> variants() const override { return {{"default", "flat", {}}}; }
  std::string checkSupport(const tb::Mesh&) const override { return ""; }
  // A technique that throws while building: the suite records the error for its records and
  // completes the others (tests/cli/reliability_test.cpp).
  std::unique_ptr<tb::TechniqueInstance> build(const tb::TechniqueInput&,
                                               const tb::VariantInfo&) const override {
    throw std::runtime_error("example_flat: deliberately fails to build its patches");
  }
};

}  // namespace

TB_PLUGIN(host) { host.addTechnique(std::make_unique<FlatTechnique>()); }
