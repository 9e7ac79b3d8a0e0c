// Sharded runs: which slice of the work list a run measures (`tessbench run --shard I/N`).
//
// The work list is every technique × variant × asset × measure the suite would run, plus
// every technique × asset it would record as skipped. Shard I of N owns an item when the
// 64-bit FNV-1a hash of the item's key, modulo N, is I. The rule reads nothing but the
// item's own names, so an item keeps its shard when techniques, variants, assets or
// measures are added or removed (only N moves items), every shard decides alone, and the
// N shards partition the list exactly. Hashing spreads the work evenly by count; items
// differ in cost (a crack measure takes seconds, a memory measure milliseconds), so shards
// finish at different times but none owns a whole technique or asset.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "harness/results/results_model.h"

namespace tb::suite {

struct ShardSpec {
  size_t index = 0;  // 0 ≤ index < count (a Kubernetes Indexed Job's completion index)
  size_t count = 1;  // 1: the whole work list
  bool sharded() const { return count > 1; }
};

// "I/N" with decimal I and N, 0 ≤ I < N. Throws InputError naming --shard and the rule.
ShardSpec parseShard(const std::string& text);

// Shard owning the measure `measure` on one record: key "technique/variant/asset/measure".
bool ownsMeasure(const ShardSpec& shard, const std::string& technique, const std::string& variant,
                 const std::string& asset, const std::string& measure);

// Shard recording that `technique` cannot take `asset` (key "technique//asset", which no
// measure key equals: a measure key's second field, the variant, is never empty).
bool ownsSkip(const ShardSpec& shard, const std::string& technique, const std::string& asset);

results::ShardId toShardId(const ShardSpec& shard);

struct SuiteSelection;

// The selection `runSuite` ran, in its order (techniques and measures resolved from the
// registries when the selection names none; assets as `results` lists them, then the
// scenarios) and its suite mode: what a run's context records so that `merge` can order
// shard records and refuse shards of different runs. The --camera files are the caller's
// to add (SuiteSelection holds the paths as functions).
results::RunSelection describeSelection(const SuiteSelection& selection,
                                        const results::Results& results);

}  // namespace tb::suite
