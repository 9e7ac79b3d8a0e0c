// The device's words for the culling policies (cull_policy.h): TbCullParamsBlock, and per
// program patch TbCullPatch and its tangent-plane coefficients (shaders/common/cull.glsl).
#include <bit>

#include "harness/lod/cull_policy.h"

namespace tb::lod {
namespace {

constexpr size_t kParamWords = 36;  // TbCullParamsBlock, std430

void putFloat(std::vector<uint32_t>& words, float value) {
  words.push_back(std::bit_cast<uint32_t>(value));
}
void putVec(std::vector<uint32_t>& words, const mesh::Vec3f& v, float w) {
  for (int i = 0; i < 3; ++i) putFloat(words, v[i]);
  putFloat(words, w);
}

}  // namespace

gpu::TcsCullPolicy tcsCullPolicy(const CullParams& params, const CullBounds& bounds,
                                 const gpu::GpuPatchProgram& program) {
  gpu::TcsCullPolicy policy = cullPatchData(bounds, program);
  policy.param_words = cullParamWords(params);
  return policy;
}

std::vector<uint32_t> cullParamWords(const CullParams& params) {
  std::vector<uint32_t> words;
  words.reserve(kParamWords);
  for (const std::array<float, 4>& plane : params.planes) {
    for (float v : plane) putFloat(words, v);
  }
  putVec(words, params.eye, 0);
  putFloat(words, params.global_margin);
  words.push_back(uint32_t(params.policy));
  words.push_back(0);
  words.push_back(0);
  for (float k : params.chord_factors) putFloat(words, k);
  return words;
}

gpu::TcsCullPolicy cullPatchData(const CullBounds& bounds, const gpu::GpuPatchProgram& program) {
  gpu::TcsCullPolicy data;
  std::vector<uint32_t>& words = data.patch_words;
  words.reserve(size_t(program.patch_count) * gpu::kTcsCullPatchWords);
  for (uint32_t i = 0; i < program.patch_count; ++i) {
    const size_t p = program.patch_ids.empty() ? i : program.patch_ids[i];
    const CullPatchBounds& b = bounds.patches.at(p);
    for (int c = 0; c < 4; ++c) putVec(words, b.corner_position[c], b.corner_margin[c]);
    for (int c = 0; c < 4; ++c) putVec(words, b.corner_normal[c], 0);
    putVec(words, b.cone_axis, b.cone_sine);
    words.push_back(b.corner_count);
    words.push_back(uint32_t(b.hull.size()));
    putFloat(words, b.displacement_bound);
    words.push_back(0);
    words.push_back(uint32_t(data.tangent_words.size() / 4));
    words.push_back(uint32_t(b.tangent_plane.size()));
    putFloat(words, b.tangent_normal_max);
    putFloat(words, b.tangent_offset_max);
    putFloat(words, b.tangent_reach);
    putFloat(words, b.tangent_first_times_second);
    putFloat(words, b.tangent_second_squared);
    words.push_back(0);
    for (size_t h = 0; h < kCullHullPoints; ++h) {
      putVec(words, h < b.hull.size() ? b.hull[h] : mesh::Vec3f{0, 0, 0}, 0);
    }
    for (const std::array<float, 4>& c : b.tangent_plane) {
      for (float v : c) putFloat(data.tangent_words, v);
    }
  }
  return data;
}

}  // namespace tb::lod
