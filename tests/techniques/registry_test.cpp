#include <gtest/gtest.h>

#include "techniques/registry.h"

namespace tb {
namespace {

TEST(Registry, PhongRegistersItselfWithCompleteInfo) {
  const Technique* phong = TechniqueRegistry::instance().find("phong");
  ASSERT_NE(phong, nullptr);
  EXPECT_EQ(phong->info().family, TechniqueFamily::kSurface);
  EXPECT_FALSE(phong->info().title.empty());
  EXPECT_NE(phong->info().citation.find("Boubekeur"), std::string::npos);
  EXPECT_EQ(phong->variants().size(), 5u);  // four α values and `edge`
  EXPECT_EQ(TechniqueRegistry::instance().find("no_such_technique"), nullptr);
}

TEST(Registry, ListingIsSortedAndDuplicatesAreRefused) {
  const auto all = TechniqueRegistry::instance().all();
  for (size_t i = 1; i < all.size(); ++i) EXPECT_LT(all[i - 1]->info().id, all[i]->info().id);
  class Dummy final : public Technique {
   public:
    const TechniqueInfo& info() const override {
      static const TechniqueInfo kInfo{"phong", TechniqueFamily::kSurface, "", "", ""};
      return kInfo;
    }
    std::vector<VariantInfo> variants() const override { return {}; }
    std::string checkSupport(const Mesh&) const override { return {}; }
    std::unique_ptr<TechniqueInstance> build(const TechniqueInput&,
                                             const VariantInfo&) const override {
      return nullptr;
    }
  };
  EXPECT_FALSE(TechniqueRegistry::instance().add(std::make_unique<Dummy>()));
}

TEST(Registry, LoadsAnOutOfTreePlugin) {
  ASSERT_EQ(TechniqueRegistry::instance().find("example_flat"), nullptr);
  loadPlugin(TB_EXAMPLE_PLUGIN);
  const Technique* flat = TechniqueRegistry::instance().find("example_flat");
  ASSERT_NE(flat, nullptr);
  EXPECT_EQ(flat->info().title, "Flat triangles (example plug-in)");
}

TEST(Registry, BadPluginPathNamesTheFile) {
  try {
    loadPlugin("/nonexistent/plugin.so");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()).rfind("/nonexistent/plugin.so: ", 0), 0u) << error.what();
  }
}

}  // namespace
}  // namespace tb
