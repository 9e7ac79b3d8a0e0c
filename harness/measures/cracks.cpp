#include "harness/measures/cracks.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>

#include "core/gpu/patch_program.h"
#include "core/mesh/topology.h"

namespace tb {
namespace {

constexpr int64_t kFixedOne = 1 << 16;  // the tessellator's 16.16 fixed point

uint32_t cornerCount(PatchDomain domain) { return domain == PatchDomain::kQuad ? 4 : 3; }

// The domain points of one patch that lie on its boundary, in a fixed order: corners
// first (index = corner), then each local edge's interior points by ascending t.
struct BoundaryPoints {
  std::vector<tess::DomainPoint> points;
  // Per local edge: edge parameter in 16.16 -> index into `points`.
  std::vector<std::map<int64_t, uint32_t>> edge_index;
};

tess::Levels uniformLevels(float level) {
  tess::Levels levels;
  levels.outer = {level, level, level, level};
  levels.inner = {level, level};
  return levels;
}

tess::Domain tessDomain(PatchDomain domain) {
  return domain == PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle;
}

BoundaryPoints boundaryPoints(PatchDomain domain, const tess::Tessellation& tessellation) {
  const uint32_t corners = cornerCount(domain);
  BoundaryPoints b;
  b.points.resize(corners);
  std::vector<bool> seen(corners, false);
  b.edge_index.resize(corners);
  std::vector<std::map<int64_t, tess::DomainPoint>> edge_points(corners);
  for (const tess::DomainPoint& p : tessellation.points) {
    for (uint32_t c = 0; c < corners; ++c) {
      if (isDomainCorner(domain, c, p)) {
        b.points[c] = p;
        seen[c] = true;
      }
    }
    for (uint32_t e = 0; e < corners; ++e) {
      const int64_t t = domainEdgeParameter(domain, e, p);
      if (t > 0 && t < kFixedOne) edge_points[e].emplace(t, p);
    }
  }
  if (std::find(seen.begin(), seen.end(), false) != seen.end()) {
    throw std::logic_error("cracks: the tessellation lacks a patch corner");
  }
  for (uint32_t e = 0; e < corners; ++e) {
    for (const auto& [t, p] : edge_points[e]) {
      b.edge_index[e].emplace(t, uint32_t(b.points.size()));
      b.points.push_back(p);
    }
  }
  return b;
}

using CoordBits = std::tuple<uint32_t, uint32_t, uint32_t>;
CoordBits coordBits(const tess::DomainPoint& p) {
  return {std::bit_cast<uint32_t>(p[0]), std::bit_cast<uint32_t>(p[1]),
          std::bit_cast<uint32_t>(p[2])};
}

struct CoordBitsHash {
  size_t operator()(const CoordBits& c) const {
    return std::get<0>(c) * 0x9E3779B1u ^ std::get<1>(c) * 0x85EBCA77u ^ std::get<2>(c);
  }
};

// The boundary points of every patch, from one tessellation per distinct (domain, levels)
// (patches may mix quads and triangles and carry their own levels), and where each
// patch's points start in the flat positions array.
struct PatchBoundaries {
  std::vector<BoundaryPoints> tessellations;  // one per distinct (domain, levels)
  std::vector<size_t> tessellated_points;     // per tessellation: all its points
  std::vector<uint32_t> tessellation;         // per patch: index into tessellations
  std::vector<PatchDomain> domain;            // per patch
  std::vector<size_t> offset;                 // per patch, then the total
  size_t culled_patches = 0;                  // patches whose levels cull them

