// Oracle: docs/FORMATS.md "What each reader refuses": every broken glTF rule is one
// InputError line naming the file, the mesh and primitive where there is one, and the rule;
// each case breaks one rule of the square that tests/mesh/gltf_test_files.h writes, which
// loads (the control).
#include <gtest/gtest.h>

#include <limits>

#include "core/mesh/gltf_loader.h"
#include "core/mesh/input_error.h"
#include "tests/mesh/gltf_test_files.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::GltfSpec;

std::string gltfSpecText(GltfSpec spec) { return testing::gltfText(spec); }

using testing::gltfErrorOf;

TEST(GltfErrors, EveryCaseIsOneLineNamingFileMeshAndPrimitive) {
  EXPECT_EQ(gltfErrorOf(gltfSpecText({})), "") << "the control loads";
  const std::vector<testing::GltfCase> cases = testing::badGltfFiles();
  EXPECT_GE(cases.size(), 8u);
  for (const testing::GltfCase& bad : cases) {
    const std::string error = gltfErrorOf(bad.text);
    EXPECT_NE(error.find("test.gltf"), std::string::npos) << bad.name;
    SCOPED_TRACE(std::string(bad.name) + ": " + error);
    ASSERT_FALSE(error.empty()) << "refused";
    EXPECT_EQ(error.find('\n'), std::string::npos) << "one line";
    for (const std::string& name : bad.names)
      EXPECT_NE(error.find(name), std::string::npos) << name;
  }
}

TEST(GltfErrors, MissingExternalBuffer) {
  const auto dir = testing::scratchDirectory("gltf_missing_buffer");
  GltfSpec spec;
  spec.edit = [](nlohmann::json& g) { g["buffers"][0]["uri"] = "lost.bin"; };
  testing::writeTextFile(dir / "lost.gltf", gltfSpecText(spec));
  try {
    mesh::loadGltfFile((dir / "lost.gltf").string());
    ADD_FAILURE() << "a missing buffer file loads";
  } catch (const mesh::InputError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("lost.gltf"), std::string::npos) << text;
    EXPECT_NE(text.find("lost.bin"), std::string::npos) << text;
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
  }
}

TEST(GltfErrors, MissingFile) {
  EXPECT_THROW(mesh::loadGltfFile("/nonexistent/x.glb"), mesh::InputError);
}

}  // namespace
}  // namespace tb
