// A sample of an asset's patches for the figures that cost per patch on production-size
// assets (error's Hausdorff distances, cracks' pairs): every feature patch, then runs of
// consecutive other patches, evenly spaced in patch order, up to a budget. A run's patches
// are neighbours on a refined mesh (its faces come in patch order per parent face), so a
// run keeps most of its shared edges and the neighbourhood it needs stays small.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tb::measures {

inline constexpr size_t kPatchSampleRun = 16;  // patches per run of the sample

struct PatchSubset {
  std::vector<uint8_t> part;  // per patch: 1 when sampled
  size_t count = 0;           // patches sampled
  bool all = true;            // every candidate patch is in the sample
};

// `feature[p]` = 1 puts patch p in the sample whatever the budget (unless !keep_features,
// the controls' sample, which treats features as any other patch); `candidate[p]` = 0 leaves
// p out (a patch without a figure to sample). Then runs of kPatchSampleRun of the other
// candidates, evenly spaced, while the sample stays within `budget`; every candidate when
// they all fit.
PatchSubset samplePatches(const std::vector<uint8_t>& feature,
                          const std::vector<uint8_t>& candidate, size_t budget,
                          bool keep_features = true);

}  // namespace tb::measures
