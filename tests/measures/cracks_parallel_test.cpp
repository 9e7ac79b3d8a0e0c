// The crack measure evaluates and pairs in parallel (TBB); its rows must not depend on the
// thread count. Oracle: the same measure run with TBB limited to one thread, every row's
// keys and metric values compared bit for bit. The asset has more shared edges and
// corners than one pairing block (256), so the blocks' reduction order is exercised;
// with a Vulkan device the GPU rows (device capture) are compared too.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "harness/measures/common/cracks/cracks.h"
#include "harness/measures/measure.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

results::MeasureResult runCracks(const techniques::Technique& technique,
                                 const techniques::VariantInfo& variant, const std::string& asset,
                                 const mesh::Mesh& mesh, const techniques::SurfacePatches& patches,
                                 gpu::Context* context) {
  const measures::Measure* measure = measures::MeasureRegistry::instance().find("cracks");
  EXPECT_NE(measure, nullptr);
  const measures::MeasureInput input{technique,
                                     variant,
                                     asset,
                                     mesh,
                                     &patches,
                                     context,
                                     context == nullptr ? "no Vulkan device in this test" : "",
                                     nullptr,
                                     nullptr};
  return measure->run(input);
}

results::MeasureResult runCracks(const techniques::Technique& technique,
                                 const techniques::VariantInfo& variant, const std::string& asset,
                                 const mesh::Mesh& mesh, const techniques::SurfacePatches& patches,
                                 gpu::Context* context, size_t threads) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  return runCracks(technique, variant, asset, mesh, patches, context);
}

techniques::VariantInfo findVariant(const techniques::Technique& technique,
                                    const std::string& name) {
  for (const techniques::VariantInfo& v : technique.variants()) {
    if (v.name == name) return v;
  }
  throw std::runtime_error("no variant " + name);
}

void expectSameRows(const results::MeasureResult& a, const results::MeasureResult& b,
                    const std::string& what) {
  ASSERT_EQ(a.rows.size(), b.rows.size()) << what;
  for (size_t r = 0; r < a.rows.size(); ++r) {
    const results::MetricRow& x = a.rows[r];
    const results::MetricRow& y = b.rows[r];
    ASSERT_EQ(x.keys, y.keys) << what << " row " << r;
    ASSERT_EQ(x.metrics.size(), y.metrics.size()) << what << " row " << r;
    for (size_t m = 0; m < x.metrics.size(); ++m) {
      EXPECT_EQ(x.metrics[m].name, y.metrics[m].name);
      EXPECT_EQ(std::memcmp(&x.metrics[m].value, &y.metrics[m].value, sizeof(double)), 0)
          << what << " row " << r << " " << x.metrics[m].name << ": " << x.metrics[m].value
          << " vs " << y.metrics[m].value;
    }
  }
}

TEST(CracksParallel, RowsDoNotDependOnTheThreadCount) {
  std::string reason;
  gpu::Context* context = gpu::testing::sharedContext(&reason);
  const std::string asset = "tessbench/tri_pawn.obj";
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(asset));
  // gregory_acc's asymmetric variant opens gaps, so the sums and maxima are not all 0.
  for (const auto& [id, variant_name] :
       {std::pair{"gregory_acc", "asymmetric"}, std::pair{"pn_triangles", "pn"}}) {
    const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find(id);
    ASSERT_NE(technique, nullptr);
    const techniques::VariantInfo variant = findVariant(*technique, variant_name);
    const techniques::BuiltSurface patches = techniques::buildSurface(*technique, mesh, variant);
    ASSERT_GT(measures::findSharedBoundaries(*patches).edges.size(), 256u);
    const results::MeasureResult one =
        runCracks(*technique, variant, asset, mesh, *patches, context, 1);
    ASSERT_FALSE(one.rows.empty());
    if (std::string(id) == "gregory_acc") {
      double max_gap = 0;
      for (const results::MetricRow& row : one.rows) {
        for (const results::Metric& m : row.metrics) {
          if (m.name == "max_gap_world") max_gap = std::max(max_gap, m.value);
        }
      }
      EXPECT_GT(max_gap, 0.0);
    }
    for (size_t threads : {2, 4}) {
      const results::MeasureResult many =
          runCracks(*technique, variant, asset, mesh, *patches, context, threads);
      expectSameRows(one, many, std::string(id) + " with " + std::to_string(threads) + " threads");
    }
  }
}

// Two records at once on one shared Context (as the suite runs them on two threads) give
// the rows each gives alone.
TEST(CracksParallel, TwoRecordsAtOnceOnOneContextMatchTheirSerialRuns) {
  std::string reason;
  gpu::Context* context = gpu::testing::sharedContext(&reason);
  if (context == nullptr) GTEST_SKIP() << "no usable Vulkan device: " << reason;
  const std::string asset = "tessbench/tri_pawn.obj";
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(asset));
  const techniques::Technique* gregory =
      techniques::TechniqueRegistry::instance().find("gregory_acc");
  const techniques::Technique* pn = techniques::TechniqueRegistry::instance().find("pn_triangles");
  ASSERT_TRUE(gregory != nullptr && pn != nullptr);
  const techniques::VariantInfo gregory_variant = findVariant(*gregory, "asymmetric");
  const techniques::VariantInfo pn_variant = findVariant(*pn, "pn");
  const techniques::BuiltSurface a = techniques::buildSurface(*gregory, mesh, gregory_variant);
  const techniques::BuiltSurface b = techniques::buildSurface(*pn, mesh, pn_variant);
  const results::MeasureResult serial_a =
      runCracks(*gregory, gregory_variant, asset, mesh, *a, context);
  const results::MeasureResult serial_b = runCracks(*pn, pn_variant, asset, mesh, *b, context);
  results::MeasureResult concurrent_a, concurrent_b;
  std::thread first(
      [&] { concurrent_a = runCracks(*gregory, gregory_variant, asset, mesh, *a, context); });
  std::thread second([&] { concurrent_b = runCracks(*pn, pn_variant, asset, mesh, *b, context); });
  first.join();
  second.join();
  expectSameRows(serial_a, concurrent_a, "gregory_acc beside pn_triangles");
  expectSameRows(serial_b, concurrent_b, "pn_triangles beside gregory_acc");
}

}  // namespace
}  // namespace tb
