#include "harness/measures/common/cracks/crack_capture.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/gpu/compute_path.h"
#include "core/gpu/patch_program.h"

namespace tb::measures {
namespace {

// A draw of about this many TES invocations keeps lavapipe's single-threaded tessellator
// out of its super-linear regime (docs/ARCHITECTURE.md §6): 8 patches at level 16 (289
// points each), 1 to 2 at a full level 64.
constexpr uint64_t kInvocationsPerDraw = 4096;
constexpr uint32_t kMaxPatchesPerDraw = 8;

// The compute path's chunk: at most this many bytes of its buffers by the bound below, a
// quarter of lavapipe's storage buffer range (128 MiB; GPUs allow more).
constexpr uint64_t kComputeChunkBytes = 32ull << 20;

// An upper bound on one patch's compute-path buffer bytes under `levels`, as its tessellator
// sizes them (core/gpu/compute_tessellator.cpp): per axis ceil(level) + 3 points (67 under pow2
// spacing, whose rounding it does not model), the four edges and the inner grid; each point
// 8 bytes of coordinates, 6 index words of 4 bytes and a 40-byte vertex record.
uint64_t computeBound(const tess::Levels& levels, tess::Spacing spacing) {
  const auto axis = [&](float level) -> uint64_t {
    if (spacing == tess::Spacing::kPow2 || !(level <= 64.0f)) return 67;
    return uint64_t(std::ceil(std::max(level, 2.0f))) + 3;
  };
  const uint64_t points = axis(levels.outer[0]) + axis(levels.outer[1]) + axis(levels.outer[2]) +
                          axis(levels.outer[3]) + axis(levels.inner[0]) * axis(levels.inner[1]);
  return 72 * points;
}

techniques::PatchDomain patchDomain(tess::Domain domain) {
  return domain == tess::Domain::kQuad ? techniques::PatchDomain::kQuad
                                       : techniques::PatchDomain::kTriangle;
}

// Program patch i's SurfacePatches patch.
uint32_t surfacePatch(const gpu::GpuPatchProgram& program, uint32_t i) {
  return program.patch_ids.empty() ? i : program.patch_ids.at(i);
}

class ProgramCapture {
 public:
  ProgramCapture(const techniques::SurfacePatches& patches, const PatchBoundaries& boundaries,
                 tess::Spacing spacing, std::span<const tess::Levels> patch_levels,
                 const CrackCaptureOptions& options, BoundaryCapture* capture,
                 std::vector<uint8_t>* filled)
      : patches_(patches),
        boundaries_(boundaries),
        spacing_(spacing),
        patch_levels_(patch_levels),
        options_(options),
        capture_(capture),
        filled_(filled) {}

  void run(const gpu::GpuPatchProgram& program, gpu::Context& context) {
    const techniques::PatchDomain domain = patchDomain(program.domain);
    std::vector<tess::Levels> levels(program.patch_count);
    std::vector<uint64_t> boundary_points(program.patch_count);
    uint64_t max_points = 1;
    for (uint32_t i = 0; i < program.patch_count; ++i) {
      const uint32_t patch = surfacePatch(program, i);
      checkPatch(program, patch, domain);
      const BoundaryTessellation& t = boundaries_.of(patch);
      levels[i] = options_.lower_inner_levels ? t.capture_levels : patch_levels_[patch];
      boundary_points[i] = t.points.size();
      const uint64_t points = options_.lower_inner_levels ? t.capture_points : t.tessellated_points;
      max_points = std::max(max_points, points);
      capture_->tes_invocations += points;
    }
    gpu::PatchProgramOptions run;
    run.spacing = spacing_;
    run.boundary_only = true;
    run.sort = false;  // store() indexes each vertex and checks a duplicate against its slot
    run.statistics = false;
    run.skip_culled = true;  // the crack sample's left-out patches
    run.patches_per_draw =
        uint32_t(std::clamp<uint64_t>(kInvocationsPerDraw / max_points, 1, kMaxPatchesPerDraw));
    // The compute path holds every point of a chunk (not the boundary alone), in buffers its
    // tessellator sizes by each patch's largest level: its chunks are cut by that bound.
    std::vector<uint64_t> chunk_cost(boundary_points);
    uint64_t chunk_budget = options_.max_vertices_per_call;
    if (options_.compute_path) {
      for (uint32_t i = 0; i < program.patch_count; ++i)
        chunk_cost[i] = computeBound(levels[i], spacing_);
      chunk_budget = kComputeChunkBytes;
    }
    for (uint32_t first = 0; first < program.patch_count;) {
      uint64_t cost = 0;
      uint32_t end = first;
      while (end < program.patch_count &&
             (end == first || cost + chunk_cost[end] <= chunk_budget)) {
        cost += chunk_cost[end++];
      }
      if (options_.compute_path) {
        storeComputed(program, runComputeChunk(context, program, levels, first, end), domain);
      } else {
        run.first_patch = first;
        run.patch_count = end - first;
        store(program, gpu::runPatchProgram(context, program, levels, run), domain);
      }
      first = end;
    }
  }

