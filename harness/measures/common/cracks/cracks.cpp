#include "harness/measures/common/cracks/cracks.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <map>
#include <span>
#include <stdexcept>
#include <string>

#include "core/mesh/topology.h"
#include "harness/measures/common/cracks/crack_capture.h"
#include "harness/measures/common/patch_sample.h"

namespace tb::measures {
namespace {

// Why a device backend cannot run (empty: it can): no program, no device, or on the compute
// path a program without a compute shader or a displaced build (not on the compute path yet).
std::string deviceSkipReason(std::span<const gpu::GpuPatchProgram> programs, CrackBackend backend,
                             const gpu::Context* context) {
  if (programs.empty()) return "the technique has no GPU program";
  if (context == nullptr) return "no Vulkan device";
  if (backend != CrackBackend::kGpuCompute) return "";
  for (const gpu::GpuPatchProgram& program : programs) {
    if (program.compute_shader.empty()) {
      return "the program " + program.evaluation_shader + " has no compute shader";
    }
    if (program.displacement != nullptr) return "the compute path does not displace yet";
  }
  return "";
}

uint32_t cornerCount(techniques::PatchDomain domain) {
  return domain == techniques::PatchDomain::kQuad ? 4 : 3;
}

tess::Levels uniformLevels(float level) {
  tess::Levels levels;
  levels.outer = {level, level, level, level};
  levels.inner = {level, level};
  return levels;
}

// Positions at every boundary point of every patch: [boundaries.at(patch, k)].
using BoundaryPositions = std::vector<mesh::Vec3f>;

// Boundary points per parallel task: below this, waking a worker costs more than it saves.
constexpr size_t kPointsPerTask = 4096;

// evaluateFloat at every boundary point, patches in parallel (each writes its own slots).
BoundaryPositions cpuPositions(const techniques::SurfacePatches& patches,
                               const PatchBoundaries& boundaries) {
  BoundaryPositions positions(boundaries.size());
  const size_t count = patches.patchCount();
  const size_t per_patch = std::max<size_t>(boundaries.size() / std::max<size_t>(count, 1), 1);
  const size_t grain = std::max<size_t>(kPointsPerTask / per_patch, 1);
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, count, grain),
      [&](const tbb::blocked_range<size_t>& range) {
        for (size_t p = range.begin(); p < range.end(); ++p) {
          const auto& points = boundaries.of(p).points;
          for (size_t k = 0; k < points.size(); ++k) {
            positions[boundaries.at(p, k)] = patches.evaluateFloat(p, points[k]).position;
          }
        }
      },
      tbb::simple_partitioner());
  return positions;
}

// The pair figures of one block of shared edges and corners, in pair order.
struct PairBlock {
  uint64_t compared = 0, not_equal = 0, unpaired = 0, max_ulp = 0;
  double max_scale_ulp = 0, max_gap = 0;
  CrackLocation worst;               // first pair with the block's largest gap
  std::vector<double> gaps;          // every pair's gap, in order (summed in order across blocks)
  bool keep_unequal = false;         // fill `unequal`
  std::vector<UnequalPair> unequal;  // the pairs that differ, in order

  void add(const mesh::Vec3f& a, const mesh::Vec3f& b, double scale_ulp,
           const CrackLocation& where) {
    ++compared;
    const double dx = double(a.x) - b.x, dy = double(a.y) - b.y, dz = double(a.z) - b.z;
    const double gap = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (!(a == b)) {
      ++not_equal;
      if (keep_unequal) unequal.push_back({a, b, gap});
    }
    gaps.push_back(gap);
    max_ulp = std::max(max_ulp, mesh::maxUlpDistance(a, b));
    const double component = std::max({std::fabs(dx), std::fabs(dy), std::fabs(dz)});
    max_scale_ulp = std::max(max_scale_ulp, component / scale_ulp);
    if (!worst.found || gap > max_gap) {
      max_gap = gap;
      worst = where;
      worst.found = true;
    }
  }
};

// Pairs every side of each shared edge and corner (after the first) with the first.
// Items are the edges, then the corners, cut into fixed blocks that run in parallel and
// are reduced in order, so every figure is the one a serial loop computes, bit for bit
// (the mean's sum included), whatever the thread count.
class Pairing {
 public:
  // `kind`: only the edges and corners of that kind (classifySeams); none: every one.
  Pairing(const SharedBoundaries& shared, const PatchBoundaries& boundaries,
          const BoundaryPositions& positions, double scale_ulp,
          std::optional<EdgeKind> kind = std::nullopt)
      : shared_(shared),
        boundaries_(boundaries),
        positions_(positions),
        scale_ulp_(scale_ulp),
        kind_(kind) {
    assert(positions.size() == boundaries.size() && scale_ulp > 0);
  }

