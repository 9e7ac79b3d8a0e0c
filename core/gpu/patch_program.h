// Runs a technique's own tessellation shaders (TCS + TES) on the Vulkan device and captures
// what its TES computes (position, normal, exact gl_TessCoord bits) at every domain point, or
// only on the patch boundary (what the crack measure pairs), so the CPU float evaluation can
// be compared in ulps and shared points bitwise. The binding contract (capture at set 0,
// binding 0; storage buffers 1..N; per-patch levels at set 1, binding 0; constant 200 the
// harness's) is in shaders/common/patch_program.glsl; why draws are small and capture is by
// SSBO: docs/ARCHITECTURE.md §6. Thread-safe: each call has its own capture buffer, query
// pool and descriptor sets; pipelines are shared; submissions take turns on the queue.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/gpu/patch_program_desc.h"
#include "core/gpu/tess_capture.h"
#include "core/mesh/vec.h"
#include "core/tess/tessellator.h"
#include "shaders/common/layout/capture_record.h"
#include "shaders/common/layout/cull_layout.h"
#include "shaders/common/layout/factor_layout.h"

namespace tb::gpu {

struct CapturedVertex {
  uint32_t patch = 0;         // SurfacePatches patch (GpuPatchProgram::patch_ids applied)
  tess::DomainPoint coord{};  // gl_TessCoord bit for bit
  mesh::Vec3f position;
  mesh::Vec3f normal;
};

// A view-dependent factor policy computed by the program's own TCS
// (shaders/common/tess_factors.glsl) in place of the harness's levels. Plain words; the
// CPU twin that packs them is harness/lod/factor_policy.h.
struct TcsFactorPolicy {
  // Per program patch, 64 words (float bits): 4 corners of 8 words (position xyzw, normal
  // xyzw), then the error_bound policy's 4 edge spheres, edge bounds, patch sphere, inner
  // bound and a pad vec4 (harness/lod/error_bound.h): TbFactorPatches at set 1, binding 1.
  std::vector<uint32_t> corner_words;
  std::vector<uint32_t> param_words;  // TbFactorParamsBlock at set 1, binding 2
};

// A culling policy run by the program's own TCS (shaders/common/cull.glsl): culled patches
// get outer level 0. Plain words; the CPU twin that packs them is
// harness/lod/cull_policy.h.
struct TcsCullPolicy {
  std::vector<uint32_t> param_words;  // TbCullParamsBlock at set 1, binding 4
  // Per program patch, kTcsCullPatchWords words: TbCullPatches at set 1, binding 5.
  std::vector<uint32_t> patch_words;
  // The tangent_plane policy's coefficients, 4 words each, that TbCullPatch::tangent
  // indexes: TbCullTangentPlanes at set 1, binding 6 (may be empty).
  std::vector<uint32_t> tangent_words;
};
inline constexpr size_t kTcsCullPatchWords = layout::kWordsOf<layout::TbCullPatch>;
inline constexpr size_t kTcsCullParamWords = layout::kWordsOf<layout::TbCullParamsBlock>;
// Words per program patch of TcsFactorPolicy::corner_words (TbFactorPatch).
inline constexpr size_t kTcsFactorPatchWords = layout::kWordsOf<layout::TbFactorPatch>;

struct PatchProgramCapture {
  // Sorted by (patch, coord bits), so the order does not depend on the device's
  // invocation order; duplicates (same patch, same coord) are kept once. Unless
  // PatchProgramOptions::sort is false: then in capture order, duplicates kept.
  std::vector<CapturedVertex> vertices;
  PipelineStatistics stats;      // summed over all draws
  double submit_to_fence_s = 0;  // host seconds over all submissions
  uint32_t draws = 0;
  // With PatchProgramOptions::factor_policy or cull_policy: the levels the TCS wrote, per program
  // patch (patches outside the call's range stay 0), float bits outer[0..3], inner[0..1].
  std::vector<tess::LevelsBits> tcs_levels;
};

struct PatchProgramOptions {
  tess::Spacing spacing = tess::Spacing::kInteger;
  uint32_t first_patch = 0;
  uint32_t patch_count = UINT32_MAX;  // clamped to the program's
  uint32_t patches_per_draw = 1;
  bool capture = true;  // false: time the shaders alone (no SSBO writes)
  // With capture: keep only the TES invocations whose gl_TessCoord lies on the patch
  // boundary (an edge or a corner of the quad or triangle; isolines have none). The
  // shaders run as without it; only the SSBO writes and the host's reading shrink.
  bool boundary_only = false;
  // false: leave the vertices in capture order with duplicates, for callers that index
  // them by (patch, coord) themselves (the crack measure) and need no sort.
  bool sort = true;
  // false: no pipeline-statistics query (stats stay 0). Reading one back costs lavapipe
  // about 40 us a call (it synchronises with its queue), more than a small draw.
  bool statistics = true;
  // true: patches whose levels cull them (an outer level <= 0) are not drawn at all (their
  // TCS does not run either); false: they are drawn and culled by the tessellator, as a
  // renderer's would be (the statistics count their TCS invocations).
  bool skip_culled = false;
  // Non-null: the TCS computes its own levels with this policy (kTbFactorPolicy = 1), and
  // the call returns them (tcs_levels). patch_levels are then only the expected levels,
  // which size the capture: pass the CPU twin's. Its corner_words must hold kTcsFactorPatchWords
  // per program patch.
  const TcsFactorPolicy* factor_policy = nullptr;
  // Non-null: the TCS culls with this policy (kTbCullPolicy = 1) and the call returns the
  // levels it wrote (tcs_levels; a culled patch has outer levels 0). Its patch_words must
  // hold kTcsCullPatchWords words per program patch.
  const TcsCullPolicy* cull_policy = nullptr;
};

// Words per captured vertex (shaders/common/layout/capture_record.h TbCaptureRecord).
inline constexpr uint32_t kCaptureRecordWords = layout::kWordsOf<layout::TbCaptureRecord>;

// Appends the vertices of `words`, the capture's 10-word records (patch_program_tes.glsl:
// program patch, gl_TessCoord bits (3), position (3), normal (3)), with the program patch
// mapped through patch_ids (empty: unchanged). Defined in capture_records.cpp.
void appendCaptureRecords(std::span<const uint32_t> words, std::span<const uint32_t> patch_ids,
                          std::vector<CapturedVertex>* vertices);
// Sorts by (patch, coord bits) and keeps one vertex of each (PatchProgramCapture's order).
void sortUniqueVertices(std::vector<CapturedVertex>* vertices);

// Per-patch levels: patch_levels[i] are program patch i's levels (tbPatchIndex(), before
// GpuPatchProgram::patch_ids is applied), one per program patch. The TCS writes them
// bit for bit (pow2 spacing: after tess::roundPow2Levels, as the CPU tessellator does).
// Throws GpuError when the device lacks a needed feature, a shader is not embedded,
// the capture overflows, patch_levels.size() != program.patch_count, or boundary_only is
// asked of an isoline program.
PatchProgramCapture runPatchProgram(Context& context, const GpuPatchProgram& program,
                                    std::span<const tess::Levels> patch_levels,
                                    const PatchProgramOptions& options = {});

// Uniform levels: the same `levels` for every patch.
PatchProgramCapture runPatchProgram(Context& context, const GpuPatchProgram& program,
                                    const tess::Levels& levels,
                                    const PatchProgramOptions& options = {});

}  // namespace tb::gpu
