#include "harness/measures/memory/memory.h"

#include <meshoptimizer.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cstring>
#include <optional>
#include <unordered_map>

#include "core/gpu/patch_program.h"
#include "core/mesh/render_vertices.h"
#include "core/tess/tessellator.h"
#include "harness/measures/common/cracks/cracks.h"

namespace tb::measures {
namespace {

constexpr uint64_t kDisplacementTexelBytes = 2;        // 16-bit scalar
constexpr uint64_t kVectorDisplacementTexelBytes = 6;  // 3 × 16 bits
constexpr int64_t kFixedOne = 1 << 16;                 // the tessellator's 16.16 fixed point
constexpr size_t kFloatsPerVertex = mesh::kRenderVertexBytes / sizeof(float);

// Points strictly inside one patch at uniform integer level n (not on its edges).
uint64_t interiorPointCount(techniques::PatchDomain domain, uint32_t n) {
  if (domain == techniques::PatchDomain::kQuad) return uint64_t(n - 1) * (n - 1);
  return tess::trianglePointCount(n) - 3ull * n;
}

uint64_t displacementTexels(techniques::PatchDomain domain, uint32_t n) {
  if (domain == techniques::PatchDomain::kQuad) return uint64_t(n + 1) * (n + 1);
  return uint64_t(n + 1) * (n + 2) / 2;
}

}  // namespace

TransientFigures computePathTransient(const techniques::SurfacePatches& patches, uint32_t level) {
  assert(level >= 1);
  TransientFigures t;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const bool quad = patches.patchDomain(p) == techniques::PatchDomain::kQuad;
    t.points += quad ? tess::quadPointCount(level) : tess::trianglePointCount(level);
    t.index_words +=
        3 * (quad ? tess::quadTriangleCount(level) : tess::triangleTriangleCount(level));
  }
  t.vertex_bytes = t.points * 4 * gpu::kCaptureRecordWords;
  t.index_bytes = t.index_words * 4;
  return t;
}

MemoryFigures measureMemory(const techniques::SurfacePatches& patches, uint32_t level) {
  const mesh::Mesh& control = patches.controlMesh();
  const mesh::RenderVertices render = mesh::buildRenderVertices(control);

  // Points on edges are shared through the render mesh's edges; the rest is per patch,
  // in the patch's own domain.
  uint64_t interior_points = 0, triangles = 0, texels = 0;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const techniques::PatchDomain domain = patches.patchDomain(p);
    interior_points += interiorPointCount(domain, level);
    triangles += domain == techniques::PatchDomain::kQuad ? tess::quadTriangleCount(level)
                                                          : tess::triangleTriangleCount(level);
    texels += displacementTexels(domain, level);
  }

  MemoryFigures m;
  m.level = level;
  m.plain_vertices =
      render.vertex_count + uint64_t(render.edge_count) * (level - 1) + interior_points;
  m.plain_triangles = triangles;
  m.plain_bytes =
      m.plain_vertices * mesh::kRenderVertexBytes + m.plain_triangles * 3 * mesh::kIndexBytes;
  m.technique = patches.footprint();
  if (m.technique.displacement_map_bytes > 0) {
    // A displaced surface carries its real map (already in technique.total()): its GPU bytes
    // replace the one-texel-per-vertex assumption, for the scalar and the vector figures.
    m.displacement_bytes = m.vector_displacement_bytes = m.technique.displacement_map_bytes;
    m.technique_with_displacement_bytes = m.technique_with_vector_displacement_bytes =
        m.technique.total();
    m.plain_over_technique = m.plain_over_technique_vector =
        double(m.plain_bytes) / double(m.technique_with_displacement_bytes);
    return m;
  }
  m.displacement_bytes = texels * kDisplacementTexelBytes;
  m.technique_with_displacement_bytes = m.technique.total() + m.displacement_bytes;
  m.plain_over_technique = double(m.plain_bytes) / double(m.technique_with_displacement_bytes);
  m.vector_displacement_bytes = texels * kVectorDisplacementTexelBytes;
  m.technique_with_vector_displacement_bytes = m.technique.total() + m.vector_displacement_bytes;
  m.plain_over_technique_vector =
      double(m.plain_bytes) / double(m.technique_with_vector_displacement_bytes);
  return m;
}