  // `unequal`, when given, receives every pair that differs, in pair order.
  void run(CrackFigures* f, std::vector<UnequalPair>* unequal = nullptr) const {
    const size_t items = shared_.edges.size() + shared_.corners.size();
    std::vector<PairBlock> blocks((items + kItemsPerBlock - 1) / kItemsPerBlock);
    for (PairBlock& block : blocks) block.keep_unequal = unequal != nullptr;
    // Blocks are fixed by the items alone; how they are spread over threads is not.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks.size(), 1),
                      [&](const tbb::blocked_range<size_t>& range) {
                        for (size_t b = range.begin(); b < range.end(); ++b) {
                          const size_t end = std::min(items, (b + 1) * kItemsPerBlock);
                          for (size_t i = b * kItemsPerBlock; i < end; ++i) item(i, &blocks[b]);
                        }
                      });
    double sum = 0;
    for (const PairBlock& block : blocks) {
      f->points_compared += block.compared;
      f->points_not_equal += block.not_equal;
      f->unpaired_points += block.unpaired;
      f->max_gap_ulp = std::max(f->max_gap_ulp, block.max_ulp);
      f->max_gap_scale_ulp = std::max(f->max_gap_scale_ulp, block.max_scale_ulp);
      for (double gap : block.gaps) sum += gap;
      if (unequal != nullptr)
        unequal->insert(unequal->end(), block.unequal.begin(), block.unequal.end());
      if (block.worst.found && (!f->worst.found || block.max_gap > f->max_gap_world)) {
        f->max_gap_world = block.max_gap;
        f->worst = block.worst;
      }
    }
    f->mean_gap_world = f->points_compared ? sum / double(f->points_compared) : 0;
    if (f->max_gap_world == 0) f->worst = {};
  }

 private:
  static constexpr size_t kItemsPerBlock = 256;

  const mesh::Vec3f& at(uint32_t patch, size_t k) const {
    assert(patch < boundaries_.tessellation.size() && k < boundaries_.of(patch).points.size());
    return positions_[boundaries_.at(patch, k)];
  }

  void item(size_t i, PairBlock* block) const {
    if (i < shared_.edges.size()) {
      if (!kind_ || shared_.edges[i].kind == *kind_) edge(shared_.edges[i], block);
      return;
    }
    const SharedCorner& corner = shared_.corners[i - shared_.edges.size()];
    if (kind_ && corner.kind != *kind_) return;
    assert(corner.sides.size() >= 2);
    const PatchSide& a = corner.sides[0];
    for (size_t s = 1; s < corner.sides.size(); ++s) {
      const PatchSide& b = corner.sides[s];
      block->add(at(a.patch, a.local), at(b.patch, b.local), scale_ulp_,
                 {true, true, a.patch, b.patch, a.local, b.local, 0});
    }
  }

  void edge(const SharedEdge& edge, PairBlock* block) const {
    assert(edge.sides.size() >= 2);
    const PatchSide& a = edge.sides[0];
    const BoundaryTessellation& ta = boundaries_.of(a.patch);
    for (size_t s = 1; s < edge.sides.size(); ++s) {
      const PatchSide& b = edge.sides[s];
      const BoundaryTessellation& tb = boundaries_.of(b.patch);
      for (uint32_t k_a = ta.edge_begin[a.local]; k_a < ta.edge_begin[a.local + 1]; ++k_a) {
        const int64_t t_a = ta.edge_t[k_a];
        const int64_t t_b = a.reversed == b.reversed ? t_a : kEdgeParameterOne - t_a;
        const int64_t k_b = tb.edgePoint(b.local, t_b);
        if (k_b < 0) {
          ++block->unpaired;
          continue;
        }
        block->add(
            at(a.patch, k_a), at(b.patch, size_t(k_b)), scale_ulp_,
            {true, false, a.patch, b.patch, a.local, b.local, double(t_a) / kEdgeParameterOne});
      }
    }
  }

  const SharedBoundaries& shared_;
  const PatchBoundaries& boundaries_;
  const BoundaryPositions& positions_;
  double scale_ulp_;
  std::optional<EdgeKind> kind_;
};

