// End-to-end tests of the `tessbench` executable: exit codes, one-line errors,
// JSON listings and byte-identical results for identical inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "tests/cli/cli_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::CommandResult;
using testing::lineCount;
using testing::readFile;
using testing::runTessbench;

TEST(Cli, ListTechniquesJsonHasTheRequiredFields) {
  const CommandResult r = runTessbench("list techniques --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto json = nlohmann::json::parse(r.output);
  ASSERT_TRUE(json.is_array());
  ASSERT_FALSE(json.empty());
  for (const auto& technique : json) {
    for (const char* key : {"id", "family", "title", "citation"}) {
      EXPECT_TRUE(technique.contains(key)) << key;
    }
  }
  // Every registered technique is listed; phong is always registered (others may sort
  // before it).
  EXPECT_TRUE(std::any_of(json.begin(), json.end(),
                          [](const auto& technique) { return technique["id"] == "phong"; }));
}

TEST(Cli, MissingAssetIsOneLineNamingTheFile) {
  const CommandResult r =
      runTessbench("run --quiet --asset does/not/exist.obj --out /tmp/tb_cli_x");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(lineCount(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find("does/not/exist.obj"), std::string::npos) << r.output;
}

TEST(Cli, MalformedObjNamesTheLine) {
  const auto dir = testing::scratchDirectory("cli_malformed");
  const std::string path =
      testing::writeTextFile(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  const CommandResult r =
      runTessbench("run --quiet --asset " + path + " --out " + (dir / "out").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(lineCount(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find(path + ": line 4"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "a failed run must leave no folder";
}

TEST(Cli, AnAssetNoSelectedTechniqueSupportsIsOneLineNamingTheFace) {
  const auto dir = testing::scratchDirectory("cli_unsupported");
  const std::string path =
      testing::writeTextFile(dir / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const CommandResult r = runTessbench("run --quiet --technique acc --measure error --asset " +
                                       path + " --out " + (dir / "out").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(lineCount(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find(path), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("face 0"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "a failed run must leave no folder";
}

TEST(Cli, ErrorMeasureReportsEveryTriangleAsset) {
  const auto dir = testing::scratchDirectory("cli_error");
  const CommandResult r = runTessbench(
      "run --quiet --technique phong --measure error --asset loop_cube --asset tjunction "
      "--run-id e --out " +
      dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto json = nlohmann::json::parse(readFile(dir / "e" / "results.json"));
  size_t with_error = 0;
  for (const auto& record : json["records"]) {
    ASSERT_EQ(record["measures"].size(), 1u);
    const auto& measure = record["measures"][0];
    EXPECT_EQ(measure["status"], "ok") << measure["reason"];
    with_error += measure["rows"].size() == 1;
  }
  // The default suite's 2 variants (α = 0.75 and `edge`; the α sweep is --suite full's) x 2.
  EXPECT_EQ(with_error, 4u);
  EXPECT_NE(readFile(dir / "e" / "report.md").find("### error\n"), std::string::npos);
}

// Oracle: lavapipe's own tessellator. Both backends must give the same points and the
// same triangles (as coordinate triples), whatever order each emits them in.
TEST(Cli, TessellateCpuAndGpuBackendsAgree) {
  const std::string args =
      "tessellate --domain tri --spacing fractional_odd --outer 3.3,5.1,7.9 --inner 4.4 --json";
  const CommandResult cpu = runTessbench(args + " --backend cpu");
  ASSERT_EQ(cpu.exit_code, 0) << cpu.output;
  const CommandResult gpu = runTessbench(args + " --backend gpu");
  if (gpu.exit_code != 0 && gpu.output.find("Vulkan") != std::string::npos) {
    GTEST_SKIP() << "no Vulkan device: " << gpu.output;
  }
  ASSERT_EQ(gpu.exit_code, 0) << gpu.output;
  using Point = std::vector<double>;
  auto canonical = [](const std::string& text) {
    const auto json = nlohmann::json::parse(text);
    std::vector<Point> points;
    for (const auto& p : json["points"]) points.push_back(p.get<Point>());
    std::vector<std::vector<Point>> primitives;
    for (const auto& prim : json["primitives"]) {
      std::vector<Point> corners;
      for (const auto& i : prim) corners.push_back(points.at(i.get<size_t>()));
      std::sort(corners.begin(), corners.end());
      primitives.push_back(corners);
    }
    std::sort(points.begin(), points.end());
    std::sort(primitives.begin(), primitives.end());
    return std::make_pair(points, primitives);
  };
  const auto a = canonical(cpu.output), b = canonical(gpu.output);
  EXPECT_GT(a.first.size(), 10u);
  EXPECT_EQ(a.first, b.first);
  EXPECT_EQ(a.second, b.second);
}

TEST(Cli, TessellateRejectsBadLevelsInOneLine) {
  for (const char* args : {"--domain quad --spacing integer --outer 1,2,3 --inner 1,1",
                           "--domain tri --spacing integer --outer 1,x,3 --inner 1",
                           "--domain tri --spacing sideways --outer 1,2,3 --inner 1"}) {
    const CommandResult r = runTessbench(std::string("tessellate ") + args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(lineCount(r.output), 1u) << r.output;
  }
}

TEST(Cli, ThreadCountOutOfRangeIsRejected) {
  for (const char* value : {"-1", "abc", "5000"}) {
    const CommandResult r = runTessbench(std::string("run --quiet --threads ") + value);
    EXPECT_NE(r.exit_code, 0) << value;
    EXPECT_NE(r.output.find("--threads: Value " + std::string(value) + " not in range 0 to 4096"),
              std::string::npos)
        << r.output;
  }
}

TEST(Cli, UnknownTechniqueAndMeasureAreRejected) {
  CommandResult r = runTessbench("run --quiet --technique nope");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("unknown technique"), std::string::npos) << r.output;
  r = runTessbench("run --quiet --measure nope");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("unknown measure"), std::string::npos) << r.output;
}

// Drops the fields that legitimately differ between runs.
std::string withoutDateAndRunId(const std::string& text) {
  auto json = nlohmann::ordered_json::parse(text);
  json["context"].erase("date");
  json["context"].erase("run_id");
  return json.dump(2);
}

TEST(Cli, IdenticalInputsGiveByteIdenticalResults) {
  // Under a sanitizer ThreadInvariance.ResultsAreByteIdenticalOnOneAndTwoThreads runs the same
  // suite code twice and compares the bytes; this run adds only the command line's parsing,
  // which the other Cli tests run there.
  if (testing::kUnderSanitizer)
    GTEST_SKIP() << "ThreadInvariance runs the suite twice under a sanitizer";
  const auto dir = testing::scratchDirectory("cli_determinism");
  // Every measure, on a quad and a triangle asset (the whole suite is README command 1).
  const std::string assets = "--asset catmark_cube --asset loop_icosahedron";
  const std::string args = "run --quiet " + assets + " --out " + (dir / "runs").string();
  const CommandResult first = runTessbench(args);
  const CommandResult second = runTessbench(args);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  ASSERT_EQ(second.exit_code, 0) << second.output;
  std::vector<std::filesystem::path> runs;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "runs"))
    runs.push_back(entry.path());
  ASSERT_EQ(runs.size(), 2u) << "each run gets its own folder";
  const std::string a = readFile(runs[0] / "results.json");
  const std::string b = readFile(runs[1] / "results.json");
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(withoutDateAndRunId(a), withoutDateAndRunId(b));
  // Apart from those two fields the raw bytes agree too: only two lines differ.
  size_t differing_lines = 0;
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  while (std::getline(sa, la) && std::getline(sb, lb)) differing_lines += la != lb;
  EXPECT_LE(differing_lines, 2u);
  EXPECT_TRUE(std::filesystem::exists(runs[0] / "report.md"));
  // The pictures too: the same files, byte for byte (only an index when there is no device).
  ASSERT_TRUE(std::filesystem::exists(runs[0] / "pictures" / "pictures.json"));
  size_t pictures = 0;
  for (const auto& entry : std::filesystem::directory_iterator(runs[0] / "pictures")) {
    const auto other = runs[1] / "pictures" / entry.path().filename();
    ASSERT_TRUE(std::filesystem::exists(other)) << other;
    EXPECT_EQ(readFile(entry.path()), readFile(other)) << entry.path().filename();
    ++pictures;
  }
  const auto index = nlohmann::json::parse(readFile(runs[0] / "pictures" / "pictures.json"));
  // An error and a wireframe picture per entry, and a crack picture per entry that cracks
  // (phong/alpha0.75 and osd_adaptive/iso2_gregory on the cube, when there is a device).
  size_t crack_pictures = 0;
  for (const auto& entry : index["pictures"]) crack_pictures += entry.contains("crack_png");
  if (!index["pictures"].empty()) {
    EXPECT_GE(crack_pictures, 2u);
  }
  EXPECT_EQ(pictures, 1 + 2 * index["pictures"].size() + crack_pictures);
}

TEST(Cli, RunWritesPicturesUnlessToldNot) {
  const auto dir = testing::scratchDirectory("cli_pictures");
  const std::string args =
      "run --quiet --technique acc --asset catmark_torus --measure error --out " + dir.string() +
      " --run-id ";
  CommandResult r = runTessbench(args + "with");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto index = nlohmann::json::parse(readFile(dir / "with" / "pictures" / "pictures.json"));
  if (index["status"] == "ok") {
    ASSERT_EQ(index["pictures"].size(), 1u);
    const auto& picture = index["pictures"][0];
    EXPECT_EQ(picture["error_png"], "pictures/acc--opensubdiv--catmark_torus--error.png");
    EXPECT_TRUE(std::filesystem::exists(dir / "with" / picture["error_png"].get<std::string>()));
    EXPECT_TRUE(
        std::filesystem::exists(dir / "with" / picture["wireframe_png"].get<std::string>()));
  } else {
    EXPECT_EQ(index["status"], "skipped");
    EXPECT_TRUE(index["pictures"].empty());
  }
  r = runTessbench(args + "without --no-pictures");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "without" / "results.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "without" / "pictures"));
}

TEST(Cli, DefaultRunCoversPhongOnEveryBundledAsset) {
  const auto dir = testing::scratchDirectory("cli_default");
  // Phong alone: the default selection itself (every technique on every asset) is the
  // baseline test's; this one asks that phong reaches every bundled asset.
  // Under a sanitizer, three assets of the sweep (about 4 minutes there otherwise).
  const std::string subset = testing::kUnderSanitizer
                                 ? " --asset catmark_cube --asset tri_torus --asset catmark_pawn"
                                 : "";
  const std::string args = "run --quiet --technique phong --measure memory --run-id only" + subset +
                           " --out " + dir.string();
  const CommandResult r = runTessbench(args);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto json = nlohmann::json::parse(readFile(dir / "only" / "results.json"));
  // Memory records per phong variant: the default (alpha0.75) and `edge`, whose per-edge
  // normals are patch data of its own; the other α variants share the default's.
  std::map<std::string, size_t> phong_assets;
  size_t displaced_phong = 0;
  for (const auto& record : json["records"]) {
    if (record["technique"] != "phong") continue;
    if (record["parameters"].contains("displacement")) {
      // The bundled map's displaced asset: 4 levels x 2 samplings x path tessellator | compute
      // (the compute path's rows skipped: it does not displace yet).
      ++displaced_phong;
      EXPECT_EQ(record["measures"][0]["rows"].size(), 16u);
      continue;
    }
    for (const auto& measure : record["measures"]) {
      if (measure["measure"] == "memory") {
        ++phong_assets[record["variant"].get<std::string>()];
        EXPECT_EQ(measure["rows"].size(), 8u);  // 4 levels x path tessellator | compute
      }
    }
  }
  EXPECT_EQ(displaced_phong, testing::kUnderSanitizer ? 0u : 1u);
  size_t assets = 0;  // bundled OBJ assets, not the displaced ones ("<asset>+<map>")
  for (const auto& asset : json["assets"]) {
    assets += asset["name"].get<std::string>().find('+') == std::string::npos;
  }
  EXPECT_EQ(phong_assets, (std::map<std::string, size_t>{{"alpha0.75", assets}, {"edge", assets}}));
  const std::string report = readFile(dir / "only" / "report.md");
  EXPECT_NE(report.find("### memory\n"), std::string::npos);
  // The same run id again is refused, and the first results stay.
  const CommandResult again = runTessbench(args);
  EXPECT_NE(again.exit_code, 0);
  EXPECT_NE(again.output.find("already exists"), std::string::npos) << again.output;
}

}  // namespace
}  // namespace tb

namespace tb {
namespace {

using testing::CommandResult;
using testing::readFile;
using testing::runTessbench;

// What a reader sees cites sources by published title and author, never by the project's
// internal seed numbers ("seed 000"), which mean nothing in a published table.
TEST(Cli, ReaderVisibleTextCitesSourcesNotSeedNumbers) {
  const auto dir = testing::scratchDirectory("cli_citations");
  std::string seen;
  for (const char* command :
       {"--help", "list techniques --json", "list measures --json", "run --help", "report --help",
        "compare --help", "merge --help", "tessellate --help"}) {
    const CommandResult r = runTessbench(command);
    EXPECT_EQ(r.exit_code, 0) << command << ": " << r.output;
    seen += r.output;
  }
  const CommandResult run = runTessbench(
      "run --quiet --technique acc --technique pn_triangles --asset catmark_cube --measure "
      "published_figures --measure memory --run-id c --out " +
      dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  seen += readFile(dir / "c" / "report.md");
  EXPECT_NE(seen.find("SubD10"), std::string::npos) << "the published figures are cited";
  EXPECT_NE(seen.find("Lost Planet 2"), std::string::npos);
  const std::regex seed_number("seed[ _-]?0[0-9][0-9]", std::regex::icase);
  std::smatch match;
  EXPECT_FALSE(std::regex_search(seen, match, seed_number))
      << "'" << match.str() << "' near: "
      << seen.substr(static_cast<size_t>(std::max<long>(0, match.position() - 80)), 200);
}

}  // namespace
}  // namespace tb

namespace tb {
namespace {

// Issue 18's acceptance 5: wave particles are listed as a simulation, and a run of the
// technique alone runs every bundled scenario written for it with its four measures.
TEST(Cli, WaveParticlesAreASimulationRunOnEveryBundledScenarioWithTheirMeasures) {
  const CommandResult list = runTessbench("list techniques --json");
  ASSERT_EQ(list.exit_code, 0) << list.output;
  bool listed = false;
  for (const auto& technique : nlohmann::json::parse(list.output)) {
    if (technique["id"] == "wave_particles") {
      listed = true;
      EXPECT_EQ(technique["family"], "simulation");
    }
  }
  EXPECT_TRUE(listed);
  const CommandResult scenarios = runTessbench("list scenarios --json");
  ASSERT_EQ(scenarios.exit_code, 0) << scenarios.output;
  std::set<std::string> bundled;
  for (const auto& scenario : nlohmann::json::parse(scenarios.output)) {
    if (scenario["technique"] == "wave_particles") bundled.insert(scenario["name"]);
  }
  EXPECT_TRUE(bundled.count("wave_point_impulse") && bundled.count("wave_straight_wall"));

  const auto dir = testing::scratchDirectory("cli_wave_particles");
  const CommandResult r =
      runTessbench("run --quiet --technique wave_particles --run-id w --out " + dir.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto json = nlohmann::json::parse(readFile(dir / "w" / "results.json"));
  std::map<std::string, std::set<std::string>> measures_by_record;
  for (const auto& record : json["records"]) {
    EXPECT_EQ(record["technique"], "wave_particles");
    std::set<std::string>& ids = measures_by_record[record["variant"].get<std::string>() + " " +
                                                    record["asset"].get<std::string>()];
    for (const auto& measure : record["measures"]) {
      EXPECT_EQ(measure["status"], "ok") << measure["measure"];
      ids.insert(measure["measure"]);
    }
  }
  EXPECT_EQ(measures_by_record.size(), 2 * bundled.size()) << "full and lp2 on every scenario";
  size_t isa_records = 0;
  for (auto [record, ids] : measures_by_record) {
    // isa: once per technique × variant (the default variant in the default suite), on the
    // first scenario.
    isa_records += ids.erase("isa");
    EXPECT_EQ(ids, (std::set<std::string>{"instructions", "memory", "sim_cost", "wave_error"}))
        << record;
  }
  EXPECT_EQ(isa_records, 1u);
}

}  // namespace
}  // namespace tb
