#include "harness/measures/common/patch_sample.h"

#include <algorithm>
#include <cassert>

namespace tb::measures {

PatchSubset samplePatches(const std::vector<uint8_t>& feature,
                          const std::vector<uint8_t>& candidate, size_t budget,
                          bool keep_features) {
  assert(feature.size() == candidate.size());
  const size_t patch_count = feature.size();
  PatchSubset out{std::vector<uint8_t>(patch_count, 0), 0, true};
  std::vector<size_t> others;  // candidates without a feature
  for (size_t p = 0; p < patch_count; ++p) {
    if (!candidate[p]) continue;
    if (feature[p] && keep_features) {
      out.part[p] = 1, ++out.count;
    } else {
      others.push_back(p);
    }
  }
  const size_t runs = (others.size() + kPatchSampleRun - 1) / kPatchSampleRun;
  const size_t room = out.count >= budget ? 0 : budget - out.count;
  const size_t take = std::min(runs, room / kPatchSampleRun);
  for (size_t i = 0; i < take; ++i) {
    const size_t run = take == runs ? i : (2 * i + 1) * runs / (2 * take);
    const size_t end = std::min(others.size(), (run + 1) * kPatchSampleRun);
    for (size_t k = run * kPatchSampleRun; k < end; ++k) out.part[others[k]] = 1, ++out.count;
  }
  out.all = take == runs && keep_features;
  return out;
}

}  // namespace tb::measures