namespace {

// The integer-level tessellation of one domain, each point classified as corner c, edge e
// at parameter t (from corner e towards e + 1, as domainEdgeParameter gives it for both
// domains, so a quad and a triangle that share an edge name its points alike), or inside.
struct ClassifiedTessellation {
  struct PointClass {
    int corner = -1, edge = -1;
    int64_t t = 0;
  };
  techniques::PatchDomain domain;
  uint32_t corners;
  tess::Tessellation t;
  std::vector<PointClass> classes;
};

ClassifiedTessellation classifiedTessellation(techniques::PatchDomain domain, uint32_t level) {
  const float n = float(level);
  ClassifiedTessellation c{
      domain,
      domain == techniques::PatchDomain::kQuad ? 4u : 3u,
      tess::tessellate(
          domain == techniques::PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle,
          tess::Spacing::kInteger, {{n, n, n, n}, {n, n}}),
      {}};
  c.classes.resize(c.t.points.size());
  for (size_t i = 0; i < c.t.points.size(); ++i) {
    for (uint32_t k = 0; k < c.corners; ++k) {
      if (isDomainCorner(domain, k, c.t.points[i])) c.classes[i].corner = int(k);
    }
    for (uint32_t e = 0; e < c.corners && c.classes[i].corner < 0; ++e) {
      const int64_t param = domainEdgeParameter(domain, e, c.t.points[i]);
      if (param > 0 && param < kFixedOne) c.classes[i] = {-1, int(e), param};
    }
  }
  return c;
}

}  // namespace

TessellatedMesh buildTessellatedMesh(const techniques::SurfacePatches& patches, uint32_t level) {
  return buildTessellatedMesh(patches, level, mesh::buildRenderVertices(patches.controlMesh()), 0,
                              patches.patchCount());
}

TessellatedMesh buildTessellatedMesh(const techniques::SurfacePatches& patches, uint32_t level,
                                     const mesh::RenderVertices& render, size_t first_patch,
                                     size_t end_patch) {
  TessellatedMesh mesh;
  buildTessellatedMesh(patches, level, render, first_patch, end_patch, &mesh);
  return mesh;
}

