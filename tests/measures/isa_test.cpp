// The ISA measure against the GPU compilers themselves (RADV's null device): the executables
// follow the hardware's stage merging, and controls made to cost more (a patch evaluated
// twice, many values live at once) cost more in the compiler's own statistics on every
// family. Without the radeon ICD the measure's rows are skipped with the reason.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "harness/measures/common/isa/isa_compilers.h"
#include "harness/measures/isa/isa_pipelines.h"
#include "harness/measures/isa/isa_statistics.h"
#include "harness/measures/measure.h"
#include "harness/results/shader_db.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using measures::isa::CompileOutcome;
using measures::isa::PipelineRequest;

// Skips the test (with the reason) where this machine has no radeon ICD or worker.
#define TB_REQUIRE_RADEON()                                                                        \
  do {                                                                                             \
    std::string why;                                                                               \
    if (measures::isa::radeonIcd(&why).empty() || measures::isa::workerExecutable(&why).empty()) { \
      GTEST_SKIP() << why;                                                                         \
    }                                                                                              \
  } while (false)

// shaders/gpu/test_isa_controls.tese in build `mode` (0 the twin, 1 twice the evaluation,
// 2 many live values) behind test_bilinear.tesc.
PipelineRequest controlRequest(uint32_t mode) {
  PipelineRequest r;
  r.program.control_shader = "gpu/test_bilinear.tesc";
  r.program.evaluation_shader = "gpu/test_isa_controls.tese";
  r.program.domain = tess::Domain::kQuad;
  r.program.storage_buffers.resize(1);
  r.program.specialization = {mode};
  return r;
}

CompileOutcome compiled(std::string_view family, const PipelineRequest& request) {
  const measures::isa::FamilyCompile result = measures::isa::compileOn(family, request);
  EXPECT_NE(result.outcome, nullptr) << family << ": " << result.unavailable;
  if (!result.outcome) return {};
  EXPECT_EQ(result.outcome->error, "") << family;
  return *result.outcome;
}

// The executable that runs `stage`; a failure and null when none does.
const gpu::PipelineExecutable* running(const CompileOutcome& outcome, VkShaderStageFlags stage) {
  for (const gpu::PipelineExecutable& e : outcome.executables) {
    if (e.stages & stage) return &e;
  }
  ADD_FAILURE() << "no executable runs stage " << stage;
  return nullptr;
}

double statistic(const gpu::PipelineExecutable& e, std::string_view name) {
  for (const gpu::ExecutableStatistic& s : e.statistics) {
    if (s.name == name) return s.value;
  }
  ADD_FAILURE() << e.name << " has no statistic " << name;
  return 0;
}

// acc's default program on the bundled cube, as the suite builds it.
std::vector<measures::isa::NamedPipeline> accPipelines() {
  const techniques::Technique& acc = testing::technique("acc");
  const mesh::Mesh cube = testing::loadAsset("opensubdiv/catmark_cube.obj");
  const auto instance = acc.build({&cube, nullptr}, acc.variants().front());
  return measures::isa::surfacePipelines(*instance->surface(), false);
}

TEST(Isa, PolarisRunsTheHullStagesApartAndNavi21MergesThem) {
  TB_REQUIRE_RADEON();
  const std::vector<measures::isa::NamedPipeline> pipelines = accPipelines();
  ASSERT_FALSE(pipelines.empty());
  ASSERT_EQ(pipelines.front().pipeline, "tessellator");
  const PipelineRequest& request = pipelines.front().request;
  const CompileOutcome polaris = compiled("polaris10", request);
  const CompileOutcome navi = compiled("navi21", request);
  const gpu::PipelineExecutable* polaris_vs = running(polaris, VK_SHADER_STAGE_VERTEX_BIT);
  const gpu::PipelineExecutable* navi_vs = running(navi, VK_SHADER_STAGE_VERTEX_BIT);
  ASSERT_TRUE(polaris_vs && navi_vs);
  EXPECT_EQ(polaris_vs->stages, VkShaderStageFlags(VK_SHADER_STAGE_VERTEX_BIT)) << polaris_vs->name;
  EXPECT_EQ(navi_vs->stages, VkShaderStageFlags(VK_SHADER_STAGE_VERTEX_BIT |
                                                VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT))
      << navi_vs->name;
  EXPECT_EQ(polaris.executables.size(), navi.executables.size() + 1);
  // The control: the merge is the hardware's, so vega10 (GFX9) already merges.
  const CompileOutcome vega = compiled("vega10", request);
  EXPECT_EQ(vega.executables.size(), navi.executables.size());
}

TEST(Isa, TwiceTheEvaluationCostsMoreInstructionsAndLatencyOnEveryFamily) {
  TB_REQUIRE_RADEON();
  for (const measures::isa::Family& family : measures::isa::defaultFamilies()) {
    const CompileOutcome twin = compiled(family.name, controlRequest(0));
    const CompileOutcome twice = compiled(family.name, controlRequest(1));
    const auto* a = running(twin, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT);
    const auto* b = running(twice, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT);
    ASSERT_TRUE(a && b) << family.name;
    EXPECT_GT(statistic(*b, "Instructions"), statistic(*a, "Instructions")) << family.name;
    EXPECT_GT(statistic(*b, "Latency"), statistic(*a, "Latency")) << family.name;
  }
}

