// The device's words for the culling policies (cull_policy.h): TbCullParamsBlock, and per
// program patch TbCullPatch and its tangent-plane coefficients, as the shared layout
// shaders/common/layout/cull_layout.h defines them (cull.glsl includes it too).
#include <bit>

#include "harness/lod/cull_policy.h"
#include "shaders/common/layout/cull_layout.h"

namespace tb::lod {
namespace {

using gpu::layout::vec4;
static_assert(kCullHullPoints == gpu::layout::kTbCullHullPoints);

vec4 vec(const mesh::Vec3f& v, float w) { return {v[0], v[1], v[2], w}; }
vec4 vec(const std::array<float, 4>& v) { return {v[0], v[1], v[2], v[3]}; }

}  // namespace

gpu::TcsCullPolicy tcsCullPolicy(const CullParams& params, const CullBounds& bounds,
                                 const gpu::GpuPatchProgram& program) {
  gpu::TcsCullPolicy policy = cullPatchData(bounds, program);
  policy.param_words = cullParamWords(params);
  return policy;
}

std::vector<uint32_t> cullParamWords(const CullParams& params) {
  gpu::layout::TbCullParamsBlock block{};
  for (size_t k = 0; k < params.planes.size(); ++k) block.planes[k] = vec(params.planes[k]);
  block.eye = vec(params.eye, 0);
  block.global_margin = params.global_margin;
  block.policy = uint32_t(params.policy);
  block.chord_factors = vec(params.chord_factors);
  std::vector<uint32_t> words;
  gpu::layout::appendWords(words, block);
  return words;
}

gpu::TcsCullPolicy cullPatchData(const CullBounds& bounds, const gpu::GpuPatchProgram& program) {
  gpu::TcsCullPolicy data;
  data.patch_words.reserve(size_t(program.patch_count) * gpu::kTcsCullPatchWords);
  for (uint32_t i = 0; i < program.patch_count; ++i) {
    const size_t p = program.patch_ids.empty() ? i : program.patch_ids[i];
    const CullPatchBounds& b = bounds.patches.at(p);
    gpu::layout::TbCullPatch record{};
    for (int c = 0; c < 4; ++c) {
      record.corner_position[c] = vec(b.corner_position[c], b.corner_margin[c]);
      record.corner_normal[c] = vec(b.corner_normal[c], 0);
    }
    record.cone = vec(b.cone_axis, b.cone_sine);
    record.header = {b.corner_count, uint32_t(b.hull.size()),
                     std::bit_cast<uint32_t>(b.displacement_bound), 0};
    record.tangent = {uint32_t(data.tangent_words.size() / 4), uint32_t(b.tangent_plane.size()),
                      std::bit_cast<uint32_t>(b.tangent_normal_max),
                      std::bit_cast<uint32_t>(b.tangent_offset_max)};
    record.tangent_chord = {b.tangent_reach, b.tangent_first_times_second, b.tangent_second_squared,
                            0};
    for (size_t h = 0; h < kCullHullPoints && h < b.hull.size(); ++h) {
      record.hull[h] = vec(b.hull[h], 0);
    }
    gpu::layout::appendWords(data.patch_words, record);
    for (const std::array<float, 4>& c : b.tangent_plane) {
      for (float v : c) data.tangent_words.push_back(std::bit_cast<uint32_t>(v));
    }
  }
  return data;
}

}  // namespace tb::lod
