#include "techniques/registry.h"

#include <gtest/gtest.h>

#include "tests/test_paths.h"

namespace tb {
namespace {

TEST(Registry, PhongRegistersItselfWithCompleteInfo) {
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  ASSERT_NE(phong, nullptr);
  EXPECT_EQ(phong->info().family, techniques::TechniqueFamily::kSurface);
  EXPECT_FALSE(phong->info().title.empty());
  EXPECT_NE(phong->info().citation.find("Boubekeur"), std::string::npos);
  EXPECT_EQ(phong->variants().size(), 5u);  // four α values and `edge`
  EXPECT_EQ(techniques::TechniqueRegistry::instance().find("no_such_technique"), nullptr);
}

TEST(Registry, ListingIsSortedAndDuplicatesAreRefused) {
  const auto all = techniques::TechniqueRegistry::instance().all();
  for (size_t i = 1; i < all.size(); ++i) EXPECT_LT(all[i - 1]->info().id, all[i]->info().id);
  class Dummy final : public techniques::Technique {
   public:
    const techniques::TechniqueInfo& info() const override {
      static const techniques::TechniqueInfo kInfo{"phong", techniques::TechniqueFamily::kSurface,
                                                   "", "", ""};
      return kInfo;
    }
    std::vector<techniques::VariantInfo> variants() const override { return {}; }
    std::string checkSupport(const mesh::Mesh&) const override { return {}; }
    std::unique_ptr<techniques::TechniqueInstance> build(
        const techniques::TechniqueInput&, const techniques::VariantInfo&) const override {
      return nullptr;
    }
  };
  EXPECT_FALSE(techniques::TechniqueRegistry::instance().add(std::make_unique<Dummy>()));
}

TEST(Registry, LoadsAnOutOfTreePlugin) {
  ASSERT_EQ(techniques::TechniqueRegistry::instance().find("example_flat"), nullptr);
  techniques::loadPlugin(TB_EXAMPLE_PLUGIN);
  const techniques::Technique* flat =
      techniques::TechniqueRegistry::instance().find("example_flat");
  ASSERT_NE(flat, nullptr);
  EXPECT_EQ(flat->info().title, "Flat triangles (example plug-in)");
}

std::vector<std::string> registeredIds() {
  std::vector<std::string> ids;
  for (const techniques::Technique* technique : techniques::TechniqueRegistry::instance().all()) {
    ids.push_back(technique->info().id);
  }
  return ids;
}

std::string loadError(const std::string& path) {
  try {
    techniques::loadPlugin(path);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

// The handshake comes first: a plug-in of another ABI is refused in one line naming the
// file and both numbers, its registration entry (which aborts) is never called, and the
// registry is unchanged.
TEST(Registry, APluginOfAnotherAbiIsRefusedBeforeItRegisters) {
  const std::vector<std::string> before = registeredIds();
  const std::string error = loadError(TB_WRONG_ABI_PLUGIN);
  EXPECT_EQ(error.rfind(std::string(TB_WRONG_ABI_PLUGIN) + ": plug-in ABI " +
                            std::to_string(kTessbenchPluginAbi + 1) + ", this tessbench's ABI " +
                            std::to_string(kTessbenchPluginAbi),
                        0),
            0u)
      << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  EXPECT_EQ(registeredIds(), before);
}

// A shared library that is no plug-in (the C maths library) is one line, nothing registered.
TEST(Registry, ALibraryWithoutTheEntryPointsIsNotAPlugin) {
  const std::vector<std::string> before = registeredIds();
  const std::string error = loadError("libm.so.6");
  EXPECT_EQ(error.rfind("libm.so.6: not a tessbench plug-in: no tessbench_plugin_abi", 0), 0u)
      << error;
  EXPECT_EQ(registeredIds(), before);
}

// Loading the same plug-in twice: the second finds its id taken and adds nothing.
TEST(Registry, APluginWhoseIdIsTakenAddsNothing) {
  if (techniques::TechniqueRegistry::instance().find("example_flat") == nullptr)
    techniques::loadPlugin(TB_EXAMPLE_PLUGIN);
  const std::vector<std::string> before = registeredIds();
  const std::string error = loadError(TB_EXAMPLE_PLUGIN);
  EXPECT_NE(error.find("technique id 'example_flat' is already registered; nothing was registered"),
            std::string::npos)
      << error;
  EXPECT_EQ(registeredIds(), before);
}

TEST(Registry, BadPluginPathNamesTheFile) {
  try {
    techniques::loadPlugin("/nonexistent/plugin.so");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()).rfind("/nonexistent/plugin.so: ", 0), 0u) << error.what();
  }
}

}  // namespace
}  // namespace tb
