// Oracle: the run's own records. A picture pair exists exactly for each technique × asset
// with a record of the technique's default variant whose `error` result is ok; every file
// the index names is written, decodes with libpng to the index's size, and comes out the
// same byte for byte on a second run. Without a device only a "skipped" index is written.
#include "harness/pictures/run_pictures.h"

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "harness/measures/measure.h"
#include "harness/suite/suite.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"

namespace tb {
namespace {

using Files = std::map<std::string, std::string>;

pictures::WriteFileFn collectInto(Files* files) {
  return [files](const std::string& path, const std::string& bytes) {
    EXPECT_TRUE(files->emplace(path, bytes).second) << path << " written twice";
  };
}

// A small run: the error measure of acc and pn_triangles (every variant) on a quad torus
// and a triangle cube (acc skips the cube).
const results::Results& smallRun() {
  static const results::Results results = [] {
    suite::SuiteSelection selection;
    selection.techniques = {techniques::TechniqueRegistry::instance().find("acc"),
                            techniques::TechniqueRegistry::instance().find("pn_triangles")};
    selection.assets = {suite::resolveAsset("opensubdiv/catmark_torus"),
                        suite::resolveAsset("opensubdiv/loop_cube")};
    selection.measures = {measures::MeasureRegistry::instance().find("error")};
    results::Results r;
    suite::runSuite(selection, {}, &r);
    return r;
  }();
  return results;
}

TEST(RunPictures, FileNamesFollowTechniqueAndAsset) {
  EXPECT_EQ(pictures::errorPicturePath("acc", "opensubdiv/catmark_torus"),
            "pictures/acc--opensubdiv--catmark_torus--error.png");
  EXPECT_EQ(pictures::wireframePicturePath("pn_triangles", "my dir/x+y.obj"),
            "pictures/pn_triangles--my_dir--x_y.obj--wireframe.png");
}

TEST(RunPictures, WithoutADeviceTheIndexSaysSkipped) {
  Files files;
  const pictures::PicturesIndex index =
      pictures::renderRunPictures(smallRun(), nullptr, "no ICD found", collectInto(&files));
  EXPECT_EQ(index.status, "skipped");
  EXPECT_NE(index.reason.find("no ICD found"), std::string::npos);
  EXPECT_TRUE(index.pictures.empty());
  ASSERT_EQ(files.size(), 1u);
  // One colour scale per asset: the largest error of its pictures (acc's torus is exact at its
  // vertices, pn's is not: an own scale per picture would differ).
  std::map<std::string, double> largest;
  for (const pictures::PictureEntry& entry : index.pictures) {
    largest[entry.asset] =
        std::max({largest[entry.asset], entry.error_max, pictures::kMinimumScaleMax});
  }
  for (const pictures::PictureEntry& entry : index.pictures) {
    EXPECT_EQ(entry.scale_max, largest.at(entry.asset)) << entry.technique << " " << entry.asset;
  }
  const auto json = nlohmann::json::parse(files.at(pictures::kPicturesIndexPath));
  EXPECT_EQ(json.at("status"), "skipped");
  EXPECT_TRUE(json.at("pictures").empty());
  // A device name that matches no device is the same skip, never a crash.
  Files by_name;
  const pictures::PicturesIndex unnamed =
      pictures::renderRunPictures(smallRun(), "no-such-device-7f3a", collectInto(&by_name));
  EXPECT_EQ(unnamed.status, "skipped");
  EXPECT_EQ(by_name.size(), 1u);
}

TEST(RunPictures, OnePairPerDefaultVariantRecordWithAnErrorResult) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const results::Results& results = smallRun();
  // Expected from the records themselves.
  std::vector<std::pair<std::string, std::string>> expected;
  for (const results::Record& record : results.records) {
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(record.technique);
    if (record.variant != technique->variants().front().name) continue;
    for (const results::MeasureResult& m : record.measures) {
      if (m.measure == "error" && m.status == results::MeasureStatus::kOk) {
        expected.push_back({record.technique, record.asset});
      }
    }
  }
  ASSERT_GE(expected.size(), 3u);  // acc torus, pn torus, pn cube
  Files files;
  const pictures::PicturesIndex index =
      pictures::renderRunPictures(results, &context, "", collectInto(&files));
  EXPECT_EQ(index.status, "ok");
  ASSERT_EQ(index.pictures.size(), expected.size());
  EXPECT_EQ(files.size(), 2 * expected.size() + 1);
  for (size_t i = 0; i < expected.size(); ++i) {
    const pictures::PictureEntry& entry = index.pictures[i];
    EXPECT_EQ(entry.status, "ok") << entry.reason;
    EXPECT_EQ(entry.technique, expected[i].first);
    EXPECT_EQ(entry.asset, expected[i].second);
    EXPECT_EQ(entry.level, 8);
    EXPECT_EQ(entry.error_statistic, "max_of_3_vertices");
    EXPECT_EQ(entry.scale_min, 0);
    EXPECT_GE(entry.scale_max, entry.error_max);
    for (const std::string& path : {entry.error_png, entry.wireframe_png}) {
      ASSERT_TRUE(files.count(path)) << path;
      png_image image{};
      image.version = PNG_IMAGE_VERSION;
      const std::string& bytes = files.at(path);
      ASSERT_TRUE(png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()));
      EXPECT_EQ(image.width, entry.width_px);
      EXPECT_EQ(image.height, entry.height_px);
      png_image_free(&image);
    }
  }
  const auto json = nlohmann::json::parse(files.at(pictures::kPicturesIndexPath));
  EXPECT_EQ(json.at("status"), "ok");
  ASSERT_EQ(json.at("pictures").size(), expected.size());
  EXPECT_EQ(json.at("pictures")[0].at("error_png"), index.pictures[0].error_png);
  EXPECT_EQ(json.at("pictures")[0].at("scale_max").get<double>(), index.pictures[0].scale_max);

  // The same run again: the same bytes.
  Files again;
  pictures::renderRunPictures(results, &context, "", collectInto(&again));
  EXPECT_EQ(again, files);
}

TEST(RunPictures, NoPictureWithoutAnOkErrorResult) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  results::Results results = smallRun();
  size_t before = 0;
  {
    Files files;
    before =
        pictures::renderRunPictures(results, &context, "", collectInto(&files)).pictures.size();
  }
  ASSERT_GT(before, 0u);
  // The first picture's record loses its error result's ok status.
  const std::string technique = results.records.front().technique;
  const std::string asset = results.records.front().asset;
  for (results::MeasureResult& m : results.records.front().measures) {
    if (m.measure == "error") m.status = results::MeasureStatus::kSkipped;
  }
  Files files;
  const pictures::PicturesIndex index =
      pictures::renderRunPictures(results, &context, "", collectInto(&files));
  EXPECT_EQ(index.pictures.size(), before - 1);
  for (const pictures::PictureEntry& entry : index.pictures) {
    EXPECT_FALSE(entry.technique == technique && entry.asset == asset);
  }
}

}  // namespace
}  // namespace tb
