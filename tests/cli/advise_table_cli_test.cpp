// End-to-end tests of `tessbench advise` and `tessbench table`: the oracle for advise is the
// ranking rule and the constraints applied to the figures the JSON output reports; for table,
// the structure of each format.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::lineCount;
using testing::runTessbenchSplit;
using testing::SplitResult;

struct Bounds {
  double max_error = 0.02;
  double max_memory_ratio = 0.5;
  double max_instructions = 600;
};

std::string boundArguments(const Bounds& b) {
  return " --watertight --max-error " + std::to_string(b.max_error) + " --max-memory-ratio " +
         std::to_string(b.max_memory_ratio) + " --max-instructions " +
         std::to_string(b.max_instructions);
}

double figure(const nlohmann::json& value) {
  return value.is_null() ? std::numeric_limits<double>::infinity() : value.get<double>();
}

// The first choice meets every bound; passing candidates precede excluded ones; within each
// group the order is error, instructions, memory ratio, then name; every excluded candidate
// says why.
void expectRankedByTheRule(const nlohmann::json& advice, const Bounds& b) {
  const auto& candidates = advice["candidates"];
  ASSERT_FALSE(candidates.empty());
  const auto& first = candidates[0];
  ASSERT_TRUE(first["passes"].get<bool>()) << first.dump();
  EXPECT_LE(figure(first["error"]), b.max_error);
  EXPECT_LE(figure(first["memory_ratio"]), b.max_memory_ratio);
  EXPECT_LE(figure(first["instructions"]), b.max_instructions);
  EXPECT_EQ(first["watertight"], "yes");
  EXPECT_EQ(first["verdict"].get<std::string>().rfind("wins:", 0), 0u);
  EXPECT_EQ(advice["first_choice"],
            first["technique"].get<std::string>() + "/" + first["variant"].get<std::string>());
  const auto key = [](const nlohmann::json& c) {
    return std::make_tuple(!c["passes"].get<bool>(), figure(c["error"]), figure(c["instructions"]),
                           figure(c["memory_ratio"]), c["technique"].get<std::string>(),
                           c["variant"].get<std::string>());
  };
  for (size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    EXPECT_EQ(c["rank"], i + 1);
    if (i > 0) {
      EXPECT_LE(key(candidates[i - 1]), key(c)) << c.dump();
    }
    if (c["passes"].get<bool>()) {
      EXPECT_TRUE(c["failures"].empty());
      EXPECT_LE(figure(c["error"]), b.max_error);
      EXPECT_EQ(c["watertight"], "yes");
    } else {
      EXPECT_FALSE(c["failures"].empty());
      EXPECT_EQ(c["verdict"].get<std::string>().rfind("excluded: ", 0), 0u);
    }
  }
  EXPECT_NE(advice["ranking_rule"].get<std::string>().find("error ascending"), std::string::npos);
}