void buildTessellatedMesh(const techniques::SurfacePatches& patches, uint32_t level,
                          const mesh::RenderVertices& render, size_t first_patch, size_t end_patch,
                          TessellatedMesh* out) {
  const mesh::Mesh& control = patches.controlMesh();
  std::array<std::optional<ClassifiedTessellation>, 2> by_domain;  // quad, triangle

  TessellatedMesh& mesh = *out;
  mesh.vertices.clear();
  mesh.indices.clear();
  size_t points = 0, triangles = 0;  // upper bounds: every point of every patch
  for (size_t p = first_patch; p < end_patch; ++p) {
    const bool quad = patches.patchDomain(p) == techniques::PatchDomain::kQuad;
    points += quad ? size_t(level + 1) * (level + 1) : tess::trianglePointCount(level);
    triangles += quad ? tess::quadTriangleCount(level) : tess::triangleTriangleCount(level);
  }
  mesh.vertices.reserve(points * kFloatsPerVertex);
  mesh.indices.reserve(triangles * 3);
  std::vector<uint32_t> corner_ids(render.vertex_count, UINT32_MAX);
  std::unordered_map<uint64_t, uint32_t> edge_ids;  // (render a < b, t from a) -> vertex
  edge_ids.reserve((end_patch - first_patch) * 2 * (level - 1));
  std::vector<uint32_t> local;
  for (size_t p = first_patch; p < end_patch; ++p) {
    const techniques::PatchDomain domain = patches.patchDomain(p);
    std::optional<ClassifiedTessellation>& slot =
        by_domain[domain == techniques::PatchDomain::kQuad ? 0 : 1];
    if (!slot) slot = classifiedTessellation(domain, level);
    const ClassifiedTessellation& c = *slot;
    const uint32_t corners = c.corners;
    const uint32_t first = control.face_offsets[p];
    auto renderVertex = [&](uint32_t k) { return render.corner_vertex[first + k % corners]; };
    local.resize(c.t.points.size());
    for (size_t i = 0; i < c.t.points.size(); ++i) {
      const ClassifiedTessellation::PointClass& k = c.classes[i];
      uint32_t* id = nullptr;
      uint32_t fresh = UINT32_MAX;
      if (k.corner >= 0) {
        id = &corner_ids[renderVertex(uint32_t(k.corner))];
      } else if (k.edge >= 0) {
        const uint32_t a = renderVertex(uint32_t(k.edge)), b = renderVertex(uint32_t(k.edge) + 1);
        // Unique below 2^64 for up to 16M render vertices.
        const uint64_t key =
            a < b ? (uint64_t(a) * render.vertex_count + b) * kFixedOne + uint64_t(k.t)
                  : (uint64_t(b) * render.vertex_count + a) * kFixedOne + uint64_t(kFixedOne - k.t);
        id = &edge_ids.try_emplace(key, UINT32_MAX).first->second;
      } else {
        id = &fresh;
      }
      if (*id == UINT32_MAX) {
        *id = uint32_t(mesh.vertexCount());
        const tess::DomainPoint& d = c.t.points[i];
        const techniques::SurfacePointF s = patches.evaluateFloat(p, d);
        // Corner weights of the uv interpolation, in the domain's corner order.
        float w[4] = {d[0], d[1], d[2], 0};
        if (domain == techniques::PatchDomain::kQuad) {
          w[0] = (1 - d[0]) * (1 - d[1]), w[1] = d[0] * (1 - d[1]);
          w[2] = d[0] * d[1], w[3] = (1 - d[0]) * d[1];
        }
        float uv[2] = {0, 0};
        for (uint32_t corner = 0; corner < corners && control.hasUvs(); ++corner) {
          const int32_t uv_id = control.corner_uvs[first + corner];
          if (uv_id < 0) continue;
          uv[0] += w[corner] * float(control.uvs[uv_id].x);
          uv[1] += w[corner] * float(control.uvs[uv_id].y);
        }
        for (float x : {s.position.x, s.position.y, s.position.z, s.normal.x, s.normal.y,
                        s.normal.z, uv[0], uv[1]}) {
          mesh.vertices.push_back(x);
        }
      }
      local[i] = *id;
    }
    for (const auto& tri : c.t.triangles) {
      for (uint32_t v : tri) mesh.indices.push_back(local[v]);
    }
  }
}

CompressedMesh compressMesh(TessellatedMesh* mesh) {
  CompressedMesh out;
  std::vector<float> scratch;
  compressMesh(mesh, &out, &scratch);
  return out;
}

void compressMesh(TessellatedMesh* mesh, CompressedMesh* out, std::vector<float>* scratch) {
  const size_t vertex_count = mesh->vertexCount();
  std::vector<uint32_t>& indices = mesh->indices;
  meshopt_optimizeVertexCache(indices.data(), indices.data(), indices.size(), vertex_count);
  std::vector<float>& fetched = *scratch;
  fetched.resize(mesh->vertices.size());
  const size_t used =
      meshopt_optimizeVertexFetch(fetched.data(), indices.data(), indices.size(),
                                  mesh->vertices.data(), vertex_count, mesh::kRenderVertexBytes);
  fetched.resize(used * kFloatsPerVertex);
  std::swap(mesh->vertices, fetched);

  out->index_data.resize(meshopt_encodeIndexBufferBound(indices.size(), used));
  out->index_data.resize(meshopt_encodeIndexBuffer(out->index_data.data(), out->index_data.size(),
                                                   indices.data(), indices.size()));
  out->vertex_data.resize(meshopt_encodeVertexBufferBound(used, mesh::kRenderVertexBytes));
  out->vertex_data.resize(meshopt_encodeVertexBuffer(out->vertex_data.data(),
                                                     out->vertex_data.size(), mesh->vertices.data(),
                                                     used, mesh::kRenderVertexBytes));
}