// The spacing of floats at the control mesh's largest |coordinate|.
double scaleUlp(const mesh::Mesh& mesh) {
  float extent = 1e-30f;
  for (const mesh::Vec3d& p : mesh.positions) {
    extent =
        std::max({extent, std::fabs(float(p.x)), std::fabs(float(p.y)), std::fabs(float(p.z))});
  }
  return double(std::nextafter(extent, INFINITY)) - double(extent);
}

// The device's positions against the CPU float model's at the same boundary points.
void compareWithCpu(const BoundaryPositions& device, const BoundaryPositions& cpu,
                    CrackFigures* f) {
  for (size_t i = 0; i < device.size(); ++i) {
    if (!(cpu[i] == device[i])) ++f->device_points_differing;
    f->device_max_ulp = std::max(f->device_max_ulp, mesh::maxUlpDistance(cpu[i], device[i]));
  }
}

// The pair figures (Pairing::run's fields) of `from`, into `to`.
void copyPairFigures(const CrackFigures& from, CrackFigures* to) {
  to->points_compared = from.points_compared;
  to->points_not_equal = from.points_not_equal;
  to->unpaired_points = from.unpaired_points;
  to->max_gap_world = from.max_gap_world;
  to->mean_gap_world = from.mean_gap_world;
  to->max_gap_ulp = from.max_gap_ulp;
  to->max_gap_scale_ulp = from.max_gap_scale_ulp;
  to->worst = from.worst;
}

bool bitwiseEqual(const BoundaryPositions& a, const BoundaryPositions& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(mesh::Vec3f)) == 0;
}

// True when both hold the same boundary points for every patch, bit for bit and in the
// same order (then positions and pair figures agree too).
bool sameBoundaryPoints(const PatchBoundaries& a, const PatchBoundaries& b) {
  if (a.offset != b.offset) return false;
  std::map<std::pair<uint32_t, uint32_t>, bool> compared;  // distinct tessellation pairs
  for (size_t p = 0; p < a.tessellation.size(); ++p) {
    const auto key = std::make_pair(a.tessellation[p], b.tessellation[p]);
    auto it = compared.find(key);
    if (it == compared.end()) {
      const BoundaryTessellation& ta = a.of(p);
      const BoundaryTessellation& tb = b.of(p);
      const bool same =
          &ta == &tb || (ta.edge_begin == tb.edge_begin &&
                         std::memcmp(ta.points.data(), tb.points.data(),
                                     ta.points.size() * sizeof(tess::DomainPoint)) == 0);
      it = compared.emplace(key, same).first;
    }
    if (!it->second) return false;
  }
  return true;
}

}  // namespace

const char* toString(CrackBackend backend) {
  return backend == CrackBackend::kCpuFloat ? "cpu_float" : "gpu";
}

const char* crackPath(CrackBackend backend) {
  return backend == CrackBackend::kGpuCompute ? "compute" : "tessellator";
}

SharedBoundaries findSharedBoundaries(const techniques::SurfacePatches& patches) {
  const mesh::Welding welding = mesh::weldByPosition(patches.controlMesh());
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
  classifySeams(patches.controlMesh(), welding, &shared);
  return shared;
}

std::vector<uint8_t> crackSample(const techniques::SurfacePatches& patches,
                                 const SharedBoundaries& shared, size_t budget,
                                 bool keep_features) {
  const size_t patch_count = patches.patchCount();
  if (patch_count <= budget) return std::vector<uint8_t>(patch_count, 1);
  // Per patch: its edges shared (without a seam) and its corners' patch counts.
  std::vector<uint8_t> feature(patch_count, 0);
  std::vector<uint32_t> shared_edges(patch_count, 0);
  for (const SharedEdge& edge : shared.edges) {
    for (const PatchSide& side : edge.sides) {
      if (edge.seam || edge.sides.size() != 2) feature[side.patch] = 1;
      ++shared_edges[side.patch];
    }
  }
  for (const SharedCorner& corner : shared.corners) {
    for (const PatchSide& side : corner.sides) {
      const size_t regular = cornerCount(patches.patchDomain(side.patch)) == 4 ? 4 : 6;
      if (corner.sides.size() != regular) feature[side.patch] = 1;
    }
  }
  const mesh::SubdivisionTags& tags = patches.controlMesh().tags;
  std::vector<uint8_t> tagged(patches.controlMesh().positions.size(), 0);
  for (const mesh::Crease& c : tags.creases) {
    if (c.sharpness > 0 && c.v0 < tagged.size() && c.v1 < tagged.size())
      tagged[c.v0] = tagged[c.v1] = 1;
  }
  for (const mesh::Corner& c : tags.corners) {
    if (c.sharpness > 0 && c.vertex < tagged.size()) tagged[c.vertex] = 1;
  }
  for (size_t p = 0; p < patch_count; ++p) {
    const uint32_t corners = cornerCount(patches.patchDomain(p));
    if (shared_edges[p] != corners) feature[p] = 1;  // a boundary or hole edge
    const std::array<uint32_t, 4> raw = patches.patchCorners(p);
    for (uint32_t c = 0; c < corners; ++c) {
      if (raw[c] < tagged.size() && tagged[raw[c]]) feature[p] = 1;
    }
  }
  return samplePatches(feature, std::vector<uint8_t>(patch_count, 1), budget, keep_features).part;
}

