#include "core/gpu/compute_tessellator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "core/gpu/context.h"
#include "core/gpu/gpu_error.h"
#include "core/tess/fixed_point.h"
#include "shaders/common/layout/bindings.h"

namespace tb::gpu {
namespace {

constexpr uint32_t kGroupSize = 64;  // tessellate.comp's local_size_x

// Points an edge or inside axis of this level can have: a processed level L in [1, 64]
// gives at most ceil(L) + 3 points (edge_spacing.cpp point_count; an odd inside level's
// raise to 4 included, as L >= 1 there); pow2 rounds up to a power of two first, and NaN
// or +inf clamp to the top.
uint64_t axisPointBound(float level, tess::Spacing spacing) {
  if (spacing == tess::Spacing::kPow2 || !(level <= 64.0f)) return 67;
  return static_cast<uint64_t>(std::ceil(std::max(level, 2.0f))) + 3;
}

// Upper bounds of a patch's points and index words: the boundary plus the full inside
// grid; a triangulated disc has fewer than two triangles a point (T = 2V - B - 2).
std::array<uint64_t, 2> patchBounds(const TessPatch& patch) {
  const auto& l = patch.levels;
  // A culled patch (an outer level of its domain not > 0, NaN included) has no points.
  const int edges = patch.domain == tess::Domain::kQuad       ? 4
                    : patch.domain == tess::Domain::kTriangle ? 3
                                                              : 2;
  for (int e = 0; e < edges; ++e) {
    if (!(l.outer[e] > 0.0f)) return {0, 0};
  }
  auto b = [&](float level) { return axisPointBound(level, patch.spacing); };
  switch (patch.domain) {
    case tess::Domain::kTriangle: {
      const uint64_t points =
          b(l.outer[0]) + b(l.outer[1]) + b(l.outer[2]) + b(l.inner[0]) * b(l.inner[0]);
      return {points, 6 * points};
    }
    case tess::Domain::kQuad: {
      const uint64_t points = b(l.outer[0]) + b(l.outer[1]) + b(l.outer[2]) + b(l.outer[3]) +
                              b(l.inner[0]) * b(l.inner[1]);
      return {points, 6 * points};
    }
    case tess::Domain::kIsoline:
      break;
  }
  const uint64_t points = axisPointBound(l.outer[0], tess::Spacing::kInteger) * b(l.outer[1]);
  return {points, 2 * points};
}

uint64_t storageBufferRange(Context& context) {
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(context.physicalDevice(), &properties);
  return properties.limits.maxStorageBufferRange;
}

// Appends one batch's output to another's, moving its offsets and indices along.
void append(ComputeTessellation part, ComputeTessellation* out) {
  const auto points = static_cast<uint32_t>(out->points.size());
  const auto indices = static_cast<uint32_t>(out->indices.size());
  for (TessPatchRange range : part.patches) {
    range.first_point += points;
    range.first_index += indices;
    out->patches.push_back(range);
  }
  out->points.insert(out->points.end(), part.points.begin(), part.points.end());
  for (uint32_t index : part.indices) out->indices.push_back(index + points);
}

GpuComputeBuffer buffer(uint32_t binding, const char* name, uint64_t size_bytes) {
  GpuComputeBuffer b;
  b.binding = binding;
  b.name = name;
  b.size_bytes = std::max<uint64_t>(size_bytes, 16);
  return b;
}

}  // namespace

void appendTessPatchRecord(std::vector<uint32_t>& words, const TessPatch& patch) {
  layout::TbTessPatchRecord record{};
  for (size_t j = 0; j < 4; ++j)
    record.outer_bits[j] = std::bit_cast<uint32_t>(patch.levels.outer[j]);
  for (size_t j = 0; j < 2; ++j)
    record.inner_bits[j] = std::bit_cast<uint32_t>(patch.levels.inner[j]);
  record.code = static_cast<uint32_t>(patch.domain) | (static_cast<uint32_t>(patch.spacing) << 8);
  record.flags = (patch.options.ccw ? 0u : 1u) | (patch.options.point_mode ? 2u : 0u) |
                 (patch.rounding_up_control ? 4u : 0u);
  layout::appendWords(words, record);
}

ComputeTessellationPasses describeTessellationPasses(Context& context,
                                                     std::span<const TessPatch> patches,
                                                     bool counts_only) {
  ComputeTessellationPasses out;
  std::vector<uint32_t> words;
  words.reserve(patches.size() * kTessPatchRecordWords);
  for (const TessPatch& patch : patches) {
    appendTessPatchRecord(words, patch);
    if (counts_only) continue;
    const auto bounds = patchBounds(patch);
    out.point_capacity += bounds[0];
    out.index_capacity += bounds[1];
  }
  const uint64_t range = storageBufferRange(context);
  if (8 * out.point_capacity > range || 4 * out.index_capacity > range) {
    throw GpuError("compute tessellator: a batch of " + std::to_string(patches.size()) +
                   " patches may need " + std::to_string(4 * out.index_capacity) +
                   " bytes of indices, over the device's storage buffer range of " +
                   std::to_string(range) + "; split the batch");
  }
  const uint64_t n = patches.size();
  static_assert(layout::kBindingTessPatchRecords == 0);  // the buffers below are in binding order
  std::vector<GpuComputeBuffer> buffers = {buffer(0, kTessPatchRecords, 4 * words.size()),
                                           buffer(1, "counts", 16 * n),
                                           buffer(2, "offsets", 8 * n),
                                           buffer(3, "status", 16),
                                           buffer(4, "points", 8 * out.point_capacity),
                                           buffer(5, "indices", 4 * out.index_capacity)};
  buffers[0].initial_words = std::move(words);

  const auto patch_count = static_cast<uint32_t>(n);
  const uint32_t groups = std::max<uint32_t>(1, (patch_count + kGroupSize - 1) / kGroupSize);
  const std::vector<uint32_t> push = {patch_count, static_cast<uint32_t>(out.point_capacity),
                                      static_cast<uint32_t>(out.index_capacity)};
  auto pass = [&](const char* shader, std::vector<uint32_t> specialization,
                  std::vector<uint32_t> push_words, uint32_t groups_x) {
    GpuComputePass p;
    p.shader = shader;
    p.buffers = buffers;
    p.specialization = std::move(specialization);
    p.push_constants = std::move(push_words);
    p.groups_x = groups_x;
    return p;
  };
  out.passes = {pass("gpu/tessellate.comp", {0}, push, groups),
                pass("gpu/tess_scan.comp", {}, {patch_count}, 1)};
  if (!counts_only) out.passes.push_back(pass("gpu/tessellate.comp", {1}, push, groups));
  return out;
}

ComputeTessellator::ComputeTessellator(Context& context, std::span<const TessPatch> patches)
    : ComputeTessellator(context, patches, {}) {}

ComputeTessellator::ComputeTessellator(Context& context, std::span<const TessPatch> patches,
                                       std::vector<GpuComputePass> prologue, bool counts_only)
    : patch_count_(static_cast<uint32_t>(patches.size())), counts_only_(counts_only) {
  ComputeTessellationPasses passes = describeTessellationPasses(context, patches, counts_only);
  point_capacity_ = passes.point_capacity;
  index_capacity_ = passes.index_capacity;
  std::vector<GpuComputeProgram> programs;
  if (!prologue.empty()) programs.push_back({"levels", std::move(prologue)});
  programs.push_back({"tessellate", std::move(passes.passes)});
  runner_ = std::make_unique<ComputeRunner>(context, programs);
}

ComputeTessellator::~ComputeTessellator() = default;

ComputeRunTiming ComputeTessellator::run() { return runner_->run(1); }

ComputeTessellation ComputeTessellator::read() const {
  const std::vector<uint32_t> status = runner_->read("status");
  if (status[2] != 0) {
    throw GpuError("compute tessellator: the kernels raised error bits " +
                   std::to_string(status[2]) +
                   " (1 bad domain/spacing code, 2/4 a buffer bound, 8 write pass != count pass)");
  }
  const std::vector<uint32_t> counts = runner_->read("counts");
  const std::vector<uint32_t> offsets = runner_->read("offsets");
  const std::vector<uint32_t> points =
      counts_only_ ? std::vector<uint32_t>{} : runner_->read("points", 0, 2 * uint64_t(status[0]));
  std::vector<uint32_t> indices =
      counts_only_ ? std::vector<uint32_t>{} : runner_->read("indices", 0, status[1]);
  ComputeTessellation out;
  out.patches.resize(patch_count_);
  for (size_t p = 0; p < patch_count_; ++p) {
    out.patches[p] = {offsets[2 * p], counts[4 * p], offsets[2 * p + 1], counts[4 * p + 1],
                      counts[4 * p + 2] != 0};
  }
  out.points.resize(points.size() / 2);
  for (size_t i = 0; i < out.points.size(); ++i) out.points[i] = {points[2 * i], points[2 * i + 1]};
  out.indices = std::move(indices);
  return out;
}

std::vector<uint32_t> ComputeTessellator::readBuffer(const std::string& name) const {
  return runner_->read(name);
}

ComputeTessellation tessellateOnCompute(Context& context, std::span<const TessPatch> patches) {
  const uint64_t range = storageBufferRange(context);
  ComputeTessellation out;
  for (size_t first = 0, end = 0; first < patches.size(); first = end) {
    uint64_t points = 0, indices = 0;
    for (end = first; end < patches.size(); ++end) {
      const auto bounds = patchBounds(patches[end]);
      points += bounds[0];
      indices += bounds[1];
      if (end > first && (8 * points > range || 4 * indices > range)) break;
    }
    ComputeTessellator tessellator(context, patches.subspan(first, end - first));
    tessellator.run();
    append(tessellator.read(), &out);
  }
  return out;
}

tess::Tessellation toTessellation(const ComputeTessellation& batch, size_t patch,
                                  tess::Domain domain) {
  const TessPatchRange& range = batch.patches.at(patch);
  tess::Tessellation out;
  out.culled = range.culled;
  for (uint32_t i = 0; i < range.point_count; ++i) {
    const auto& [u, v] = batch.points[range.first_point + i];
    const float uf = tess::fxp::toFloat(u), vf = tess::fxp::toFloat(v);
    out.points.push_back({uf, vf, domain == tess::Domain::kTriangle ? (1.0f - uf) - vf : 0.0f});
  }
  const uint32_t* index = batch.indices.data() + range.first_index;
  if (domain == tess::Domain::kIsoline) {
    for (uint32_t k = 0; k + 1 < range.index_count; k += 2) {
      out.lines.push_back({index[k] - range.first_point, index[k + 1] - range.first_point});
    }
  } else {
    for (uint32_t k = 0; k + 2 < range.index_count; k += 3) {
      out.triangles.push_back({index[k] - range.first_point, index[k + 1] - range.first_point,
                               index[k + 2] - range.first_point});
    }
  }
  return out;
}

}  // namespace tb::gpu