CompressedSize compressedSize(const techniques::SurfacePatches& patches, uint32_t level,
                              size_t sample_chunks) {
  assert(sample_chunks > 0);
  const mesh::RenderVertices render = mesh::buildRenderVertices(patches.controlMesh());
  const size_t patch_count = patches.patchCount();
  const size_t chunks = (patch_count + kCompressChunkPatches - 1) / kCompressChunkPatches;
  const size_t built = std::min(chunks, sample_chunks);
  auto chunkOf = [&](size_t i) { return built == chunks ? i : (2 * i + 1) * chunks / (2 * built); };
  // Per thread: the chunk's buffers, reused from chunk to chunk (a fresh 60 MB a chunk cost
  // more in page faults and copies than building it).
  struct Scratch {
    TessellatedMesh mesh;
    CompressedMesh compressed;
    std::vector<float> fetched;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  std::vector<std::array<uint64_t, 3>> per_chunk(built);  // vertex, index bytes, patches
  tbb::parallel_for(size_t(0), built, [&](size_t i) {
    const size_t first = chunkOf(i) * kCompressChunkPatches;
    const size_t end = std::min(patch_count, first + kCompressChunkPatches);
    Scratch& s = scratch.local();
    buildTessellatedMesh(patches, level, render, first, end, &s.mesh);
    compressMesh(&s.mesh, &s.compressed, &s.fetched);
    per_chunk[i] = {s.compressed.vertex_data.size(), s.compressed.index_data.size(), end - first};
  });
  uint64_t vertex_bytes = 0, index_bytes = 0, sampled_patches = 0;
  for (const auto& [v, i, p] : per_chunk) vertex_bytes += v, index_bytes += i, sampled_patches += p;
  CompressedSize total{vertex_bytes, index_bytes, chunks, built};
  if (built < chunks) {  // scaled to every patch, in integer arithmetic (rounded)
    auto scaled = [&](uint64_t bytes) {
      return (bytes * patch_count + sampled_patches / 2) / sampled_patches;
    };
    total.vertex_bytes = scaled(vertex_bytes);
    total.index_bytes = scaled(index_bytes);
  }
  return total;
}

bool decodesTo(const CompressedMesh& compressed, const TessellatedMesh& like) {
  std::vector<float> vertices(like.vertices.size());
  std::vector<uint32_t> indices(like.indices.size());
  if (meshopt_decodeVertexBuffer(vertices.data(), like.vertexCount(), mesh::kRenderVertexBytes,
                                 compressed.vertex_data.data(),
                                 compressed.vertex_data.size()) != 0 ||
      meshopt_decodeIndexBuffer(indices.data(), indices.size(), sizeof(uint32_t),
                                compressed.index_data.data(), compressed.index_data.size()) != 0) {
    return false;
  }
  // The index codec keeps triangle order and winding but may rotate a triangle's
  // vertices; compare each triangle from its smallest index.
  auto canonical = [](std::vector<uint32_t> list) {
    for (size_t i = 0; i + 2 < list.size(); i += 3) {
      while (list[i] > list[i + 1] || list[i] > list[i + 2]) {
        std::rotate(list.begin() + i, list.begin() + i + 1, list.begin() + i + 3);
      }
    }
    return list;
  };
  return canonical(indices) == canonical(like.indices) &&
         std::memcmp(vertices.data(), like.vertices.data(), vertices.size() * sizeof(float)) == 0;
}

}  // namespace tb::measures