namespace {

// `shared` with only the sides of sampled patches; edges and corners keep two or more.
SharedBoundaries sampledBoundaries(SharedBoundaries shared, const std::vector<uint8_t>& sampled) {
  const auto out = [&](const PatchSide& side) { return sampled[side.patch] == 0; };
  for (SharedEdge& edge : shared.edges) std::erase_if(edge.sides, out);
  for (SharedCorner& corner : shared.corners) std::erase_if(corner.sides, out);
  std::erase_if(shared.edges, [](const SharedEdge& e) { return e.sides.size() < 2; });
  std::erase_if(shared.corners, [](const SharedCorner& c) { return c.sides.size() < 2; });
  return shared;
}

}  // namespace

CrackSession::CrackSession(const techniques::SurfacePatches& patches, size_t patch_budget,
                           bool keep_features)
    : patches_(patches),
      programs_(patches.gpuPrograms()),
      shared_(findSharedBoundaries(patches)),
      scale_ulp_(scaleUlp(patches.controlMesh())) {
  sampled_ = crackSample(patches, shared_, patch_budget, keep_features);
  sampled_count_ = size_t(std::count(sampled_.begin(), sampled_.end(), uint8_t(1)));
  if (sampled_count_ == sampled_.size()) {
    sampled_.clear();
  } else {
    shared_ = sampledBoundaries(std::move(shared_), sampled_);
  }
  for (const SharedEdge& e : shared_.edges) {
    seam_edges_ += e.seam ? 1 : 0;
    has_seams_ = has_seams_ || e.kind == EdgeKind::kSeam;
  }
}

CrackSession::Evaluated& CrackSession::evaluated(tess::Spacing spacing,
                                                 std::span<const tess::Levels> patch_levels) {
  std::vector<tess::LevelsBits> bits(patch_levels.size());
  std::transform(patch_levels.begin(), patch_levels.end(), bits.begin(), tess::levelsBits);
  for (Evaluated& e : kept_) {
    if (e.spacing == spacing && e.levels == bits) return e;
  }
  Evaluated e{spacing, std::move(bits), patchBoundaries(patches_, spacing, patch_levels), {}};
  for (const Evaluated& other : kept_) {
    if (sameBoundaryPoints(e.boundaries, other.boundaries)) {
      e.cpu = other.cpu;
      break;
    }
  }
  if (!e.cpu) e.cpu = std::make_shared<CpuSide>();
  if (kept_.size() == kKeptEvaluations) kept_.erase(kept_.begin());
  kept_.push_back(std::move(e));
  return kept_.back();
}

const CrackFigures& CrackSession::cpuPairs(const Evaluated& e, std::optional<EdgeKind> kind) {
  std::optional<CrackFigures>& slot = e.cpu->pairs[kind ? 1 + size_t(*kind) : 0];
  if (!slot) {
    CrackFigures pairs;
    Pairing(shared_, e.boundaries, e.cpu->positions, scale_ulp_, kind).run(&pairs);
    slot = pairs;
  }
  return *slot;
}

CrackFigures CrackSession::measure(tess::Spacing spacing, float level, CrackBackend backend,
                                   gpu::Context* context, std::optional<EdgeKind> kind) {
  const std::vector<tess::Levels> patch_levels(patches_.patchCount(), uniformLevels(level));
  return measure(spacing, patch_levels, backend, context, kind);
}

