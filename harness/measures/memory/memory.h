// Memory footprint against plain triangle meshes (docs/MEASURES.md).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh/render_vertices.h"
#include "techniques/technique.h"

namespace tb::measures {

inline const std::vector<uint32_t> kMemoryLevels{8, 16, 32, 64};

// One uniform tessellation level. All byte counts are resident GPU buffer sizes.
struct MemoryFigures {
  uint32_t level = 0;
  // The equivalent plain triangle mesh: the technique's output at this level,
  // welded (points on shared edges stored once, seams duplicated), each vertex
  // float3 position + float3 normal + float2 uv (32 B), 32-bit indices.
  uint64_t plain_vertices = 0;
  uint64_t plain_triangles = 0;
  uint64_t plain_bytes = 0;
  // The technique's own data (control mesh + patch data + stencils), independent
  // of the level.
  techniques::DataFootprint technique;
  // A 16-bit scalar displacement map sized for the level: one texel per
  // tessellated point of each patch, (n+1)^2 per quad, (n+1)(n+2)/2 per triangle
  // (two triangles share a square tile), no mip chain.
  uint64_t displacement_bytes = 0;
  uint64_t technique_with_displacement_bytes = 0;
  // plain_bytes / technique_with_displacement_bytes: above 1 the technique is the
  // smaller one. Seed 000 reports about 8 (943 MB against 118 MB at level 64).
  double plain_over_technique = 0;
  // The same with a vector-displacement map: 3 × 16 bits per texel.
  uint64_t vector_displacement_bytes = 0;
  uint64_t technique_with_vector_displacement_bytes = 0;
  double plain_over_technique_vector = 0;
};

// Closed form from the tessellator's counts, summed over the patches in their own
// patchDomain (quads and triangles may mix).
MemoryFigures measureMemory(const techniques::SurfacePatches& patches, uint32_t level);

// The compute path's transient output at one uniform integer level (core/gpu/compute_path.h):
// what it writes per frame and the tessellator path never holds (its points stream from the
// TES to the rasteriser). Closed form from the tessellator's counts, unwelded: every patch
// its own points. tests/measures/memory_test.cpp holds it to runComputePath's counts.
struct TransientFigures {
  uint64_t points = 0;        // domain points, patch after patch (= TES invocations)
  uint64_t index_words = 0;   // 3 per triangle
  uint64_t vertex_bytes = 0;  // points x the 40-byte record (patch, coordinate, position, normal)
  uint64_t index_bytes = 0;   // index_words x 4
  uint64_t bytes() const { return vertex_bytes + index_bytes; }
};
TransientFigures computePathTransient(const techniques::SurfacePatches& patches, uint32_t level);

// The equivalent plain triangle mesh itself: the technique evaluated (evaluateFloat) at
// the CPU tessellator's points of every patch (in its own patchDomain) at uniform integer
// level `level`, welded as MemoryFigures::plain_vertices counts them (a point on an edge
// between two render vertices is stored once, also between a quad and a triangle patch;
// corners are the control mesh's render vertices). Vertices are float3 position, float3
// normal, float2 uv (interpolated from the patch corners; 0 when the mesh has none), 32 B;
// triangles use the tessellator's winding.
struct TessellatedMesh {
  std::vector<float> vertices;    // kRenderVertexBytes / 4 floats per vertex
  std::vector<uint32_t> indices;  // 3 per triangle
  size_t vertexCount() const { return vertices.size() / 8; }
};
TessellatedMesh buildTessellatedMesh(const techniques::SurfacePatches& patches, uint32_t level);
// The same over patches [first_patch, end_patch) only, welded among themselves; `render`
// is buildRenderVertices(patches.controlMesh()), built once by the caller.
TessellatedMesh buildTessellatedMesh(const techniques::SurfacePatches& patches, uint32_t level,
                                     const mesh::RenderVertices& render, size_t first_patch,
                                     size_t end_patch);
// The same into `out`, reusing its buffers' capacity (a level-64 chunk is about 60 MB).
void buildTessellatedMesh(const techniques::SurfacePatches& patches, uint32_t level,
                          const mesh::RenderVertices& render, size_t first_patch, size_t end_patch,
                          TessellatedMesh* out);

// meshoptimizer's codecs on a mesh (docs/MEASURES.md, memory): vertex-cache
// then vertex-fetch optimisation (the order a shipping pipeline uses; it reorders `mesh`
// in place), then meshopt_encodeIndexBuffer and meshopt_encodeVertexBuffer.
struct CompressedMesh {
  std::vector<unsigned char> vertex_data;
  std::vector<unsigned char> index_data;
  uint64_t bytes() const { return vertex_data.size() + index_data.size(); }
};
CompressedMesh compressMesh(TessellatedMesh* mesh);
// The same into `out`, reusing `out`'s and `scratch`'s capacity.
void compressMesh(TessellatedMesh* mesh, CompressedMesh* out, std::vector<float>* scratch);

// Patches per chunk of the compressed baseline: about a million vertices at level 64, so
// memory stays bounded and the cost grows linearly with the asset. A streaming engine
// compresses per chunk (cluster, page) too.
inline constexpr size_t kCompressChunkPatches = 256;

// The most chunks the compressed baseline builds per level: every chunk of an asset up to
// 2,048 patches (every bundled one), an evenly spaced sample of a larger one. Building the
// plain mesh is the measure's whole cost (a 25k-patch asset is 110 million points at level
// 64), and the bytes per patch of one chunk differ little from another's: on the production
// assets an 8-chunk sample is within 0.3 % of every chunk at level 8
// (tests/measures/memory_test.cpp).
inline constexpr size_t kCompressSampleChunks = 8;

// The compressed baseline of the whole asset at `level`: the plain mesh of each run of
// kCompressChunkPatches patches (in patch order; the whole mesh when it has no more)
// built, compressed with compressMesh, and the byte counts summed. Points on an edge
// between two chunks are stored in both. With more than `sample_chunks` chunks, only
// `sample_chunks` of them, evenly spaced (chunk floor((i + 0.5) * chunks / sample_chunks)),
// are built, and their bytes scaled by the patches of all chunks over theirs. Chunks are
// compressed in parallel; the sums do not depend on the thread count.
struct CompressedSize {
  uint64_t vertex_bytes = 0;    // bytes; all chunks' or the sample's scaled, rounded
  uint64_t index_bytes = 0;     // bytes; likewise
  uint64_t chunks = 0;          // chunks of the asset
  uint64_t sampled_chunks = 0;  // chunks built: `chunks` (best, exact) down to sample_chunks
  uint64_t bytes() const { return vertex_bytes + index_bytes; }
};
CompressedSize compressedSize(const techniques::SurfacePatches& patches, uint32_t level,
                              size_t sample_chunks = kCompressSampleChunks);

// Decodes `compressed` into buffers the size of `like`; true when they equal it (each
// triangle up to rotation, which the index codec may apply; winding is kept).
bool decodesTo(const CompressedMesh& compressed, const TessellatedMesh& like);

}  // namespace tb::measures