nlohmann::json adviseJson(const std::string& arguments, int expected_exit) {
  const SplitResult r = runTessbenchSplit("advise " + arguments + " --json");
  EXPECT_EQ(r.exit_code, expected_exit) << r.out << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(AdviseCli, QuadMeshEveryTechniqueAppliesAndTheFirstChoiceMeetsEveryConstraint) {
  const Bounds bounds;
  const auto advice = adviseJson("opensubdiv/catmark_cube" + boundArguments(bounds), 0);
  expectRankedByTheRule(advice, bounds);
  EXPECT_TRUE(advice["unsupported"].empty()) << advice["unsupported"].dump();
  for (const char* technique : {"acc", "gregory_acc", "pn_triangles", "phong"}) {
    EXPECT_TRUE(std::any_of(advice["candidates"].begin(), advice["candidates"].end(),
                            [&](const auto& c) { return c["technique"] == technique; }))
        << technique;
  }
}

// loop_icosahedron (20 triangles) rather than tri_pawn (1176): the same refusal in seconds.
TEST(AdviseCli, TriangleMeshExcludesAccWithItsReason) {
  const Bounds bounds;
  const auto advice = adviseJson("opensubdiv/loop_icosahedron" + boundArguments(bounds), 0);
  expectRankedByTheRule(advice, bounds);
  // acc and the quad-only baseline osd_adaptive refuse it; every other technique takes it.
  ASSERT_EQ(advice["unsupported"].size(), 2u) << advice["unsupported"].dump();
  EXPECT_EQ(advice["unsupported"][0]["technique"], "acc");
  EXPECT_NE(advice["unsupported"][0]["reason"].get<std::string>().find("ACC needs quads"),
            std::string::npos);
  EXPECT_EQ(advice["unsupported"][1]["technique"], "osd_adaptive");
  EXPECT_FALSE(std::any_of(advice["candidates"].begin(), advice["candidates"].end(),
                           [](const auto& c) { return c["technique"] == "acc"; }));
  const SplitResult markdown =
      runTessbenchSplit("advise opensubdiv/loop_icosahedron --technique acc");
  EXPECT_EQ(markdown.exit_code, 1) << "nothing supports the asset: no candidate passes";
  EXPECT_NE(markdown.out.find("excluded: unsupported input: acc:"), std::string::npos)
      << markdown.out;
}

TEST(AdviseCli, TorusFirstChoiceMeetsEveryConstraint) {
  const Bounds bounds{0.005, 0.3, 500};
  expectRankedByTheRule(adviseJson("opensubdiv/catmark_torus" + boundArguments(bounds), 0), bounds);
}

TEST(AdviseCli, ReadsARunFolderAndExitsOneWhenNoCandidatePasses) {
  const auto dir = testing::scratchDirectory("advise_run");
  const SplitResult run = runTessbenchSplit(
      "run --quiet --technique phong --technique acc --asset opensubdiv/catmark_cube "
      "--measure error --measure cracks --measure memory --measure instructions --measure "
      "published_figures --out " +
      dir.string() + " --run-id r");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string folder = (dir / "r").string();

  const Bounds bounds;
  expectRankedByTheRule(
      adviseJson("opensubdiv/catmark_cube --run " + folder + boundArguments(bounds), 0), bounds);
  // No error is 0: no candidate meets it, each says by how much.
  const auto none = adviseJson("opensubdiv/catmark_cube --run " + folder + " --max-error 0", 1);
  EXPECT_TRUE(none["first_choice"].is_null());
  for (const auto& c : none["candidates"]) {
    EXPECT_FALSE(c["passes"].get<bool>());
    EXPECT_NE(c["verdict"].get<std::string>().find("> max 0"), std::string::npos) << c.dump();
  }
  // --technique narrows the candidates.
  const auto phong =
      adviseJson("opensubdiv/catmark_cube --run " + folder + " --technique phong", 0);
  for (const auto& c : phong["candidates"]) EXPECT_EQ(c["technique"], "phong");
  // The short name `run --asset` takes finds the run's asset too.
  const auto short_name = adviseJson("catmark_cube --run " + folder + " --technique phong", 0);
  EXPECT_EQ(short_name["asset"], "opensubdiv/catmark_cube");
  EXPECT_EQ(short_name["candidates"].size(), phong["candidates"].size());

  // An asset the run has no records of, bad numbers, an unknown technique: one line, exit 2.
  for (const std::string& bad :
       {"tessbench/tri_pawn --run " + folder,
        "opensubdiv/catmark_cube --run " + folder + " --max-error abc",
        "opensubdiv/catmark_cube --run " + folder + " --max-memory-ratio -1",
        "opensubdiv/catmark_cube --run " + folder + " --technique nope",
        std::string("no/such_asset --max-error 1")}) {
    const SplitResult r = runTessbenchSplit("advise " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.out << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << bad << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }

  // table on the same folder.
  const SplitResult latex =
      runTessbenchSplit("table " + folder + " --measure error --format latex --per-asset");
  ASSERT_EQ(latex.exit_code, 0) << latex.err;
  EXPECT_NE(latex.out.find("\\toprule"), std::string::npos) << latex.out;
  EXPECT_NE(latex.out.find("hausdorff median (rel\\_diag)"), std::string::npos);
  const SplitResult published = runTessbenchSplit("table " + folder + " --published --format csv");
  ASSERT_EQ(published.exit_code, 0) << published.err;
  EXPECT_NE(published.out.find("NVIDIA's displacement subdivision surfaces talk"),
            std::string::npos);
  EXPECT_NE(published.out.find("DirectX SDK SubD10"), std::string::npos) << published.out;
  for (const SplitResult& r : {latex, published}) {
    EXPECT_EQ(r.out.find("seed 0"), std::string::npos) << r.out;
  }
  for (const std::string& bad :
       {folder + " --measure nope", folder + " --measure error --format html",
        folder + " --measure error --metric nope", folder + " --published --measure error"}) {
    const SplitResult r = runTessbenchSplit("table " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.out << r.err;
    EXPECT_EQ(lineCount(r.err), 1u) << bad << "\n" << r.err;
  }
}

}  // namespace
}  // namespace tb
