// Reliability of the `tessbench` executable: every class of bad input is one line and exit 2
// with no results folder; no Vulkan device is a run whose GPU rows are skipped; a killed run
// leaves nothing that looks finished; an unwritable --out is one line before any measuring.
#include <fcntl.h>
#include <grp.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "tests/cli/cli_support.h"
#include "tests/mesh/gltf_test_files.h"
#include "tests/test_support.h"

namespace tb {
namespace {

namespace fs = std::filesystem;
using testing::folderEntries;
using testing::readFile;
using testing::runTessbenchSplit;
using testing::SplitResult;
using testing::writeTextFile;

// Bytes no text editor writes: NULs, high bytes and stray newlines, the same every run.
std::string binaryGarbage(size_t size) {
  std::string bytes(size, '\0');
  uint32_t state = 12345;
  for (char& byte : bytes) {
    state = state * 1664525u + 1013904223u;
    byte = char(state >> 24);
  }
  return bytes;
}

// A disc of `valence` quads around vertex 1: its centre has that valence.
std::string poleObj(int valence) {
  std::string text = "v 0 0 0\n";
  const double pi = std::acos(-1.0);
  for (int ring = 1; ring <= 2; ++ring) {
    for (int i = 0; i < valence; ++i) {
      const double a = 2 * pi * (i + 0.5 * (ring - 1)) / valence;
      text += "v " + std::to_string(ring * std::cos(a)) + " " + std::to_string(ring * std::sin(a)) +
              " 0\n";
    }
  }
  for (int i = 0; i < valence; ++i) {
    text += "f 1 " + std::to_string(2 + i) + " " + std::to_string(2 + valence + i) + " " +
            std::to_string(2 + (i + 1) % valence) + "\n";
  }
  return text;
}

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
constexpr const char* kQuad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

// One class of bad input: the files it needs, the arguments (with {dir} for the scratch
// folder), and what its one line must name (the file, and the line or element).
struct BadInput {
  const char* name;
  std::vector<std::pair<std::string, std::string>> files;
  std::string arguments;
  std::vector<std::string> line_names;
};

// OBJ files: the classes of docs/ARCHITECTURE.md section 8 and the reliability list, and
// what a technique cannot take, when no selected technique can.
std::vector<BadInput> objInputs(const std::string& run) {
  const std::string acc = run + "--technique acc --measure memory --asset ";
  return {
      {"obj missing", {}, run + "--asset {dir}/missing.obj", {"{dir}/missing.obj", "no such file"}},
      {"obj empty",
       {{"empty.obj", ""}},
       run + "--asset {dir}/empty.obj",
       {"{dir}/empty.obj", "empty"}},
      {"obj truncated mid-face",
       {{"cut.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 1 2"}},
       run + "--asset {dir}/cut.obj",
       {"{dir}/cut.obj: line 6", "degenerate face"}},
      {"obj binary garbage",
       {{"garbage.obj", binaryGarbage(4096)}},
       run + "--asset {dir}/garbage.obj",
       {"{dir}/garbage.obj"}},
      {"obj NaN coordinate",
       {{"nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n"}},
       run + "--asset {dir}/nan.obj",
       {"{dir}/nan.obj: line 2", "not finite"}},
      {"obj infinite coordinate",
       {{"inf.obj", "v 0 0 0\nv 1 0 -inf\nv 0 1 0\nf 1 2 3\n"}},
       run + "--asset {dir}/inf.obj",
       {"{dir}/inf.obj: line 2", "not finite"}},
      {"obj vertex index out of range",
       {{"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"}},
       run + "--asset {dir}/range.obj",
       {"{dir}/range.obj: line 4", "index 9 is out of range"}},
      {"obj normal index out of range",
       {{"normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n"}},
       run + "--asset {dir}/normal.obj",
       {"{dir}/normal.obj: line 5", "normal index 7"}},
      {"obj degenerate face",
       {{"degenerate.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n"}},
       run + "--asset {dir}/degenerate.obj",
       {"{dir}/degenerate.obj: line 4", "uses vertex 2 twice"}},
      {"obj unreadable tag",
       {{"tag.obj", std::string(kQuad) + "t crease 1/x/0 1 2 5\n"}},
       run + "--asset {dir}/tag.obj",
       {"{dir}/tag.obj: line 6", "tag 'crease'"}},
      // What a technique cannot take, when no selected technique can.
      {"non-quad face for acc",
       {{"tri.obj", kTriangle}},
       acc + "{dir}/tri.obj",
       {"{dir}/tri.obj", "face 0 (line 4)", "ACC needs quads"}},
      {"non-manifold edge for acc",
       {{"fan.obj",
         "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 -1 0\nv 1 -1 0\n"
         "f 1 2 4 3\nf 2 1 5 6\nf 1 2 8 7\n"}},
       acc + "{dir}/fan.obj",
       {"{dir}/fan.obj", "edge 0-1 is shared by 3 faces"}},
      // acc and gregory_acc accept valence 64 (assets/full_suite/pole64.obj) and keep a
      // finite limit of 256 (techniques/acc/acc.h kMaxValence): the class applies above it.
      {"valence over acc's limit",
       {{"pole257.obj", poleObj(257)}},
       acc + "{dir}/pole257.obj",
       {"{dir}/pole257.obj", "vertex 0", "valence 257 above the maximum 256"}},
  };
}

// Camera path files (run --camera).
std::vector<BadInput> cameraInputs(const std::string& run) {
  const std::string camera = run +
                             "--technique phong --measure adaptivity --asset catmark_cube "
                             "--camera ";
  const std::string orbit = readFile(testing::assetPath("cameras/orbit.json"));
  // The bundled orbit with one top-level field's value replaced as text (1e999 is no
  // double a JSON library would write).
  auto orbitWith = [&](const std::string& field, const std::string& value) {
    std::string text = orbit;
    const size_t key = text.find("\"" + field + "\": ");
    const size_t start = key + field.size() + 4;
    text.replace(start, text.find_first_of(",\n", start) - start, value);
    return text;
  };
  return {
      {"camera missing", {}, camera + "{dir}/missing.json", {"{dir}/missing.json", "no such file"}},
      {"camera malformed JSON",
       {{"cut.json", orbit.substr(0, orbit.size() / 2)}},
       camera + "{dir}/cut.json",
       {"{dir}/cut.json", "malformed JSON"}},
      {"camera binary garbage",
       {{"garbage.json", binaryGarbage(512)}},
       camera + "{dir}/garbage.json",
       {"{dir}/garbage.json", "malformed JSON"}},
      {"camera non-finite field",
       {{"huge.json", orbitWith("near", "1e999")}},
       camera + "{dir}/huge.json",
       {"{dir}/huge.json", "near"}},
      {"camera field out of range",
       {{"fov.json", orbitWith("fov_y_deg", "180")}},
       camera + "{dir}/fov.json",
       {"{dir}/fov.json", "fov_y_deg"}},
      {"camera field of the wrong type",
       {{"frames.json", orbitWith("frames", "\"24\"")}},
       camera + "{dir}/frames.json",
       {"{dir}/frames.json", "frames"}},
  };
}

// Scenario files (run --scenario), and what a simulation cannot take.
std::vector<BadInput> scenarioInputs(const std::string& run) {
  const std::string scenario = run + "--technique wave_particles --measure wave_error --scenario ";
  const std::string point = readFile(testing::assetPath("scenarios/wave_point_impulse.json"));
  // The bundled point impulse with `from` replaced (it must be there).
  auto pointWith = [&](const std::string& from, const std::string& to) {
    std::string text = point;
    const size_t at = text.find(from);
    if (at == std::string::npos) throw std::logic_error("not in the scenario: " + from);
    return text.replace(at, from.size(), to);
  };
  return {
      {"scenario missing",
       {},
       scenario + "{dir}/missing.json",
       {"{dir}/missing.json", "no such file"}},
      {"scenario malformed JSON",
       {{"cut.json", point.substr(0, point.size() / 2)}},
       scenario + "{dir}/cut.json",
       {"{dir}/cut.json", "malformed JSON"}},
      {"scenario binary garbage",
       {{"garbage.json", binaryGarbage(512)}},
       scenario + "{dir}/garbage.json",
       {"{dir}/garbage.json", "malformed JSON"}},
      {"scenario non-finite field",
       {{"huge.json", pointWith("\"time_step_s\": 0.02", "\"time_step_s\": 1e999")}},
       scenario + "{dir}/huge.json",
       {"{dir}/huge.json", "not a finite number"}},
      {"scenario duration below the step",
       {{"short.json", pointWith("\"duration_s\": 3.0", "\"duration_s\": 0.01")}},
       scenario + "{dir}/short.json",
       {"{dir}/short.json", "duration_s", "time_step_s"}},
      {"scenario missing parameter",
       {{"speed.json", pointWith("\"wave_speed_m_per_s\": 1.0,", "")}},
       scenario + "{dir}/speed.json",
       {"{dir}/speed.json", "parameters.wave_speed_m_per_s", "missing"}},
      {"scenario source outside the domain",
       {{"far.json", pointWith("\"position_m\": [0.0, 0.0]", "\"position_m\": [9.0, 0.0]")}},
       scenario + "{dir}/far.json",
       {"{dir}/far.json", "wave_particles.sources[0].position_m"}},
      {"unknown scenario",
       {},
       scenario + "no_such_scenario",
       {"no_such_scenario", "not a bundled scenario"}},
  };
}

// Displacement maps (`run --displacement`): the EXR and its sidecar.
std::vector<BadInput> displacementInputs(const std::string& run) {
  // A bundled map and its sidecar, and edited copies of the sidecar.
  const std::string displace = run + "--measure memory --technique acc --displacement ";
  const std::string exr = readFile(testing::assetPath("displacement/acc_catmark_torus.exr"));
  const std::string sidecar =
      readFile(testing::assetPath("displacement/acc_catmark_torus.exr.json"));
  auto sidecarWith = [&](const std::string& from, const std::string& to) {
    std::string text = sidecar;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  const std::string vector_sidecar = sidecarWith("\"kind\": \"scalar\"", "\"kind\": \"vector\"");
  const std::string other_asset =
      sidecarWith("opensubdiv/catmark_torus", "opensubdiv/catmark_cube");
  return {
      {"exr missing", {}, displace + "{dir}/missing.exr", {"{dir}/missing.exr", "no such file"}},
      {"exr truncated",
       {{"cut.exr", exr.substr(0, exr.size() / 2)}, {"cut.exr.json", sidecar}},
       displace + "{dir}/cut.exr",
       {"{dir}/cut.exr"}},
      {"exr not an EXR",
       {{"garbage.exr", binaryGarbage(2048)}, {"garbage.exr.json", sidecar}},
       displace + "{dir}/garbage.exr",
       {"{dir}/garbage.exr"}},
      {"exr without its sidecar",
       {{"alone.exr", exr}},
       displace + "{dir}/alone.exr",
       {"{dir}/alone.exr.json", "missing bake sidecar"}},
      {"exr sidecar of another kind",
       {{"kind.exr", exr}, {"kind.exr.json", vector_sidecar}},
       displace + "{dir}/kind.exr",
       {"{dir}/kind.exr.json", "kind"}},
      {"exr baked for another asset",
       {{"other.exr", exr}, {"other.exr.json", other_asset}},
       displace + "{dir}/other.exr",
       {"other.exr", "tiles but the surface has"}},
  };
}

// glTF files: the loader's malformed cases (tests/mesh/gltf_test_files.h), each through `run`.
std::vector<BadInput> gltfInputs(const std::string& run) {
  std::vector<BadInput> inputs;
  for (const testing::GltfCase& bad : testing::badGltfFiles()) {
    std::vector<std::string> names = bad.names;
    names.insert(names.begin(), "{dir}/" + bad.file);
    inputs.push_back({bad.name, {{bad.file, bad.text}}, run + "--asset {dir}/" + bad.file, names});
  }
  return inputs;
}

// Names and options, and where results go.
std::vector<BadInput> optionInputs(const std::string& run) {
  return {
      {"unknown technique", {}, run + "--technique nope", {"--technique", "nope"}},
      {"unknown measure", {}, run + "--measure nope", {"--measure", "nope"}},
      {"unknown asset", {}, run + "--asset no_such_asset", {"no_such_asset"}},
      {"unknown suite", {}, run + "--suite huge", {"--suite", "huge"}},
      {"option out of range", {}, run + "--threads -1", {"--threads", "-1"}},
      {"unknown option", {}, run + "--frobnicate", {"--frobnicate"}},
      {"tessellation level not a number",
       {},
       "tessellate --domain tri --spacing integer --outer 1,x,1",
       {"--outer", "'x'"}},
      {"tessellation level count",
       {},
       "tessellate --domain quad --spacing integer --outer 1,1",
       {"--outer", "needs 4 values"}},
      // Where results go: a path through a regular file cannot hold a folder, whoever runs.
      {"unwritable --out",
       {{"plain_file", "x"}},
       "run --quiet --technique phong --measure memory --asset catmark_cube --out "
       "{dir}/plain_file/results",
       {"{dir}/plain_file/results", "cannot create results folder"}},
  };
}

// Every class, `run` being "run --quiet --out {dir}/out ".
std::vector<BadInput> badInputs() {
  const std::string run = "run --quiet --out {dir}/out ";
  std::vector<BadInput> all;
  for (auto inputs :
       {objInputs, gltfInputs, cameraInputs, scenarioInputs, displacementInputs, optionInputs}) {
    for (BadInput& input : inputs(run)) all.push_back(std::move(input));
  }
  return all;
}

std::string expand(std::string text, const std::string& dir) {
  for (size_t at; (at = text.find("{dir}")) != std::string::npos;) text.replace(at, 5, dir);
  return text;
}

// Every class: exit 2, exactly one line on stderr that names the file (or option) and the
// line or element, nothing on stdout, and no results folder.
TEST(BadInputTable, EveryClassIsOneLineExit2AndNoResultsFolder) {
  const std::vector<BadInput> cases = badInputs();
  for (size_t i = 0; i < cases.size(); ++i) {
    const BadInput& bad = cases[i];
    const fs::path dir = testing::scratchDirectory("bad_input_" + std::to_string(i));
    for (const auto& [file, contents] : bad.files) writeTextFile(dir / file, contents);
    const SplitResult r = runTessbenchSplit(expand(bad.arguments, dir.string()));
    SCOPED_TRACE(std::string(bad.name) + ": " + r.err);
    EXPECT_EQ(r.exit_code, 2);
    ASSERT_FALSE(r.err.empty());
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line, ending in a newline";
    EXPECT_EQ(r.err.back(), '\n');
    EXPECT_EQ(r.err.rfind("tessbench: error: ", 0), 0u);
    EXPECT_TRUE(r.out.empty()) << r.out;
    for (const std::string& name : bad.line_names) {
      EXPECT_NE(r.err.find(expand(name, dir.string())), std::string::npos) << name;
    }
    EXPECT_FALSE(fs::exists(dir / "out")) << "no results folder";
    EXPECT_FALSE(fs::exists(dir / "plain_file" / "results"));
  }
}

// A run id in use, finished or interrupted, is refused and the earlier folder is untouched.
TEST(BadInputTable, ARunIdInUseIsRefusedAndTheEarlierRunKept) {
  const fs::path dir = testing::scratchDirectory("bad_input_run_id");
  for (const char* earlier : {"taken", "halfway.incomplete"}) {
    fs::create_directories(dir / "out" / earlier);
    writeTextFile(dir / "out" / earlier / "results.json", "earlier\n");
  }
  for (const char* id : {"taken", "halfway"}) {
    const SplitResult r = runTessbenchSplit(
        "run --quiet --technique phong --measure memory --asset catmark_cube --out " +
        (dir / "out").string() + " --run-id " + id);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find((dir / "out" / id).string() + ": run folder already exists"),
              std::string::npos)
        << r.err;
  }
  EXPECT_EQ(folderEntries(dir / "out"), (std::vector<std::string>{"halfway.incomplete", "taken"}));
  EXPECT_EQ(readFile(dir / "out" / "taken" / "results.json"), "earlier\n");
}

// A level above the spacing's maximum is not an error: it is clamped, as hardware does, and
// the clamp is reported on one line.
TEST(BadInputTable, ALevelAboveTheMaximumIsClampedAndReported) {
  const SplitResult r = runTessbenchSplit(
      "tessellate --domain quad --spacing fractional_odd --outer 1,2,1e999,3 "
      "--inner 200,1");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("--outer[2] = inf is above 63, the fractional_odd maximum: clamped to 63"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--inner[0] = 200 is above 63"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;
  EXPECT_NE(r.out.find(" triangles\n"), std::string::npos);
}

// No Vulkan driver at all: the CPU measures run, every GPU part is a row with status
// "skipped" and the reason (never an ok row whose note says so), and the run exits 0.
TEST(NoDevice, CpuMeasuresRunAndGpuRowsAreSkippedWithTheReason) {
  const fs::path dir = testing::scratchDirectory("no_device");
  const SplitResult r = runTessbenchSplit(
      "run --quiet --technique phong --technique wave_particles --asset catmark_cube --run-id r "
      "--out " +
          (dir / "out").string(),
      "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(readFile(dir / "out" / "r" / "results.json"));
  EXPECT_EQ(json["context"]["vulkan_device"].get<std::string>().rfind("none", 0), 0u);
  std::map<std::string, size_t> skipped_rows, measured_rows;
  for (const auto& record : json["records"]) {
    for (const auto& measure : record["measures"]) {
      const std::string id = measure["measure"];
      EXPECT_EQ(measure["status"], "ok") << id;
      for (const auto& note : measure["notes"]) {
        EXPECT_EQ(note.get<std::string>().find("skipped"), std::string::npos) << id << ": " << note;
      }
      for (const auto& row : testing::rowObjects(measure)) {
        const std::string note = row["keys"].value("note", "");
        EXPECT_EQ(note.find("skipped"), std::string::npos) << id << " " << row["keys"].dump();
        EXPECT_EQ(note.find("failed"), std::string::npos) << id << " " << row["keys"].dump();
        const bool gpu_part =
            row["keys"].value("backend", "") == "gpu" || row["keys"].value("part", "") == "gpu";
        if (!row.contains("status")) {
          EXPECT_FALSE(gpu_part) << id << " " << row["keys"].dump()
                                 << ": measured without a device";
          EXPECT_FALSE(row["metrics"].empty()) << id << " " << row["keys"].dump();
          ++measured_rows[id];
          continue;
        }
        EXPECT_EQ(row["status"], "skipped") << id << " " << row["keys"].dump();
        if (id == "isa") {
          // Its compilers are drivers too: VK_ICD_FILENAMES here names no radeon ICD.
          const std::string reason = row["reason"];
          EXPECT_TRUE(reason.find("names no radeon ICD") != std::string::npos ||
                      reason.rfind("no Vulkan device", 0) == 0)
              << reason;
          continue;
        }
        EXPECT_TRUE(gpu_part) << id << " " << row["keys"].dump();
        EXPECT_EQ(row["reason"].get<std::string>().rfind("no Vulkan device", 0), 0u)
            << row["reason"];
        EXPECT_TRUE(row["metrics"].empty());
        ++skipped_rows[id];
      }
    }
  }
  // The measures with a GPU half say so; every measure still measured its CPU rows.
  for (const char* id : {"cracks", "adaptivity", "culling"}) {
    EXPECT_GT(skipped_rows[id], 0u) << id;
  }
  for (const char* id : {"cracks", "adaptivity", "culling", "error", "instructions", "memory",
                         "wave_error", "sim_cost"}) {
    EXPECT_GT(measured_rows[id], 0u) << id;
  }
  EXPECT_GT(skipped_rows["sim_cost"], 0u) << "the simulation's device run";
  // And report.md shows the skips as statuses too.
  EXPECT_NE(readFile(dir / "out" / "r" / "report.md").find("| skipped: no Vulkan device"),
            std::string::npos);
}

// A run without a device compared with one that had lavapipe: the GPU figures are missing
// (with the reason), so the comparison fails instead of passing; two runs with the device pass.
TEST(NoDevice, ACompareAgainstARunWithADeviceSaysTheGpuFiguresAreMissing) {
  const fs::path dir = testing::scratchDirectory("no_device_compare");
  const std::string run =
      "run --quiet --technique phong --asset catmark_cube --measure cracks "
      "--measure memory --out " +
      (dir / "out").string() + " --run-id ";
  ASSERT_EQ(runTessbenchSplit(run + "device").exit_code, 0);
  ASSERT_EQ(runTessbenchSplit(run + "device_again").exit_code, 0);
  ASSERT_EQ(runTessbenchSplit(run + "none",
                              "VK_ICD_FILENAMES=/nonexistent/icd.json "
                              "VK_DRIVER_FILES=/nonexistent/icd.json")
                .exit_code,
            0);
  const std::string device = (dir / "out" / "device").string();
  const SplitResult same = runTessbenchSplit("compare " + device + " " + device + "_again");
  EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
  EXPECT_NE(same.out.find("0 missing, 0 regressions"), std::string::npos) << same.out;
  const SplitResult lost =
      runTessbenchSplit("compare " + device + " " + (dir / "out" / "none").string());
  EXPECT_EQ(lost.exit_code, 1) << lost.out << lost.err;
  EXPECT_NE(lost.out.find("FAIL"), std::string::npos) << lost.out;
  EXPECT_NE(lost.out.find("| missing | phong/alpha0.75 opensubdiv/catmark_cube | cracks | "
                          "backend=gpu level=1 path=tessellator spacing=integer | (all) |  | "
                          "skipped: no Vulkan device"),
            std::string::npos)
      << lost.out;
  EXPECT_NE(lost.out.find("Vulkan device differs"), std::string::npos) << lost.out;
}

// A plug-in whose technique throws while building its patches: that record carries the
// error as its measures' status, every other record completes, and the run exits 1 with one
// stderr line per failed measure.
TEST(PluginFailure, AThrowWhileBuildingFailsThatRecordOnly) {
  const fs::path dir = testing::scratchDirectory("plugin_throws");
  const SplitResult r = runTessbenchSplit(
      std::string("--plugin ") + TB_EXAMPLE_PLUGIN +
      " run --quiet --technique example_flat --technique phong --asset catmark_cube --measure "
      "memory --measure error --run-id r --out " +
      (dir / "out").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("tessbench: failed: example_flat/default opensubdiv/catmark_cube memory: "
                       "building the technique failed: example_flat: deliberately fails"),
            std::string::npos)
      << r.err;
  const auto json = nlohmann::json::parse(readFile(dir / "out" / "r" / "results.json"));
  size_t failed = 0, ok = 0;
  for (const auto& record : json["records"]) {
    for (const auto& measure : record["measures"]) {
      if (record["technique"] == "example_flat") {
        EXPECT_EQ(measure["status"], "failed");
        EXPECT_NE(measure["reason"].get<std::string>().find("deliberately fails"),
                  std::string::npos);
        ++failed;
      } else {
        EXPECT_EQ(measure["status"], "ok") << record["variant"] << " " << measure["measure"];
        ++ok;
      }
    }
  }
  EXPECT_EQ(failed, 2u);
  EXPECT_GE(ok, 2u) << "phong's variants measured";
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;
}

// A plug-in whose GPU program names a shader it never shipped: the CPU rows are measured, the
// GPU rows fail naming the shader, and the run says so in one line per record and measure.
TEST(PluginFailure, AMissingShaderFailsTheGpuRowsNamingIt) {
  const fs::path dir = testing::scratchDirectory("plugin_missing_shader");
  const SplitResult r = runTessbenchSplit(
      std::string("--plugin ") + TB_EXAMPLE_PLUGIN +
      " run --quiet --technique example_no_shader --asset loop_cube --measure cracks "
      "--run-id r --out " +
      (dir / "out").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("tessbench: failed: example_no_shader/default"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("shader 'example_no_shader/missing.tesc' is neither built in"),
            std::string::npos)
      << r.err;
  const auto json = nlohmann::json::parse(readFile(dir / "out" / "r" / "results.json"));
  size_t cpu_ok = 0, gpu_failed = 0;
  for (const auto& row : testing::rowObjects(json["records"][0]["measures"][0])) {
    if (row["keys"]["backend"] == "gpu") {
      gpu_failed += row.value("status", "") == "failed";
    } else if (!row["keys"].contains("edge_kind")) {  // loop_cube's seams: CPU rows only
      cpu_ok += !row.contains("status");
    }
  }
  EXPECT_GT(cpu_ok, 0u);
  EXPECT_EQ(gpu_failed, cpu_ok);
}

}  // namespace
}  // namespace tb
