#include "harness/results/merge.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <tuple>

#include "harness/results/results_json.h"

namespace tb::results {
namespace {

std::string describe(const ShardId& shard) {
  return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

[[noreturn]] void refuse(const std::string& folder, const std::string& rule) {
  throw std::runtime_error(folder + ": " + rule);
}

// Every input is a shard of the same N, and indices 0..N-1 each appear exactly once.
// Returns the runs ordered by shard index.
std::vector<const ShardRun*> orderedShardSet(const std::vector<ShardRun>& shards) {
  if (shards.empty()) throw std::runtime_error("merge: no shard folders given");
  const ShardRun& first = shards.front();
  std::vector<const ShardRun*> by_index;
  for (const ShardRun& run : shards) {
    const ShardId& shard = run.results.context.shard;
    if (shard.count == 0) {
      refuse(run.folder, "not a shard run (its context has no shard; run with --shard I/N)");
    }
    if (shard.count != first.results.context.shard.count) {
      refuse(run.folder, "shard " + describe(shard) + " is not a shard of the same N as " +
                             first.folder + " (" + describe(first.results.context.shard) + ")");
    }
    if (by_index.empty()) by_index.resize(shard.count, nullptr);
    if (by_index[shard.index] != nullptr) {
      refuse(run.folder, "shard " + describe(shard) + " given twice (also " +
                             by_index[shard.index]->folder + ")");
    }
    by_index[shard.index] = &run;
  }
  std::string missing;
  for (size_t i = 0; i < by_index.size(); ++i) {
    if (by_index[i] == nullptr) {
      missing += (missing.empty() ? "" : ", ") + describe({i, by_index.size()});
    }
  }
  if (!missing.empty()) {
    throw std::runtime_error("merge: missing shard " + missing + " (every shard 0.." +
                             std::to_string(by_index.size() - 1) +
                             " of N = " + std::to_string(by_index.size()) + " is needed)");
  }
  return by_index;
}

// Shards must come from one build, device and selection: anything else would not add up to
// one run.
void checkSameRun(const ShardRun& reference, const ShardRun& run) {
  const RunContext& a = reference.results.context;
  const RunContext& b = run.results.context;
  const auto differs = [&](const std::string& what, const std::string& mine,
                           const std::string& theirs, const std::string& rule) {
    refuse(run.folder, what + " '" + mine + "' differs from " + reference.folder + "'s '" + theirs +
                           "'; " + rule);
  };
  const std::string one_build = "shards must come from one build";
  if (b.git_sha != a.git_sha) differs("git sha", b.git_sha, a.git_sha, one_build);
  if (b.compiler != a.compiler) differs("compiler", b.compiler, a.compiler, one_build);
  if (b.build_type != a.build_type) differs("build type", b.build_type, a.build_type, one_build);
  if (b.libraries != a.libraries) {
    refuse(run.folder, "library versions differ from " + reference.folder + "'s; " + one_build);
  }
  if (b.vulkan_device != a.vulkan_device) {
    differs("Vulkan device", b.vulkan_device, a.vulkan_device,
            "shards must measure on one kind of device");
  }
  if (b.selection.techniques.empty() && b.selection.assets.empty()) {
    refuse(run.folder, "results.json records no selection (written by an older tessbench)");
  }
  const std::string one_selection =
      "shards must run one selection (--technique, --asset, --measure, --suite, --camera)";
  if (!(b.selection == a.selection)) {
    refuse(run.folder, "selection differs from " + reference.folder + "'s; " + one_selection);
  }
  const nlohmann::ordered_json mine = toJson(run.results), theirs = toJson(reference.results);
  for (const char* section : {"assets", "measures"}) {
    if (mine[section] != theirs[section]) {
      refuse(run.folder, std::string(section) + " differ from " + reference.folder + "'s; " +
                             one_selection + " on the same files");
    }
  }
}

size_t indexIn(const std::vector<std::string>& names, const std::string& name,
               const std::string& folder, const std::string& what) {
  const auto found = std::find(names.begin(), names.end(), name);
  if (found == names.end()) refuse(folder, what + " '" + name + "' is not in the run's selection");
  return size_t(found - names.begin());
}

// Where a record, skip or measure stands in the unsharded run's order.
class RunOrder {
 public:
  explicit RunOrder(const RunSelection& selection) : selection_(selection) {
    for (const auto& technique : selection.techniques) techniques_.push_back(technique.technique);
  }
  size_t technique(const std::string& id, const std::string& folder) const {
    return indexIn(techniques_, id, folder, "technique");
  }
  size_t variant(size_t technique, const std::string& name, const std::string& folder) const {
    return indexIn(selection_.techniques[technique].variants, name, folder,
                   "variant " + techniques_[technique] + "/");
  }
  size_t asset(const std::string& name, const std::string& folder) const {
    return indexIn(selection_.assets, name, folder, "asset");
  }
  size_t measure(const std::string& id, const std::string& folder) const {
    return indexIn(selection_.measures, id, folder, "measure");
  }

 private:
  const RunSelection& selection_;
  std::vector<std::string> techniques_;
};

using RecordKey = std::tuple<size_t, size_t, size_t>;  // technique, variant, asset indices

// Joins records measured in several shards; the shards' copies of parameters and warnings
// (set for every record whatever its measures) must agree.
std::vector<Record> mergeRecords(const std::vector<const ShardRun*>& shards,
                                 const RunOrder& order) {
  std::map<RecordKey, Record> merged;
  std::map<RecordKey, std::map<size_t, std::string>> measured_in;  // measure -> folder
  for (const ShardRun* run : shards) {
    for (const Record& record : run->results.records) {
      const size_t t = order.technique(record.technique, run->folder);
      const RecordKey key{t, order.variant(t, record.variant, run->folder),
                          order.asset(record.asset, run->folder)};
      const std::string name = record.technique + "/" + record.variant + " " + record.asset;
      auto [it, inserted] = merged.try_emplace(key, record);
      if (!inserted) {
        if (record.parameters != it->second.parameters || record.warnings != it->second.warnings) {
          refuse(run->folder,
                 "record " + name + " has other parameters or warnings than in " + "another shard");
        }
        for (const MeasureResult& measure : record.measures) it->second.measures.push_back(measure);
      }
      for (const MeasureResult& measure : record.measures) {
        const size_t m = order.measure(measure.measure, run->folder);
        auto [where, first] = measured_in[key].try_emplace(m, run->folder);
        if (!first) {
          refuse(run->folder, "record " + name + " measure " + measure.measure +
                                  " was also measured in " + where->second);
        }
      }
    }
  }
  std::vector<Record> records;
  for (auto& [key, record] : merged) {
    std::stable_sort(record.measures.begin(), record.measures.end(),
                     [&](const MeasureResult& a, const MeasureResult& b) {
                       return order.measure(a.measure, "") < order.measure(b.measure, "");
                     });
    records.push_back(std::move(record));
  }
  return records;
}

std::vector<Skip> mergeSkipped(const std::vector<const ShardRun*>& shards, const RunOrder& order) {
  std::map<std::pair<size_t, size_t>, std::pair<Skip, std::string>> merged;  // skip, folder
  for (const ShardRun* run : shards) {
    for (const Skip& skip : run->results.skipped) {
      const std::pair key{order.technique(skip.technique, run->folder),
                          order.asset(skip.asset, run->folder)};
      auto [it, inserted] = merged.try_emplace(key, skip, run->folder);
      if (!inserted) {
        refuse(run->folder, "skip of " + skip.technique + " on " + skip.asset +
                                " was also recorded in " + it->second.second);
      }
    }
  }
  std::vector<Skip> skipped;
  for (auto& [key, entry] : merged) skipped.push_back(std::move(entry.first));
  return skipped;
}

// The distinct values of one context field over the shards, in shard order, joined by "; ".
template <class Field>
std::string joinDistinct(const std::vector<const ShardRun*>& shards, Field field) {
  std::vector<std::string> seen;
  for (const ShardRun* run : shards) {
    const std::string& value = field(run->results.context);
    if (std::find(seen.begin(), seen.end(), value) == seen.end()) seen.push_back(value);
  }
  std::string joined;
  for (const std::string& value : seen) joined += (joined.empty() ? "" : "; ") + value;
  return joined;
}

RunContext mergedContext(const std::vector<const ShardRun*>& shards) {
  RunContext context = shards.front()->results.context;
  context.date.clear();
  context.run_id.clear();
  context.command_line.clear();
  context.shard = {};
  context.host =
      joinDistinct(shards, [](const RunContext& c) -> const std::string& { return c.host; });
  context.cpu =
      joinDistinct(shards, [](const RunContext& c) -> const std::string& { return c.cpu; });
  for (const ShardRun* run : shards) {
    const RunContext& c = run->results.context;
    context.merged_from.push_back({c.shard, c.run_id, c.date, c.host, run->folder});
  }
  return context;
}

}  // namespace

Results mergeShards(const std::vector<ShardRun>& shards) {
  const std::vector<const ShardRun*> ordered = orderedShardSet(shards);
  for (const ShardRun* run : ordered) checkSameRun(*ordered.front(), *run);
  const Results& first = ordered.front()->results;
  const RunOrder order(first.context.selection);
  Results merged;
  merged.schema_version = first.schema_version;
  merged.context = mergedContext(ordered);
  merged.assets = first.assets;
  merged.records = mergeRecords(ordered, order);
  merged.skipped = mergeSkipped(ordered, order);
  merged.measures = first.measures;
  return merged;
}

}  // namespace tb::results
