// The results model: what a run measured, independent of how it is shown.
// results.json is this model serialised; every report renderer reads only this.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "harness/results/metric_spec.h"

namespace tb::results {

// Bumped whenever a field changes meaning or is removed.
// 2: measure declarations (metric units, directions, headline, fixed notes) at the top
//    level; MeasureResult::notes hold only the notes about their own record.
// 3: rows carry a status: a part of a measure that could not run (no Vulkan device, no
//    shaders, a device error) is a row with status "skipped" or "failed" and a reason,
//    never an ok row whose note says so.
// 4: a measure's rows are a table: "keys" and "metrics" name the columns once, each row is
//    [[key values], [metric values]] (null where absent; status and reason appended when
//    not ok); units come from the declaration; integral values print as integers. Each row
//    is one line of the file. Declarations may carry a summary scope and plots.
constexpr int kResultsSchemaVersion = 4;

struct Metric {
  std::string name;  // snake_case, declared by the measure (MeasureDeclaration::metrics)
  double value = 0;
  std::string unit;  // toString(Unit) of the declared unit: "bytes", "ratio", "ulp", ...
};

enum class MeasureStatus { kOk, kSkipped, kFailed };

// One row of a measure: the parameters that vary inside the measure (e.g. the
// tessellation level) as keys, and the figures for them. A row whose case could not be
// measured has status kSkipped (it cannot run here: no Vulkan device, nothing to measure)
// or kFailed (it ran and broke), the reason, and no metrics; its keys are the ones the
// measured row would have, so a comparison with a run that measured it sees the figures
// missing. results.json writes status and reason only on rows that are not ok.
struct MetricRow {
  std::map<std::string, std::string> keys;
  std::vector<Metric> metrics;
  MeasureStatus status = MeasureStatus::kOk;
  std::string reason = {};  // why the row has no figures; empty when ok
};

// A row with `keys`, no figures, and the status and reason saying why.
MetricRow unmeasuredRow(std::map<std::string, std::string> keys, MeasureStatus status,
                        std::string reason);

struct MeasureResult {
  std::string measure;  // measure id, e.g. "memory"
  MeasureStatus status = MeasureStatus::kOk;
  std::string reason;  // why it was skipped or failed; empty when ok
  std::vector<MetricRow> rows;
  // Notes about this record alone (e.g. how this asset's patches were sampled); the notes
  // that hold for every record are MeasureDeclaration::notes.
  std::vector<std::string> notes;
};

// One (technique, variant, asset, parameters) combination.
struct Record {
  std::string technique;
  std::string variant;
  std::string asset;
  std::map<std::string, std::string> parameters;
  std::vector<std::string> warnings;
  std::vector<MeasureResult> measures;
};

struct AssetSummary {
  std::string name;  // e.g. "opensubdiv/catmark_cube"
  std::string path;  // relative to the source tree when bundled
  size_t faces = 0;
  size_t vertices = 0;
  std::string face_kinds;  // "triangles", "quads", "mixed (max 5)"
  bool normals_computed = false;
  // What the user should know before trusting this asset's figures (mesh::connectivityWarnings),
  // one line each; results.json writes the field only when non-empty.
  std::vector<std::string> warnings = {};
};

// A technique × asset pair the run did not measure, and why.
struct Skip {
  std::string technique;
  std::string asset;
  std::string reason;
};

// What a run selected, in run order: techniques (each with its variants, in the
// technique's order), the inputs (assets, then scenarios) and the measures. Records are
// written in this order (technique, variant, asset), a record's measures in measure order;
// `tessbench merge` orders shard records by it and refuses shards whose selections differ.
struct RunSelection {
  struct TechniqueVariants {
    std::string technique;
    std::vector<std::string> variants;
    // The variants made to show a failure (techniques::VariantInfo::control): never a choice.
    std::vector<std::string> controls = {};
    bool operator==(const TechniqueVariants&) const = default;
  };
  std::vector<TechniqueVariants> techniques;
  std::vector<std::string> assets;
  std::vector<std::string> measures;
  // The suite mode (`run --suite`): "default" or "full". Results written before it was
  // recorded read as "default".
  std::string suite = "default";
  // The camera path files given with `run --camera`, as results name them
  // ("assets/cameras/orbit.json" for a bundled path); empty: the suite's own paths.
  std::vector<std::string> camera_paths{};
  bool operator==(const RunSelection&) const = default;
};

// The slice of the work list a run measured (`tessbench run --shard I/N`, numbered from
// 0); count 0: not a shard (the whole list, or a merge of shards).
struct ShardId {
  size_t index = 0;
  size_t count = 0;
  bool operator==(const ShardId&) const = default;
};

// One shard run a merged run was made from.
struct ShardSource {
  ShardId shard;
  std::string run_id;
  std::string date;
  std::string host;
  std::string folder;  // as given to `tessbench merge`
};

struct RunContext {
  std::string date;    // ISO 8601 UTC; excluded from determinism checks
  std::string run_id;  // the folder name; excluded from determinism checks
  std::string git_sha;
  // The commit's committer date, ISO 8601 with its offset (git log --format=%cI); empty in
  // results written before it was recorded or built outside a git checkout. `tessbench
  // history` orders runs by it.
  std::string commit_time = {};
  std::string host;
  std::string cpu;
  std::string compiler;
  std::string build_type;
  std::map<std::string, std::string> libraries;  // name -> version
  std::string vulkan_device;                     // empty when no device was opened
  std::string command_line;
  RunSelection selection;  // empty in results written before it was recorded
  ShardId shard;
  std::vector<ShardSource> merged_from;  // the shards of a merged run, by index
};

struct Results {
  int schema_version = kResultsSchemaVersion;
  RunContext context;
  std::vector<AssetSummary> assets;
  std::vector<Record> records;
  std::vector<Skip> skipped;
  // One per measure the run selected, sorted by id.
  std::vector<MeasureDeclaration> measures;
  const MeasureDeclaration* findMeasure(const std::string& id) const;
};

const char* toString(MeasureStatus status);
std::optional<MeasureStatus> parseMeasureStatus(const std::string& text);

}  // namespace tb::results
