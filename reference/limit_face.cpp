#include "reference/limit_face.h"

#include <opensubdiv/bfr/surface.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/mesh/input_error.h"
#include "reference/face_domain.h"
#include "reference/limit_surface_impl.h"
#include "reference/mesh_checks.h"

namespace tb::ref {
namespace {

namespace Bfr = OpenSubdiv::Bfr;

// A normal is taken as degenerate when |du x dv| falls below this fraction of
// |du| |dv| (tangents parallel to ~1e-12 rad, or one of them zero).
constexpr double kDegenerateSine = 1e-12;
// Where the tangents degenerate (e.g. at the tip of an infinitely sharp corner), the
// normal is taken this far (in parameter units) towards the face centre.
constexpr double kNormalNudge = 1e-7;

mesh::Vec3d toVec(const double p[3]) { return {p[0], p[1], p[2]}; }

}  // namespace

struct LimitFace::Impl {
  const LimitSurface::Impl* surface = nullptr;
  size_t face = 0;
  Bfr::Surface<double> patch;
  std::vector<double> patch_points;  // xyz per patch point

  void evaluateRaw(double u, double v, mesh::Vec3d* p, mesh::Vec3d* du, mesh::Vec3d* dv) const {
    const double uv[2] = {u, v};
    double pp[3], pu[3], pv[3];
    patch.Evaluate(uv, patch_points.data(), Bfr::Surface<double>::PointDescriptor(3), pp, pu, pv);
    *p = toVec(pp);
    *du = toVec(pu);
    *dv = toVec(pv);
  }

  mesh::Vec3d normalAt(double u, double v, const mesh::Vec3d& du, const mesh::Vec3d& dv) const {
    const mesh::Vec3d n = cross(du, dv);
    if (length(n) > kDegenerateSine * length(du) * length(dv)) return normalize(n);
    double centre[2];
    patch.GetParameterization().GetCenterCoord(centre);
    // On a sub-faced N-gon the centre lies in the corner of every sub-face tile, so
    // nudge towards the centre of this point's own sub-face.
    if (patch.GetParameterization().HasSubFaces()) {
      const SubFacePoint sub = faceUvToSubFace(surface->scheme, patch.GetFaceSize(), {u, v});
      const mesh::Vec2d c =
          subFaceToFaceUv(surface->scheme, patch.GetFaceSize(), sub.sub_face, {0.5, 0.5});
      centre[0] = c.x;
      centre[1] = c.y;
    }
    mesh::Vec3d p, nudged_du, nudged_dv;
    evaluateRaw(u + kNormalNudge * (centre[0] - u), v + kNormalNudge * (centre[1] - v), &p,
                &nudged_du, &nudged_dv);
    return normalize(cross(nudged_du, nudged_dv));
  }
};

LimitFace LimitSurface::face(size_t face) const {
  impl_->checkFace(face);
  auto prepared = std::make_unique<LimitFace::Impl>();
  prepared->surface = impl_.get();
  prepared->face = face;
  if (!impl_->factory->InitVertexSurface<double>(int(face), &prepared->patch)) {
    throw mesh::InputError(impl_->mesh.source, mesh::describeFace(impl_->mesh, face),
                           "OpenSubdiv Bfr could not build a limit patch for this face");
  }
  const Bfr::Surface<double>::PointDescriptor xyz(3);
  prepared->patch_points.resize(size_t(prepared->patch.GetNumPatchPoints()) * 3);
  prepared->patch.PreparePatchPoints(impl_->positions.data(), xyz, prepared->patch_points.data(),
                                     xyz);
  return LimitFace(std::move(prepared));
}

LimitFace::LimitFace(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
LimitFace::~LimitFace() = default;
LimitFace::LimitFace(LimitFace&&) noexcept = default;
LimitFace& LimitFace::operator=(LimitFace&&) noexcept = default;

size_t LimitFace::index() const { return impl_->face; }
int LimitFace::faceSize() const { return impl_->patch.GetFaceSize(); }
bool LimitFace::isRegular() const { return impl_->patch.IsRegular(); }
int LimitFace::subFaceCount() const {
  return tb::ref::subFaceCount(impl_->surface->scheme, faceSize());
}

LimitPoint LimitFace::evaluate(double u, double v) const {
  checkInsideFaceDomain(impl_->surface->mesh, impl_->face, impl_->surface->scheme, {u, v});
  LimitPoint point;
  impl_->evaluateRaw(u, v, &point.position, &point.du, &point.dv);
  point.normal = impl_->normalAt(u, v, point.du, point.dv);
  return point;
}

LimitPoint LimitFace::evaluateSubFace(int sub_face, double s, double t) const {
  const mesh::Vec2d uv = subFaceToFaceUv(impl_->surface->scheme, faceSize(), sub_face, {s, t});
  return evaluate(uv.x, uv.y);
}

}  // namespace tb::ref
