// Production-size assets (asset_catalog.h, assets/production): bundled shapes refined at load.
// Oracles: OpenSubdiv Bfr's limit of the source mesh (a refined mesh with its tags has the same
// limit surface), the production list's own counts, and the bad-input rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/mesh/bounds.h"
#include "core/mesh/input_error.h"
#include "core/mesh/obj_loader.h"
#include "core/mesh/topology.h"
#include "core/osd/uniform_refinement.h"
#include "harness/suite/asset_catalog.h"
#include "reference/limit_surface.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// The largest distance, over the refined quads, between the refined mesh's limit at two corners
// of each child face and the source's limit at the same points: Far puts the 4 children of quad
// f at 4f + k, child k keeping the parent's corner k at its own corner k and the parent's
// centre at its corner k + 2.
double largestLimitGap(const mesh::Mesh& source, const mesh::Mesh& refined) {
  const ref::LimitSurface coarse(source, osd::Scheme::kCatmullClark);
  const ref::LimitSurface fine(refined, osd::Scheme::kCatmullClark);
  constexpr double kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  double gap = 0;
  for (size_t f = 0; f < source.faceCount(); ++f) {
    for (size_t k = 0; k < 4; ++k) {
      const size_t child = 4 * f + k;
      const ref::LimitPoint at_corner = coarse.evaluate(f, kCorner[k][0], kCorner[k][1]);
      const ref::LimitPoint at_centre = coarse.evaluate(f, 0.5, 0.5);
      const double* corner = kCorner[k];
      const double* centre = kCorner[(k + 2) % 4];
      gap = std::max(
          gap, length(fine.evaluate(child, corner[0], corner[1]).position - at_corner.position));
      gap = std::max(
          gap, length(fine.evaluate(child, centre[0], centre[1]).position - at_centre.position));
    }
  }
  return gap / mesh::diagonalOf(mesh::boundsOf(source));
}

// The pawn's 120 creases of sharpness 6 survive one refinement at sharpness 5, so the refined
// mesh has the pawn's limit surface; the same mesh with its tags dropped (the refinement as it
// was before it kept them: the broken control) rounds the creases off.
TEST(ProductionAssets, ARefinedAssetKeepsItsSourcesLimitSurface) {
  const mesh::Mesh pawn = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_pawn.obj"));
  ASSERT_TRUE(pawn.allFacesOfSize(4));
  const mesh::Mesh refined = osd::refineUniform(pawn, osd::Scheme::kCatmullClark, 1);
  ASSERT_EQ(refined.faceCount(), 4 * pawn.faceCount());
  ASSERT_EQ(refined.tags.creases.size(), 2 * pawn.tags.creases.size());
  for (const mesh::Crease& crease : refined.tags.creases) EXPECT_EQ(crease.sharpness, 5.0);
  EXPECT_LT(largestLimitGap(pawn, refined), 1e-6);
  mesh::Mesh untagged = refined;
  untagged.tags.creases.clear();
  EXPECT_GT(largestLimitGap(pawn, untagged), 1e-3);
}

TEST(ProductionAssets, EveryListedAssetLoadsAtItsStatedSize) {
  const std::vector<suite::AssetRef> assets = suite::productionAssets();
  ASSERT_EQ(assets.size(), 4u);
  for (const suite::AssetRef& asset : assets) {
    EXPECT_EQ(asset.name.rfind("production/", 0), 0u) << asset.name;
    EXPECT_EQ(suite::resolveAsset(asset.name).name, asset.name);
    EXPECT_GT(asset.refine, 0) << asset.name;
  }
  const mesh::Mesh pawn = suite::loadAsset(suite::resolveAsset("production/catmark_pawn_r2"));
  EXPECT_EQ(pawn.faceCount(), 9408u);
  EXPECT_TRUE(pawn.normals_computed);
  EXPECT_TRUE(mesh::connectivityWarnings(pawn, mesh::buildTopology(pawn)).empty());
}

