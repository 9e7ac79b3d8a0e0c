#include "core/osd/uniform_refinement.h"

#include <opensubdiv/far/primvarRefiner.h>

#include <vector>

#include "core/osd/topology_refiner_builder.h"

namespace tb::osd {
namespace {

// The interpolation buffer element Far::PrimvarRefiner works on.
struct RefinedPoint {
  double x = 0, y = 0, z = 0;
  void Clear() { x = y = z = 0; }
  void AddWithWeight(const RefinedPoint& p, float weight) {
    x += weight * p.x;
    y += weight * p.y;
    z += weight * p.z;
  }
};

// The tags of the last level that keep its limit surface the input's: every interior edge
// whose sharpness is still above 0 (semi-sharp creases lose 1 a level, by the crease method
// Far applies), the corners the input tagged (followed to their child vertex at each
// level), and the faces Far marks as holes. Boundary edges and the corners the boundary rule
// itself makes sharp are not tags, as in the input.
void copyRefinedTags(const mesh::Mesh& mesh, const OpenSubdiv::Far::TopologyRefiner& refiner,
                     int levels, mesh::Mesh* refined) {
  const OpenSubdiv::Far::TopologyLevel& last = refiner.GetLevel(levels);
  mesh::SubdivisionTags& tags = refined->tags;
  tags = mesh.tags;
  tags.creases.clear();
  tags.corners.clear();
  tags.holes.clear();
  for (int e = 0; e < last.GetNumEdges(); ++e) {
    const float sharpness = last.GetEdgeSharpness(e);
    if (sharpness <= 0 || last.GetEdgeFaces(e).size() != 2) continue;
    const OpenSubdiv::Far::ConstIndexArray ends = last.GetEdgeVertices(e);
    tags.creases.push_back({uint32_t(ends[0]), uint32_t(ends[1]), double(sharpness)});
  }
  for (const mesh::Corner& corner : mesh.tags.corners) {
    int v = int(corner.vertex);
    for (int level = 0; level < levels && v >= 0; ++level) {
      v = refiner.GetLevel(level).GetVertexChildVertex(v);
    }
    if (v < 0) continue;
    const float sharpness = last.GetVertexSharpness(v);
    if (sharpness > 0) tags.corners.push_back({uint32_t(v), double(sharpness)});
  }
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    if (last.IsFaceHole(f)) tags.holes.push_back(uint32_t(f));
  }
}

}  // namespace

mesh::Mesh refineUniform(const mesh::Mesh& mesh, Scheme scheme, int levels) {
  auto refiner = buildTopologyRefiner(mesh, scheme);
  OpenSubdiv::Far::TopologyRefiner::UniformOptions options(levels);
  options.fullTopologyInLastLevel = true;  // the last level's edges carry its crease tags
  refiner->RefineUniform(options);
  std::vector<RefinedPoint> points;
  for (const mesh::Vec3d& p : mesh.positions) points.push_back({p[0], p[1], p[2]});
  OpenSubdiv::Far::PrimvarRefiner primvar(*refiner);
  for (int level = 1; level <= levels; ++level) {
    std::vector<RefinedPoint> finer(size_t(refiner->GetLevel(level).GetNumVertices()));
    RefinedPoint* destination = finer.data();
    primvar.Interpolate(level, points.data(), destination);
    points = std::move(finer);
  }
  const OpenSubdiv::Far::TopologyLevel& last = refiner->GetLevel(levels);
  mesh::Mesh refined;
  refined.source = mesh.source + " (refined " + std::to_string(levels) + "x)";
  for (const RefinedPoint& p : points) refined.positions.push_back({p.x, p.y, p.z});
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const OpenSubdiv::Far::ConstIndexArray vertices = last.GetFaceVertices(f);
    std::vector<uint32_t> corners(vertices.begin(), vertices.end());
    refined.addFace(corners, {}, {}, 0);
  }
  copyRefinedTags(mesh, *refiner, levels, &refined);
  return refined;
}

}  // namespace tb::osd
