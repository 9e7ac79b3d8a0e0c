// The crack sample (cracks.h, kCrackPatchBudget): on an asset of more than the budget the
// pair figures cover every feature patch and evenly spaced runs of the others. Oracle: the
// same session without a sample (every pair). On every bundled asset each technique accepts,
// at a budget of 64 patches, the sampled figures count a subset of the full pairs (never
// more unequal points, never a larger gap) and give the same verdict, cracked or watertight,
// for variants that crack and variants that do not. Control: the sample without its feature
// patches (runs only) calls a cracked variant watertight on some asset.
#include <gtest/gtest.h>

#include <cstdio>

#include "core/mesh/obj_loader.h"
#include "harness/measures/common/cracks/cracks.h"
#include "harness/suite/asset_catalog.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/measures/bundled_surfaces.h"

namespace tb {
namespace {

constexpr size_t kSampleBudget = 64;

struct SampleCase {
  const char* technique;
  const char* variant;
};
// Cracking variants (controls and default variants that crack) and watertight ones.
constexpr SampleCase kSampleCases[] = {{"acc", "asymmetric"},
                                       {"acc", "default"},
                                       {"gregory_acc", "asymmetric"},
                                       {"gregory_acc", "edge_symmetric"},
                                       {"osd_adaptive", "iso2_gregory"},
                                       {"phong", "alpha0.75"},
                                       {"pn_triangles", "pn"}};

struct SampleTally {
  size_t sampled_assets = 0, cracked = 0, control_missed = 0;
};

void compareSampleOnAsset(const SampleCase& c, const std::string& asset,
                          const techniques::SurfacePatches& patches, SampleTally* tally) {
  measures::CrackSession full(patches, SIZE_MAX);
  measures::CrackSession sampled(patches, kSampleBudget);
  measures::CrackSession runs_only(patches, kSampleBudget, false);
  ASSERT_EQ(full.sampledPatches(), patches.patchCount());
  if (sampled.sampledPatches() == patches.patchCount()) return;  // features cover it all
  ++tally->sampled_assets;
  for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd}) {
    const auto f = full.measure(spacing, 7.3f, measures::CrackBackend::kCpuFloat);
    const auto s = sampled.measure(spacing, 7.3f, measures::CrackBackend::kCpuFloat);
    const auto r = runs_only.measure(spacing, 7.3f, measures::CrackBackend::kCpuFloat);
    const std::string where = std::string(c.technique) + "/" + c.variant + " " + asset;
    ASSERT_TRUE(f.measured && s.measured && r.measured) << where;
    EXPECT_EQ(s.patches_compared, sampled.sampledPatches());
    EXPECT_LT(s.points_compared, f.points_compared) << where;
    EXPECT_LE(s.points_not_equal, f.points_not_equal) << where;
    EXPECT_LE(s.max_gap_world, f.max_gap_world) << where;
    EXPECT_EQ(s.points_not_equal > 0, f.points_not_equal > 0)
        << where << ": the sample's verdict differs (" << s.points_not_equal << " of "
        << f.points_not_equal << " unequal points)";
    EXPECT_EQ(s.unpaired_points, 0u) << where;
    tally->cracked += f.points_not_equal > 0;
    tally->control_missed += f.points_not_equal > 0 && r.points_not_equal == 0;
  }
}

TEST(CrackSample, SampledVerdictEqualsTheFullOneOnEveryBundledAsset) {
  SampleTally tally;
  for (const SampleCase& c : kSampleCases) {
    testing::forEachBundledSurface(
        c.technique, c.variant,
        [&](const std::string& asset, const techniques::SurfacePatches& patches) {
          if (patches.patchCount() > kSampleBudget) compareSampleOnAsset(c, asset, patches, &tally);
        });
  }
  std::printf(
      "crack sample: %zu sampled (technique, asset) cases, %zu cracked rows, the control "
      "missed %zu\n",
      tally.sampled_assets, tally.cracked, tally.control_missed);
  EXPECT_GT(tally.sampled_assets, 20u);
  EXPECT_GT(tally.cracked, 10u) << "the cases include variants that crack";
  EXPECT_GT(tally.control_missed, 0u) << "without its feature patches the sample misses cracks";
}

// The device path draws only the sample (zero levels elsewhere, not drawn) and captures every
// sampled boundary point: a watertight variant's device figures equal the CPU float model's.
TEST(CrackSample, TheDeviceCapturesTheSampleAlone) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::Technique* acc = techniques::TechniqueRegistry::instance().find("acc");
  const mesh::Mesh mesh = mesh::loadObjFile(suite::resolveAsset("catmark_pawn").path);
  const auto patches = techniques::buildSurface(*acc, mesh, testing::variantNamed(*acc, "default"));
  ASSERT_GT(patches->patchCount(), kSampleBudget);
  measures::CrackSession sampled(*patches, kSampleBudget);
  ASSERT_LT(sampled.sampledPatches(), patches->patchCount());
  const auto cpu =
      sampled.measure(tess::Spacing::kFractionalOdd, 7.3f, measures::CrackBackend::kCpuFloat);
  const auto gpu =
      sampled.measure(tess::Spacing::kFractionalOdd, 7.3f, measures::CrackBackend::kGpu, &context);
  ASSERT_TRUE(gpu.measured) << gpu.skipped_reason;
  EXPECT_EQ(gpu.points_compared, cpu.points_compared);
  EXPECT_EQ(gpu.points_not_equal, 0u);
  EXPECT_GT(gpu.device_points, 0u);
  EXPECT_EQ(gpu.device_points_differing, 0u);
  EXPECT_LE(gpu.draws, 2 * sampled.sampledPatches());
}

}  // namespace
}  // namespace tb