CrackFigures CrackSession::measure(tess::Spacing spacing,
                                   std::span<const tess::Levels> patch_levels, CrackBackend backend,
                                   gpu::Context* context, std::optional<EdgeKind> kind) {
  if (patch_levels.size() != patches_.patchCount()) {
    throw std::invalid_argument("cracks: " + std::to_string(patch_levels.size()) +
                                " per-patch levels for " + std::to_string(patches_.patchCount()) +
                                " patches");
  }
  if (kind && backend != CrackBackend::kCpuFloat) {
    throw std::invalid_argument("cracks: edge kinds are measured on the CPU float model only");
  }
  CrackFigures figures;
  figures.backend = backend;
  figures.shared_edges = shared_.edges.size();
  figures.shared_corners = shared_.corners.size();
  figures.seam_edges = seam_edges_;
  if (kind) {
    const auto of_kind = [&](const auto& item) { return item.kind == *kind; };
    figures.shared_edges =
        uint64_t(std::count_if(shared_.edges.begin(), shared_.edges.end(), of_kind));
    figures.shared_corners =
        uint64_t(std::count_if(shared_.corners.begin(), shared_.corners.end(), of_kind));
    figures.seam_edges =
        uint64_t(std::count_if(shared_.edges.begin(), shared_.edges.end(),
                               [&](const SharedEdge& e) { return e.seam && of_kind(e); }));
  }
  figures.patches_compared = sampled_count_;
  if (backend != CrackBackend::kCpuFloat) {
    figures.skipped_reason = deviceSkipReason(programs_, backend, context);
    if (!figures.skipped_reason.empty()) return figures;
  }

  // Outside the sample, zero levels: no boundary points, nothing drawn.
  std::vector<tess::Levels> sampled_levels;
  if (!sampled_.empty()) {
    sampled_levels.assign(patch_levels.begin(), patch_levels.end());
    for (size_t p = 0; p < sampled_.size(); ++p) {
      if (!sampled_[p]) sampled_levels[p] = uniformLevels(0);
    }
    patch_levels = sampled_levels;
  }
  const size_t left_out = patches_.patchCount() - sampled_count_;
  const Evaluated& e = evaluated(spacing, patch_levels);
  if (e.boundaries.culled_patches > left_out) {
    figures.skipped_reason = e.boundaries.culled_patches == patches_.patchCount()
                                 ? "the level culls every patch"
                                 : "the levels cull some patches";
    return figures;
  }
  if (e.cpu->positions.size() != e.boundaries.size()) {
    e.cpu->positions = cpuPositions(patches_, e.boundaries);
  }
  figures.measured = true;
  if (backend == CrackBackend::kCpuFloat) {
    copyPairFigures(cpuPairs(e, kind), &figures);
    return figures;
  }
  CrackCaptureOptions capture_options;
  capture_options.compute_path = backend == CrackBackend::kGpuCompute;
  const BoundaryCapture capture = captureBoundaryPositions(
      patches_, programs_, e.boundaries, spacing, patch_levels, *context, capture_options);
  figures.draws = capture.draws;
  figures.device_points = capture.points_captured;
  compareWithCpu(capture.positions, e.cpu->positions, &figures);
  if (bitwiseEqual(capture.positions, e.cpu->positions)) {
    copyPairFigures(cpuPairs(e, std::nullopt), &figures);
  } else {
    CrackFigures pairs;
    Pairing(shared_, e.boundaries, capture.positions, scale_ulp_).run(&pairs);
    copyPairFigures(pairs, &figures);
  }
  return figures;
}

std::vector<UnequalPair> unequalPairs(const techniques::SurfacePatches& patches,
                                      tess::Spacing spacing,
                                      std::span<const tess::Levels> patch_levels,
                                      CrackFigures* figures) {
  if (patch_levels.size() != patches.patchCount()) {
    throw std::invalid_argument("cracks: the per-patch levels are not one per patch");
  }
  CrackFigures pairs;
  std::vector<UnequalPair> unequal;
  const PatchBoundaries boundaries = patchBoundaries(patches, spacing, patch_levels);
  if (boundaries.culled_patches == 0) {
    pairs.measured = true;
    Pairing(findSharedBoundaries(patches), boundaries, cpuPositions(patches, boundaries),
            scaleUlp(patches.controlMesh()))
        .run(&pairs, &unequal);
  }
  if (figures != nullptr) *figures = pairs;
  return unequal;
}

CrackFigures measureCracks(const techniques::SurfacePatches& patches, tess::Spacing spacing,
                           float level, CrackBackend backend, gpu::Context* context) {
  return CrackSession(patches).measure(spacing, level, backend, context);
}

CrackFigures measureCracks(const techniques::SurfacePatches& patches, tess::Spacing spacing,
                           std::span<const tess::Levels> patch_levels, CrackBackend backend,
                           gpu::Context* context) {
  return CrackSession(patches).measure(spacing, patch_levels, backend, context);
}

}  // namespace tb::measures
