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

}  // namespace

mesh::Mesh refineUniform(const mesh::Mesh& mesh, Scheme scheme, int levels) {
  auto refiner = buildTopologyRefiner(mesh, scheme);
  refiner->RefineUniform(OpenSubdiv::Far::TopologyRefiner::UniformOptions(levels));
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
  return refined;
}

}  // namespace tb::osd
