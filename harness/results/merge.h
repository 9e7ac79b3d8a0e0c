// Merging the runs of a sharded suite (`tessbench run --shard I/N`) into one run.
//
// Shards measure disjoint slices of one work list with one build on one kind of device, so
// their records, skips, assets and measure declarations together are the unsharded run's:
// records partial in several shards are joined, then records are put in run order
// (technique, variant, asset, as context.selection lists them) and each record's measures
// in measure order. The records, skipped, assets and measures sections then equal the
// unsharded run's byte for byte; only the context differs (date, run id, command line,
// merged_from).
#pragma once

#include <string>
#include <vector>

#include "harness/results/results_model.h"

namespace tb::results {

// One shard's results and the folder it was read from (named in errors).
struct ShardRun {
  std::string folder;
  Results results;
};

// Throws std::runtime_error, one line naming the folder and the rule, when the runs do not
// fit together: a run that is not a shard, shards of different N, a shard given twice or
// missing, another build (git sha, compiler, build type, libraries), device, selection,
// assets or measure declarations, or records that disagree (a measure in two shards, a
// record whose parameters or warnings differ). The merged context keeps the shards'
// common fields, joins differing hosts and CPUs, lists the shards in `merged_from` and
// leaves date, run_id and command_line to the caller.
Results mergeShards(const std::vector<ShardRun>& shards);

}  // namespace tb::results
