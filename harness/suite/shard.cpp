#include "harness/suite/shard.h"

#include <charconv>

#include "core/mesh/fnv1a.h"
#include "core/mesh/input_error.h"
#include "harness/suite/suite.h"
#include "techniques/registry.h"

namespace tb::suite {
namespace {

bool ownsKey(const ShardSpec& shard, const std::string& key) {
  return !shard.sharded() || mesh::fnv1a64(key) % shard.count == shard.index;
}

// A decimal number filling `text` exactly (no sign, no spaces).
bool parseCount(std::string_view text, size_t* value) {
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), *value);
  return error == std::errc() && end == text.data() + text.size();
}

}  // namespace

ShardSpec parseShard(const std::string& text) {
  const size_t slash = text.find('/');
  ShardSpec shard;
  const std::string_view view(text);
  if (slash == std::string::npos || !parseCount(view.substr(0, slash), &shard.index) ||
      !parseCount(view.substr(slash + 1), &shard.count)) {
    throw mesh::InputError("--shard", text,
                           "expected I/N, e.g. 0/3 (shard I of N, numbered from 0)");
  }
  if (shard.count == 0 || shard.index >= shard.count) {
    throw mesh::InputError("--shard", text,
                           "needs 0 <= I < N (shards are numbered from 0, like a Kubernetes "
                           "Indexed Job's completion index)");
  }
  return shard;
}

bool ownsMeasure(const ShardSpec& shard, const std::string& technique, const std::string& variant,
                 const std::string& asset, const std::string& measure) {
  return ownsKey(shard, technique + "/" + variant + "/" + asset + "/" + measure);
}

bool ownsSkip(const ShardSpec& shard, const std::string& technique, const std::string& asset) {
  return ownsKey(shard, technique + "//" + asset);
}

results::ShardId toShardId(const ShardSpec& shard) { return {shard.index, shard.count}; }

results::RunSelection describeSelection(const SuiteSelection& selection,
                                        const results::Results& results) {
  results::RunSelection described;
  std::vector<const techniques::Technique*> techniques = selection.techniques;
  if (techniques.empty()) techniques = techniques::TechniqueRegistry::instance().all();
  for (const techniques::Technique* technique : techniques) {
    described.techniques.push_back({technique->info().id, {}});
    for (const techniques::VariantInfo& variant : selectedVariants(*technique, selection)) {
      described.techniques.back().variants.push_back(variant.name);
      if (!variant.control.empty()) described.techniques.back().controls.push_back(variant.name);
    }
  }
  for (const results::AssetSummary& asset : results.assets) described.assets.push_back(asset.name);
  for (const techniques::Scenario& scenario : selection.scenarios)
    described.assets.push_back(scenario.name);
  std::vector<const measures::Measure*> measures = selection.measures;
  if (measures.empty()) measures = measures::MeasureRegistry::instance().all();
  for (const measures::Measure* measure : measures)
    described.measures.push_back(measure->info().id);
  described.suite = toString(selection.suite);
  return described;
}

}  // namespace tb::suite