  const BoundaryPoints& of(size_t patch) const { return tessellations[tessellation[patch]]; }
  size_t at(size_t patch, size_t k) const { return offset[patch] + k; }
};

PatchBoundaries patchBoundaries(const SurfacePatches& patches, tess::Spacing spacing,
                                std::span<const tess::Levels> patch_levels) {
  PatchBoundaries b;
  b.tessellation.resize(patches.patchCount());
  b.domain.resize(patches.patchCount());
  b.offset.assign(patches.patchCount() + 1, 0);
  std::map<std::pair<PatchDomain, tess::LevelsBits>, uint32_t> cache;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const PatchDomain domain = patches.patchDomain(p);
    b.domain[p] = domain;
    const auto key = std::make_pair(domain, tess::levelsBits(patch_levels[p]));
    auto found = cache.find(key);
    if (found == cache.end()) {
      const tess::Tessellation tessellation =
          tess::tessellate(tessDomain(domain), spacing, patch_levels[p]);
      // A culled tessellation has no points; an empty entry keeps the indices aligned.
      b.tessellations.push_back(tessellation.culled ? BoundaryPoints{}
                                                    : boundaryPoints(domain, tessellation));
      b.tessellated_points.push_back(tessellation.points.size());
      found = cache.emplace(key, uint32_t(b.tessellations.size() - 1)).first;
    }
    b.tessellation[p] = found->second;
    if (b.tessellations[found->second].points.empty()) ++b.culled_patches;
    b.offset[p + 1] = b.offset[p] + b.tessellations[found->second].points.size();
  }
  return b;
}

// Positions at every boundary point of every patch: [boundaries.at(patch, k)].
using BoundaryPositions = std::vector<Vec3f>;

BoundaryPositions cpuPositions(const SurfacePatches& patches, const PatchBoundaries& boundaries) {
  BoundaryPositions positions(boundaries.offset.back());
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const std::vector<tess::DomainPoint>& points = boundaries.of(p).points;
    for (size_t k = 0; k < points.size(); ++k) {
      positions[boundaries.at(p, k)] = patches.evaluateFloat(p, points[k]).position;
    }
  }
  return positions;
}

using CoordIndex = std::unordered_map<CoordBits, uint32_t, CoordBitsHash>;

// Per tessellation of `domain`: domain point bits -> index into its boundary points.
std::vector<CoordIndex> coordIndices(const PatchBoundaries& boundaries, PatchDomain domain) {
  std::vector<CoordIndex> indices(boundaries.tessellations.size());
  std::vector<uint8_t> used(boundaries.tessellations.size(), 0);
  for (size_t p = 0; p < boundaries.domain.size(); ++p) {
    if (boundaries.domain[p] == domain) used[boundaries.tessellation[p]] = 1;
  }
  for (size_t t = 0; t < indices.size(); ++t) {
    if (!used[t]) continue;
    const std::vector<tess::DomainPoint>& points = boundaries.tessellations[t].points;
    for (size_t k = 0; k < points.size(); ++k)
      indices[t].emplace(coordBits(points[k]), uint32_t(k));
  }
  return indices;
}

// The program's patches' levels, by program patch (GpuPatchProgram::patch_ids).
std::vector<tess::Levels> programLevels(const gpu::GpuPatchProgram& program,
                                        std::span<const tess::Levels> patch_levels) {
  std::vector<tess::Levels> levels(program.patch_count);
  for (uint32_t i = 0; i < program.patch_count; ++i) {
    levels[i] = patch_levels[program.patch_ids.empty() ? i : program.patch_ids.at(i)];
  }
  return levels;
}

float maxLevel(std::span<const tess::Levels> levels) {
  float max_level = 0;
  for (const tess::Levels& l : levels) {
    max_level = std::max(
        {max_level, l.outer[0], l.outer[1], l.outer[2], l.outer[3], l.inner[0], l.inner[1]});
  }
  return max_level;
}

