#include "harness/measures/memory.h"

#include "harness/measures/measure.h"
#include "harness/mesh/render_vertices.h"
#include "harness/tess/tessellator.h"

namespace tb {
namespace {

constexpr uint64_t kDisplacementTexelBytes = 2;  // 16-bit scalar

// Points strictly inside one patch at uniform integer level n (not on its edges).
uint64_t interiorPointCount(PatchDomain domain, uint32_t n) {
  if (domain == PatchDomain::kQuad) return uint64_t(n - 1) * (n - 1);
  return tess::trianglePointCount(n) - 3ull * n;
}

uint64_t displacementTexels(PatchDomain domain, uint32_t n) {
  if (domain == PatchDomain::kQuad) return uint64_t(n + 1) * (n + 1);
  return uint64_t(n + 1) * (n + 2) / 2;
}

class MemoryMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        "memory", "Memory footprint against plain triangle meshes",
        "bytes of the technique's data (plus a 16-bit displacement map) against the equivalent "
        "welded triangle mesh at uniform levels 8, 16, 32, 64"};
    return kInfo;
  }
  bool appliesTo(const Technique& technique) const override {
    return technique.info().family == TechniqueFamily::kSurface;
  }
  bool dependsOnVariant() const override { return false; }

  MeasureResult run(const MeasureInput& input) const override {
    MeasureResult result;
    result.measure = info().id;
    result.notes = {
        "plain mesh: welded vertices of float3 position, float3 normal, float2 uv (32 B) and "
        "32-bit indices, with the tessellator's point and triangle counts",
        "displacement map: 16-bit, one texel per tessellated point of each patch"};
    for (uint32_t level : kMemoryLevels) {
      const MemoryFigures m = measureMemory(*input.patches, level);
      MetricRow row;
      row.keys["level"] = std::to_string(level);
      row.metrics = {
          {"plain_vertices", double(m.plain_vertices), "count"},
          {"plain_triangles", double(m.plain_triangles), "count"},
          {"plain_bytes", double(m.plain_bytes), "bytes"},
          {"control_mesh_bytes", double(m.technique.control_mesh_bytes), "bytes"},
          {"patch_data_bytes", double(m.technique.patch_data_bytes), "bytes"},
          {"stencil_bytes", double(m.technique.stencil_bytes), "bytes"},
          {"displacement_bytes", double(m.displacement_bytes), "bytes"},
          {"technique_with_displacement_bytes", double(m.technique_with_displacement_bytes),
           "bytes"},
          {"plain_over_technique", m.plain_over_technique, "ratio"},
      };
      result.rows.push_back(std::move(row));
    }
    return result;
  }
};

TB_REGISTER_MEASURE(MemoryMeasure);

}  // namespace

MemoryFigures measureMemory(const SurfacePatches& patches, uint32_t level) {
  const Mesh& control = patches.controlMesh();
  const RenderVertices render = buildRenderVertices(control);
  const PatchDomain domain = patches.domain();
  const uint64_t patch_count = patches.patchCount();

  MemoryFigures m;
  m.level = level;
  m.plain_vertices = render.vertex_count + uint64_t(render.edge_count) * (level - 1) +
                     patch_count * interiorPointCount(domain, level);
  m.plain_triangles = patch_count * (domain == PatchDomain::kQuad
                                         ? tess::quadTriangleCount(level)
                                         : tess::triangleTriangleCount(level));
  m.plain_bytes = m.plain_vertices * kRenderVertexBytes + m.plain_triangles * 3 * kIndexBytes;
  m.technique = patches.footprint();
  m.displacement_bytes = patch_count * displacementTexels(domain, level) * kDisplacementTexelBytes;
  m.technique_with_displacement_bytes = m.technique.total() + m.displacement_bytes;
  m.plain_over_technique = double(m.plain_bytes) / double(m.technique_with_displacement_bytes);
  return m;
}

}  // namespace tb