 private:
  // The compute path over program patches [first, end): the others get zero levels (culled,
  // no points; the compute tessellator counts them and moves on).
  gpu::ComputePathResult runComputeChunk(gpu::Context& context, const gpu::GpuPatchProgram& program,
                                         const std::vector<tess::Levels>& levels, uint32_t first,
                                         uint32_t end) const {
    std::vector<tess::Levels> chunk(levels.size(), tess::Levels{{0, 0, 0, 0}, {0, 0}});
    std::copy(levels.begin() + first, levels.begin() + end, chunk.begin() + first);
    gpu::ComputePathOptions run;
    run.spacing = spacing_;
    run.draw = false;
    return gpu::runComputePath(context, program, chunk, run);
  }

  // The compute path evaluates every domain point: keep those on the patch boundary (what
  // the TES capture's boundary_only keeps), stored like a TES capture.
  void storeComputed(const gpu::GpuPatchProgram& program, const gpu::ComputePathResult& result,
                     techniques::PatchDomain domain) {
    gpu::PatchProgramCapture run;
    run.submit_to_fence_s = result.submit_to_fence_s;
    run.draws = 1;
    for (const gpu::CapturedVertex& v : result.vertices) {
      if (onPatchBoundary(v.coord, domain)) run.vertices.push_back(v);
    }
    store(program, run, domain);
  }

  // gl_TessCoord on an edge or a corner: exactly 0 or 1 (quads: u or v; triangles: a
  // barycentric 0), as patch_program_tes.glsl's tbOnPatchBoundary decides.
  static bool onPatchBoundary(const tess::DomainPoint& c, techniques::PatchDomain domain) {
    if (domain == techniques::PatchDomain::kQuad) {
      return c[0] == 0.0f || c[0] == 1.0f || c[1] == 0.0f || c[1] == 1.0f;
    }
    return c[0] == 0.0f || c[1] == 0.0f || c[2] == 0.0f;
  }

  void checkPatch(const gpu::GpuPatchProgram& program, uint32_t patch,
                  techniques::PatchDomain domain) const {
    if (patch >= patches_.patchCount() || boundaries_.domain[patch] != domain) {
      throw std::runtime_error("cracks: " + program.evaluation_shader + " draws patch " +
                               std::to_string(patch) + ", which is not a patch of its domain");
    }
  }

  void store(const gpu::GpuPatchProgram& program, const gpu::PatchProgramCapture& run,
             techniques::PatchDomain domain) {
    capture_->submit_to_fence_s += run.submit_to_fence_s;
    capture_->draws += run.draws;
    ++capture_->calls;
    for (const gpu::CapturedVertex& v : run.vertices) {
      const int64_t k = boundaries_.of(v.patch).indexOf(domain, v.coord);
      if (k < 0) {
        throw std::runtime_error("cracks: " + program.evaluation_shader + " captured patch " +
                                 std::to_string(v.patch) +
                                 " at a boundary point the CPU tessellator does not emit");
      }
      // The tessellator may emit two vertices on one 2^-16 coordinate (fractional spacing
      // just above an integer level); the CPU list keeps both, next to each other, and
      // one captured position fills them all.
      const BoundaryTessellation& b = boundaries_.of(v.patch);
      for (size_t j = size_t(k);
           j < b.points.size() && std::memcmp(&b.points[j], &v.coord, sizeof(v.coord)) == 0; ++j) {
        const size_t slot = boundaries_.at(v.patch, j);
        if ((*filled_)[slot] == 0) {
          capture_->positions[slot] = v.position;
          (*filled_)[slot] = 1;
          ++capture_->points_captured;
        } else if (std::memcmp(&capture_->positions[slot], &v.position, sizeof(mesh::Vec3f)) != 0) {
          // The TES ran twice at one gl_TessCoord (fractional spacing) and disagreed.
          throw std::runtime_error("cracks: " + program.evaluation_shader + " captured patch " +
                                   std::to_string(v.patch) +
                                   " twice at one boundary point with different positions");
        }
      }
    }
  }

  const techniques::SurfacePatches& patches_;
  const PatchBoundaries& boundaries_;
  tess::Spacing spacing_;
  std::span<const tess::Levels> patch_levels_;
  const CrackCaptureOptions& options_;
  BoundaryCapture* capture_;
  std::vector<uint8_t>* filled_;
};

}  // namespace

BoundaryCapture captureBoundaryPositions(const techniques::SurfacePatches& patches,
                                         std::span<const gpu::GpuPatchProgram> programs,
                                         const PatchBoundaries& boundaries, tess::Spacing spacing,
                                         std::span<const tess::Levels> patch_levels,
                                         gpu::Context& context,
                                         const CrackCaptureOptions& options) {
  if (patch_levels.size() != patches.patchCount()) {
    throw std::invalid_argument("cracks: capture needs one level set per patch");
  }
  BoundaryCapture capture;
  capture.positions.resize(boundaries.size());
  std::vector<uint8_t> filled(boundaries.size(), 0);
  ProgramCapture run(patches, boundaries, spacing, patch_levels, options, &capture, &filled);
  std::string shaders;
  for (const gpu::GpuPatchProgram& program : programs) {
    run.run(program, context);
    shaders += (shaders.empty() ? "" : ", ") + program.evaluation_shader;
  }
  if (std::find(filled.begin(), filled.end(), 0) != filled.end()) {
    throw std::runtime_error(
        "cracks: the GPU capture lacks boundary points the CPU tessellator emits (" + shaders +
        ")");
  }
  return capture;
}

}  // namespace tb::measures