// Issue 62's character-like asset (scripts/make_character_asset.py, refined twice): closed,
// 24,576 quads, every one of the cage's 764 extraordinary vertices kept (refinement adds only
// regular ones) and 3,048 of the faces (one in 8) touching one.
TEST(ProductionAssets, TheCharacterHasExtraordinaryVerticesAllOverIt) {
  const mesh::Mesh cage = suite::loadAsset(suite::resolveAsset("full_suite/character_base"));
  const mesh::Mesh figure = suite::loadAsset(suite::resolveAsset("production/character_r2"));
  ASSERT_EQ(cage.faceCount(), 1536u);
  ASSERT_EQ(figure.faceCount(), 24576u);
  const mesh::Topology topology = mesh::buildTopology(figure);
  EXPECT_TRUE(mesh::connectivityWarnings(figure, topology).empty());
  EXPECT_EQ(std::count(topology.on_boundary.begin(), topology.on_boundary.end(), 1), 0);
  const std::vector<uint32_t> extraordinary = topology.extraordinaryVertices(4);
  EXPECT_EQ(extraordinary.size(), 764u);
  std::vector<uint8_t> is_extraordinary(figure.positions.size(), 0);
  for (uint32_t v : extraordinary) is_extraordinary[v] = 1;
  size_t touching = 0;
  for (size_t f = 0; f < figure.faceCount(); ++f) {
    const auto corners = figure.facePositions(f);
    touching += std::any_of(corners.begin(), corners.end(),
                            [&](uint32_t v) { return is_extraordinary[v] != 0; });
  }
  EXPECT_EQ(touching, 3048u);
}

// Bad input: one line naming the file and the entry or option, never a crash.
TEST(ProductionAssets, BadListsFoldersAndRefineCountsAreRefusedWithOneLine) {
  const auto dir = testing::scratchDirectory("production_assets_bad");
  std::filesystem::create_directories(dir / "assets" / "production");
  std::filesystem::copy(testing::assetPath("opensubdiv/catmark_cube.obj"),
                        dir / "assets" / "catmark_cube.obj");
  auto refusal = [&](const std::string& list) {
    std::ofstream(dir / "assets" / "production" / "assets.json") << list;
    setenv("TB_ASSETS_DIR", (dir / "assets").c_str(), 1);
    std::string message;
    try {
      suite::productionAssets();
    } catch (const mesh::InputError& error) {
      message = error.what();
    }
    unsetenv("TB_ASSETS_DIR");
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  };
  EXPECT_NE(refusal("{\"assets\": [").find("not valid JSON"), std::string::npos);
  EXPECT_NE(refusal("{\"assets\": [{\"name\": \"x\", \"refine\": 1}]}").find("\"source\""),
            std::string::npos);
  EXPECT_NE(refusal("{\"assets\": [{\"name\": \"x\", \"source\": \"nope\", \"refine\": 1}]}")
                .find("assets[0].source"),
            std::string::npos);
  EXPECT_NE(
      refusal("{\"assets\": [{\"name\": \"x\", \"source\": \"catmark_cube\", \"refine\": 9}]}")
          .find("refinement steps"),
      std::string::npos);
  EXPECT_TRUE(refusal("{\"assets\": [{\"name\": \"x\", \"source\": \"catmark_cube\", "
                      "\"refine\": 1}]}")
                  .empty());
  try {
    suite::resolveAsset(dir.string());
    ADD_FAILURE() << "a folder resolved";
  } catch (const mesh::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("is a folder"), std::string::npos) << error.what();
  }
}

// A polygon soup is accepted with a warning that its errors say nothing; a welded mesh is not.
TEST(ProductionAssets, APolygonSoupIsWarnedAbout) {
  mesh::Mesh soup;
  for (uint32_t t = 0; t < 4; ++t) {
    const double x = t;
    soup.positions.insert(soup.positions.end(), {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}});
    const uint32_t corners[3] = {3 * t, 3 * t + 1, 3 * t + 2};
    soup.addFace(corners, {}, {}, 0);
  }
  const std::vector<std::string> warnings =
      mesh::connectivityWarnings(soup, mesh::buildTopology(soup));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("polygon soup"), std::string::npos);
  EXPECT_NE(warnings[0].find("positions repeat"), std::string::npos);  // (1,0,0) and (1,0,0)...
  const mesh::Mesh cube = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj"));
  EXPECT_TRUE(mesh::connectivityWarnings(cube, mesh::buildTopology(cube)).empty());
}

}  // namespace
}  // namespace tb