// Runs `program` over its patches and stores the captured boundary points in `positions`.
void gpuPositions(const SurfacePatches& patches, const gpu::GpuPatchProgram& program,
                  const PatchBoundaries& boundaries, tess::Spacing spacing,
                  std::span<const tess::Levels> patch_levels, gpu::Context& context,
                  BoundaryPositions* positions, std::vector<uint8_t>* filled,
                  CrackFigures* figures) {
  const PatchDomain domain =
      program.domain == tess::Domain::kQuad ? PatchDomain::kQuad : PatchDomain::kTriangle;
  const std::vector<CoordIndex> indices = coordIndices(boundaries, domain);
  size_t points_per_patch = 0;
  for (size_t p = 0; p < boundaries.domain.size(); ++p) {
    if (boundaries.domain[p] != domain) continue;
    points_per_patch =
        std::max(points_per_patch, boundaries.tessellated_points[boundaries.tessellation[p]]);
  }
  const std::vector<tess::Levels> levels = programLevels(program, patch_levels);

  // Chunks of about a million captured vertices bound the capture buffer; a few
  // patches per draw keep lavapipe's single-threaded tessellator out of its
  // super-linear regime (docs/ARCHITECTURE.md §6).
  const uint32_t patch_count = uint32_t(patches.patchCount());
  const uint32_t chunk =
      uint32_t(std::clamp<size_t>((1u << 20) / std::max<size_t>(points_per_patch, 1), 1, 4096));
  gpu::PatchProgramOptions options;
  options.spacing = spacing;
  options.patches_per_draw = maxLevel(levels) >= 32 ? 2 : 8;
  for (uint32_t first = 0; first < program.patch_count; first += chunk) {
    options.first_patch = first;
    options.patch_count = std::min(chunk, program.patch_count - first);
    const gpu::PatchProgramCapture capture =
        gpu::runPatchProgram(context, program, levels, options);
    figures->draws += capture.draws;
    for (const gpu::CapturedVertex& v : capture.vertices) {
      const Vec3f cpu = patches.evaluateFloat(v.patch, v.coord).position;
      ++figures->device_points;
      if (!(cpu == v.position)) ++figures->device_points_differing;
      figures->device_max_ulp = std::max(figures->device_max_ulp, maxUlpDistance(cpu, v.position));
      if (v.patch >= patch_count || boundaries.domain[v.patch] != domain) continue;
      const CoordIndex& index = indices[boundaries.tessellation[v.patch]];
      const auto found = index.find(coordBits(v.coord));
      if (found == index.end()) continue;
      (*positions)[boundaries.at(v.patch, found->second)] = v.position;
      (*filled)[boundaries.at(v.patch, found->second)] = 1;
    }
  }
}

BoundaryPositions gpuPositions(const SurfacePatches& patches,
                               const std::vector<gpu::GpuPatchProgram>& programs,
                               const PatchBoundaries& boundaries, tess::Spacing spacing,
                               std::span<const tess::Levels> patch_levels, gpu::Context& context,
                               CrackFigures* figures) {
  BoundaryPositions positions(boundaries.offset.back());
  std::vector<uint8_t> filled(positions.size(), 0);
  std::string shaders;
  for (const gpu::GpuPatchProgram& program : programs) {
    gpuPositions(patches, program, boundaries, spacing, patch_levels, context, &positions, &filled,
                 figures);
    shaders += (shaders.empty() ? "" : ", ") + program.evaluation_shader;
  }
  if (std::find(filled.begin(), filled.end(), 0) != filled.end()) {
    throw std::runtime_error(
        "cracks: the GPU capture lacks boundary points the CPU tessellator "
        "emits (" +
        shaders + ")");
  }
  return positions;
}

class PairAccumulator {
 public:
  PairAccumulator(CrackFigures* figures, double scale_ulp) : f_(figures), scale_ulp_(scale_ulp) {}

