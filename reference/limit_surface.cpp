#include "reference/limit_surface.h"

#include <cassert>
#include <string>

#include "core/mesh/input_error.h"
#include "core/osd/topology_refiner_builder.h"
#include "reference/limit_surface_impl.h"
#include "reference/mesh_checks.h"

namespace tb::ref {
namespace {

namespace Bfr = OpenSubdiv::Bfr;

void checkApproxLevel(const mesh::Mesh& mesh, const char* option, int level) {
  if (level < 1 || level > kMaxApproxLevel) {
    throw mesh::InputError(mesh.source, std::string("option '") + option + "'",
                           "level " + std::to_string(level) + " is outside [1, " +
                               std::to_string(kMaxApproxLevel) +
                               "]: deeper levels crash or return garbage in OpenSubdiv 3.5.0");
  }
}

}  // namespace

void LimitSurface::Impl::checkFace(size_t face) const {
  checkFaceIndex(mesh, face);
  if (factory->FaceHasLimitSurface(int(face))) return;
  throw mesh::InputError(mesh.source, mesh::describeFace(mesh, face),
                         is_hole[face]
                             ? "face is tagged as a hole and has no limit surface"
                             : "face lies on a boundary and `interpolateboundary` is none, "
                               "so it has no limit surface");
}

LimitSurface::LimitSurface(const mesh::Mesh& mesh, osd::Scheme scheme, const LimitOptions& options)
    : impl_(std::make_unique<Impl>()) {
  checkApproxLevel(mesh, "approx_level_smooth", options.approx_level_smooth);
  checkApproxLevel(mesh, "approx_level_sharp", options.approx_level_sharp);
  checkFinitePositions(mesh.positions, mesh.source);

  Impl& impl = *impl_;
  impl.mesh = mesh;
  impl.scheme = scheme;
  impl.refiner = osd::buildTopologyRefiner(mesh, scheme);
  impl.positions.reserve(mesh.positions.size() * 3);
  for (const mesh::Vec3d& p : mesh.positions)
    impl.positions.insert(impl.positions.end(), {p.x, p.y, p.z});
  impl.is_hole.assign(mesh.faceCount(), false);
  for (uint32_t hole : mesh.tags.holes) impl.is_hole[hole] = true;

  Bfr::SurfaceFactory::Options factory_options;
  factory_options.SetApproxLevelSmooth(options.approx_level_smooth);
  factory_options.SetApproxLevelSharp(options.approx_level_sharp);
  impl.factory = std::make_unique<ThreadedSurfaceFactory>(*impl.refiner, factory_options);
}

LimitSurface::~LimitSurface() = default;
LimitSurface::LimitSurface(LimitSurface&&) noexcept = default;
LimitSurface& LimitSurface::operator=(LimitSurface&&) noexcept = default;

osd::Scheme LimitSurface::scheme() const { return impl_->scheme; }
const mesh::Mesh& LimitSurface::mesh() const { return impl_->mesh; }
size_t LimitSurface::faceCount() const { return impl_->mesh.faceCount(); }

bool LimitSurface::hasLimitSurface(size_t face) const {
  checkFaceIndex(impl_->mesh, face);
  return impl_->factory->FaceHasLimitSurface(int(face));
}

bool LimitSurface::isRegular(size_t face) const { return this->face(face).isRegular(); }

LimitPoint LimitSurface::evaluate(size_t face, double u, double v) const {
  return this->face(face).evaluate(u, v);
}

void LimitSurface::evaluate(size_t face, std::span<const mesh::Vec2d> uv,
                            std::span<LimitPoint> out) const {
  assert(uv.size() == out.size());
  const LimitFace prepared = this->face(face);
  for (size_t i = 0; i < uv.size(); ++i) {
    out[i] = prepared.evaluate(uv[i].x, uv[i].y);
  }
}

}  // namespace tb::ref
