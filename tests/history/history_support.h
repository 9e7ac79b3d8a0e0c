// Synthetic run folders for the history tests, written by the results writers
// (results_json.h, timings_json.h): two techniques × two assets, one measure with a
// headline figure, so each test builds exactly the history it needs in milliseconds.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "harness/results/results_json.h"
#include "harness/results/run_folder.h"
#include "harness/results/timings_json.h"

namespace tb::testing {

struct SyntheticRun {
  std::string run_id = "r";
  std::string sha = "aaaa000000000000000000000000000000000000";
  std::string commit_time = "2026-01-01T00:00:00+00:00";
  std::string date = "2026-01-01T01:00:00Z";
  std::string device = "llvmpipe (test)";
  double acc_hausdorff = 0.001;      // acc/default's worst figure on every asset, rel_diag
  std::vector<double> samples = {};  // timings.json samples of every entry (none: no file)
  // > 0: one more measure, "isa", with a shader-db summary (group key "family"): acc/default
  // has two programs on each of polaris10 and navi21, of `isa_instructions` and 10 more.
  double isa_instructions = 0;
};

// The shader-db measure of SyntheticRun::isa_instructions.
inline void addShaderDbMeasure(const SyntheticRun& run, results::Results* r) {
  results::MeasureDeclaration isa{
      "isa",
      "ISA",
      "compiled instructions",
      {{"instructions", results::Unit::kCount, results::Direction::kLowerIsBetter}},
      {"instructions"},
      {},
      {},
      {}};
  isa.shader_db = {"family", {}, {"instructions"}};
  r->measures.push_back(isa);
  results::Record record{"acc", "default", "opensubdiv/catmark_cube", {}, {}, {}};
  results::MeasureResult result{"isa", results::MeasureStatus::kOk, "", {}, {}};
  for (const char* family : {"polaris10", "navi21"}) {
    for (const char* program : {"tessellator", "compute"}) {
      const double extra = std::string(program) == "compute" ? 10 : 0;
      result.rows.push_back({{{"family", family}, {"pipeline", program}},
                             {{"instructions", run.isa_instructions + extra, ""}}});
    }
  }
  record.measures.push_back(std::move(result));
  r->records.push_back(std::move(record));
}

inline results::Results syntheticResults(const SyntheticRun& run) {
  results::Results r;
  r.context.run_id = run.run_id;
  r.context.git_sha = run.sha;
  r.context.commit_time = run.commit_time;
  r.context.date = run.date;
  r.context.vulkan_device = run.device;
  r.measures.push_back(
      {"error",
       "Error",
       "distance to the limit",
       {{"hausdorff", results::Unit::kDiagonal, results::Direction::kLowerIsBetter},
        {"points", results::Unit::kCount, results::Direction::kNone}},
       {"hausdorff"},
       {},
       {},
       {}});
  for (const char* technique : {"acc", "phong"}) {
    for (const char* asset : {"opensubdiv/catmark_cube", "opensubdiv/loop_cube"}) {
      results::Record record{technique, "default", asset, {}, {}, {}};
      results::MeasureResult error{"error", results::MeasureStatus::kOk, "", {}, {}};
      const double worst = std::string(technique) == "acc" ? run.acc_hausdorff : 0.01;
      error.rows.push_back({{{"level", "4"}}, {{"hausdorff", worst, ""}, {"points", 100, ""}}});
      error.rows.push_back({{{"level", "8"}}, {{"hausdorff", worst / 2, ""}, {"points", 400, ""}}});
      record.measures.push_back(std::move(error));
      r.records.push_back(std::move(record));
    }
  }
  if (run.isa_instructions > 0) addShaderDbMeasure(run, &r);
  return r;
}

// Writes the run's folder `<root>/<run_id>` (results.json, and timings.json when the run has
// samples); returns its path.
inline std::string writeSyntheticRun(const std::filesystem::path& root, const SyntheticRun& run) {
  const std::filesystem::path folder = root / run.run_id;
  std::filesystem::create_directories(folder);
  const results::Results r = syntheticResults(run);
  results::writeNewFile((folder / "results.json").string(), results::serializeResults(r));
  if (!run.samples.empty()) {
    results::RunTimings timings;
    timings.repetitions = int(run.samples.size());
    for (const results::Record& record : r.records) {
      timings.measures.push_back(
          {record.technique, record.variant, record.asset, "error", run.samples});
    }
    results::writeNewFile((folder / "timings.json").string(), results::serializeTimings(timings));
  }
  return folder.string();
}

}  // namespace tb::testing