  void add(const Vec3f& a, const Vec3f& b, const CrackLocation& where) {
    ++f_->points_compared;
    if (!(a == b)) ++f_->points_not_equal;
    const double dx = double(a.x) - b.x, dy = double(a.y) - b.y, dz = double(a.z) - b.z;
    const double gap = std::sqrt(dx * dx + dy * dy + dz * dz);
    sum_ += gap;
    f_->max_gap_ulp = std::max(f_->max_gap_ulp, maxUlpDistance(a, b));
    const double component = std::max({std::fabs(dx), std::fabs(dy), std::fabs(dz)});
    f_->max_gap_scale_ulp = std::max(f_->max_gap_scale_ulp, component / scale_ulp_);
    if (!f_->worst.found || gap > f_->max_gap_world) {
      f_->max_gap_world = gap;
      f_->worst = where;
      f_->worst.found = true;
    }
  }
  void finish() {
    f_->mean_gap_world = f_->points_compared ? sum_ / double(f_->points_compared) : 0;
    if (f_->max_gap_world == 0) f_->worst = {};
  }

 private:
  CrackFigures* f_;
  double scale_ulp_;
  double sum_ = 0;
};

// The spacing of floats at the control mesh's largest |coordinate|.
double scaleUlp(const Mesh& mesh) {
  float extent = 1e-30f;
  for (const Vec3d& p : mesh.positions) {
    extent =
        std::max({extent, std::fabs(float(p.x)), std::fabs(float(p.y)), std::fabs(float(p.z))});
  }
  return double(std::nextafter(extent, INFINITY)) - double(extent);
}

}  // namespace

const char* toString(CrackBackend backend) {
  return backend == CrackBackend::kGpu ? "gpu" : "cpu_float";
}

int64_t domainEdgeParameter(PatchDomain domain, uint32_t edge, const tess::DomainPoint& p) {
  double t = -1;
  if (domain == PatchDomain::kQuad) {
    const float u = p[0], v = p[1];
    switch (edge) {
      case 0:
        if (v == 0) t = u;
        break;
      case 1:
        if (u == 1) t = v;
        break;
      case 2:
        if (v == 1) t = 1.0 - u;
        break;
      default:
        if (u == 0) t = 1.0 - v;
        break;
    }
  } else if (p[(edge + 2) % 3] == 0) {
    t = p[(edge + 1) % 3];
  }
  return t < 0 ? -1 : int64_t(std::llround(t * double(kFixedOne)));
}

bool isDomainCorner(PatchDomain domain, uint32_t corner, const tess::DomainPoint& p) {
  if (domain == PatchDomain::kTriangle) return p[corner] == 1;
  static constexpr float kCorner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  return p[0] == kCorner[corner][0] && p[1] == kCorner[corner][1];
}

SharedBoundaries findSharedBoundaries(const SurfacePatches& patches) {
  const Welding welding = weldByPosition(patches.controlMesh());
  struct EdgeSide {
    PatchSide side;
    uint32_t raw0, raw1;  // unwelded position indices, ascending
  };
  std::map<std::pair<uint32_t, uint32_t>, std::vector<EdgeSide>> edges;
  std::map<uint32_t, std::vector<PatchSide>> vertex_sides;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const std::array<uint32_t, 4> raw = patches.patchCorners(p);
    const uint32_t corners = cornerCount(patches.patchDomain(p));
    for (uint32_t c = 0; c < corners; ++c) {
      vertex_sides[welding.canonical.at(raw[c])].push_back({uint32_t(p), c, false});
    }
    for (uint32_t e = 0; e < corners; ++e) {
      const uint32_t r0 = raw[e], r1 = raw[(e + 1) % corners];
      const uint32_t a = welding.canonical.at(r0), b = welding.canonical.at(r1);
      if (a == b) continue;  // degenerate edge: nothing to pair
      edges[{std::min(a, b), std::max(a, b)}].push_back(
          {{uint32_t(p), e, a > b}, std::min(r0, r1), std::max(r0, r1)});
    }
  }
  SharedBoundaries shared;
  for (const auto& [key, sides] : edges) {
    if (sides.size() < 2) continue;
    SharedEdge edge{key.first, key.second, false, {}};
    for (const EdgeSide& s : sides) {
      edge.sides.push_back(s.side);
      edge.seam |= s.raw0 != sides[0].raw0 || s.raw1 != sides[0].raw1;
    }
    shared.edges.push_back(std::move(edge));
  }
  for (auto& [vertex, sides] : vertex_sides) {
    if (sides.size() >= 2) shared.corners.push_back({vertex, std::move(sides)});
  }
  return shared;
}