TEST(Isa, ManyLiveValuesTakeMoreVgprsAndNoMoreSubgroupsOnEveryFamily) {
  TB_REQUIRE_RADEON();
  for (const measures::isa::Family& family : measures::isa::defaultFamilies()) {
    const CompileOutcome twin = compiled(family.name, controlRequest(0));
    const CompileOutcome live = compiled(family.name, controlRequest(2));
    const auto* a = running(twin, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT);
    const auto* b = running(live, VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT);
    ASSERT_TRUE(a && b) << family.name;
    EXPECT_GT(statistic(*b, "VGPRs"), statistic(*a, "VGPRs")) << family.name;
    EXPECT_LE(statistic(*b, "Subgroups per SIMD"), statistic(*a, "Subgroups per SIMD"))
        << family.name;
  }
}

results::MeasureResult runIsa(const std::string& technique_id) {
  const techniques::Technique& technique = testing::technique(technique_id);
  const mesh::Mesh cube = testing::loadAsset("opensubdiv/catmark_cube.obj");
  const techniques::VariantInfo variant = technique.variants().front();
  const auto instance = technique.build({&cube, nullptr}, variant);
  const measures::Measure* measure = measures::MeasureRegistry::instance().find("isa");
  EXPECT_NE(measure, nullptr);
  const measures::MeasureInput input{technique,           variant, "opensubdiv/catmark_cube", cube,
                                     instance->surface(), nullptr, "no device in this test"};
  return measure->run(input);
}

TEST(Isa, EveryFamilyHasTheRegisterAndOccupancyFiguresOfEveryExecutable) {
  TB_REQUIRE_RADEON();
  const results::MeasureResult result = runIsa("acc");
  std::map<std::string, int> executables_by_family;
  for (const results::MetricRow& row : result.rows) {
    if (row.keys.at("family") == "device") {
      EXPECT_EQ(row.status, results::MeasureStatus::kSkipped);  // no device here
      continue;
    }
    ASSERT_EQ(row.status, results::MeasureStatus::kOk) << row.reason;
    EXPECT_TRUE(row.keys.at("driver").starts_with("radv")) << row.keys.at("driver");
    std::set<std::string> names;
    for (const results::Metric& m : row.metrics) names.insert(m.name);
    for (const char* wanted : {"instructions", "vgprs", "sgprs", "spilled_vgprs", "spilled_sgprs",
                               "subgroups_per_simd", "latency", "inverse_throughput"}) {
      EXPECT_TRUE(names.count(wanted)) << row.keys.at("family") << " " << wanted;
    }
    if (row.keys.at("pipeline") == "tessellator") ++executables_by_family[row.keys.at("family")];
  }
  for (const measures::isa::Family& family : measures::isa::defaultFamilies()) {
    EXPECT_GE(executables_by_family[std::string(family.name)], 2) << family.name;
  }
}

// Sets an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_) {
      setenv(name_, old_->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(Isa, WithOnlyLavapipeNamedEveryRowIsSkippedWithTheReason) {
  const ScopedEnv only_lavapipe("VK_ICD_FILENAMES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json");
  const results::MeasureResult result = runIsa("pn_triangles");
  ASSERT_FALSE(result.rows.empty());
  for (const results::MetricRow& row : result.rows) {
    EXPECT_EQ(row.status, results::MeasureStatus::kSkipped);
    if (row.keys.at("family") != "device") {
      EXPECT_NE(row.reason.find("names no radeon ICD"), std::string::npos) << row.reason;
    }
  }
}

}  // namespace
}  // namespace tb

namespace tb {
namespace {

// A run whose only record holds the ISA rows of `request` compiled on navi21.
results::Results runOf(const PipelineRequest& request) {
  results::Results run;
  run.measures.push_back(
      measures::declarationOf(measures::MeasureRegistry::instance().find("isa")->info()));
  results::Record& record = run.records.emplace_back();
  record.technique = "acc";
  record.variant = "default";
  record.asset = "opensubdiv/catmark_cube";
  results::MeasureResult& result = record.measures.emplace_back();
  result.measure = "isa";
  const measures::isa::FamilyCompile compiled = measures::isa::compileOn("navi21", request);
  EXPECT_NE(compiled.outcome, nullptr) << compiled.unavailable;
  if (!compiled.outcome) return run;
  for (const gpu::PipelineExecutable& e : compiled.outcome->executables) {
    const std::map<std::string, std::string> keys{
        {"pipeline", "tessellator"}, {"family", "navi21"}, {"driver", compiled.driver}};
    for (results::MetricRow& row : measures::isa::executableRows(keys, e, std::nullopt)) {
      result.rows.push_back(std::move(row));
    }
  }
  return run;
}

TEST(Isa, ShaderDbSummaryNamesTheChangedShaderAmongTheHurtAndAnUnchangedPairAffectsNone) {
  TB_REQUIRE_RADEON();
  const results::Results base = runOf(controlRequest(0));
  const results::Results changed = runOf(controlRequest(1));  // the TES evaluates twice
  const std::string summary = results::renderShaderDb(results::shaderDbSummaries(base, changed));
  EXPECT_NE(summary.find("total instructions in shared programs: "), std::string::npos) << summary;
  EXPECT_NE(summary.find("1 affected programs"), std::string::npos) << summary;
  EXPECT_NE(summary.find("HURT: 1"), std::string::npos) << summary;
  EXPECT_NE(summary.find("HURT acc/default opensubdiv/catmark_cube executable=Tessellation "
                         "Evaluation Shader"),
            std::string::npos)
      << summary;
  // The control: the run against itself.
  const std::string same = results::renderShaderDb(results::shaderDbSummaries(base, base));
  EXPECT_NE(same.find(", 0 affected programs"), std::string::npos) << same;
  EXPECT_EQ(same.find("HURT acc"), std::string::npos) << same;
}

}  // namespace
}  // namespace tb