CrackFigures measureCracks(const SurfacePatches& patches, tess::Spacing spacing, float level,
                           CrackBackend backend, gpu::Context* context) {
  const std::vector<tess::Levels> patch_levels(patches.patchCount(), uniformLevels(level));
  return measureCracks(patches, spacing, patch_levels, backend, context);
}

CrackFigures measureCracks(const SurfacePatches& patches, tess::Spacing spacing,
                           std::span<const tess::Levels> patch_levels, CrackBackend backend,
                           gpu::Context* context) {
  if (patch_levels.size() != patches.patchCount()) {
    throw std::invalid_argument("cracks: " + std::to_string(patch_levels.size()) +
                                " per-patch levels for " + std::to_string(patches.patchCount()) +
                                " patches");
  }
  CrackFigures figures;
  figures.backend = backend;
  const SharedBoundaries shared = findSharedBoundaries(patches);
  figures.shared_edges = shared.edges.size();
  figures.shared_corners = shared.corners.size();
  for (const SharedEdge& e : shared.edges) figures.seam_edges += e.seam ? 1 : 0;

  std::vector<gpu::GpuPatchProgram> programs;
  if (backend == CrackBackend::kGpu) {
    programs = patches.gpuPrograms();
    if (programs.empty()) {
      figures.skipped_reason = "the technique has no GPU program";
      return figures;
    }
    if (context == nullptr) {
      figures.skipped_reason = "no Vulkan device";
      return figures;
    }
  }

  const PatchBoundaries boundaries = patchBoundaries(patches, spacing, patch_levels);
  if (boundaries.culled_patches > 0) {
    figures.skipped_reason = boundaries.culled_patches == patches.patchCount()
                                 ? "the level culls every patch"
                                 : "the levels cull some patches";
    return figures;
  }
  const BoundaryPositions positions =
      backend == CrackBackend::kCpuFloat
          ? cpuPositions(patches, boundaries)
          : gpuPositions(patches, programs, boundaries, spacing, patch_levels, *context, &figures);
  figures.measured = true;

  PairAccumulator pairs(&figures, scaleUlp(patches.controlMesh()));
  for (const SharedEdge& edge : shared.edges) {
    const PatchSide& a = edge.sides[0];
    for (size_t s = 1; s < edge.sides.size(); ++s) {
      const PatchSide& b = edge.sides[s];
      const auto& b_index = boundaries.of(b.patch).edge_index[b.local];
      for (const auto& [t_a, k_a] : boundaries.of(a.patch).edge_index[a.local]) {
        const int64_t t_b = a.reversed == b.reversed ? t_a : kFixedOne - t_a;
        const auto k_b = b_index.find(t_b);
        if (k_b == b_index.end()) {
          ++figures.unpaired_points;
          continue;
        }
        pairs.add(positions[boundaries.at(a.patch, k_a)],
                  positions[boundaries.at(b.patch, k_b->second)],
                  {true, false, a.patch, b.patch, a.local, b.local, double(t_a) / kFixedOne});
      }
    }
  }
  for (const SharedCorner& corner : shared.corners) {
    const PatchSide& a = corner.sides[0];
    for (size_t s = 1; s < corner.sides.size(); ++s) {
      const PatchSide& b = corner.sides[s];
      pairs.add(positions[boundaries.at(a.patch, a.local)],
                positions[boundaries.at(b.patch, b.local)],
                {true, true, a.patch, b.patch, a.local, b.local, 0});
    }
  }
  pairs.finish();
  return figures;
}

}  // namespace tb
