#include "reference/face_domain.h"

#include <opensubdiv/bfr/parameterization.h>

#include "core/osd/sdc_scheme.h"

namespace tb::ref {
namespace {

namespace Bfr = OpenSubdiv::Bfr;

Bfr::Parameterization parameterization(osd::Scheme scheme, int face_size) {
  return Bfr::Parameterization(osd::sdcScheme(scheme), face_size);
}

}  // namespace

bool hasSubFaces(osd::Scheme scheme, int face_size) {
  return parameterization(scheme, face_size).HasSubFaces();
}

int subFaceCount(osd::Scheme scheme, int face_size) {
  return hasSubFaces(scheme, face_size) ? face_size : 1;
}

mesh::Vec2d subFaceToFaceUv(osd::Scheme scheme, int face_size, int sub_face, mesh::Vec2d st) {
  const Bfr::Parameterization param = parameterization(scheme, face_size);
  if (!param.HasSubFaces()) return st;
  const double in[2] = {st.x, st.y};
  double out[2];
  param.ConvertNormalizedSubFaceToCoord(sub_face, in, out);
  return {out[0], out[1]};
}

SubFacePoint faceUvToSubFace(osd::Scheme scheme, int face_size, mesh::Vec2d uv) {
  const Bfr::Parameterization param = parameterization(scheme, face_size);
  if (!param.HasSubFaces()) return {0, uv};
  const double in[2] = {uv.x, uv.y};
  double out[2];
  const int sub_face = param.ConvertCoordToNormalizedSubFace(in, out);
  return {sub_face, {out[0], out[1]}};
}

bool insideFaceDomain(osd::Scheme scheme, int face_size, mesh::Vec2d uv, double slack) {
  const Bfr::Parameterization param = parameterization(scheme, face_size);
  if (!param.IsValid()) return false;
  switch (param.GetType()) {
    case Bfr::Parameterization::QUAD:
      return uv.x >= -slack && uv.y >= -slack && uv.x <= 1 + slack && uv.y <= 1 + slack;
    case Bfr::Parameterization::TRI:
      return uv.x >= -slack && uv.y >= -slack && uv.x + uv.y <= 1 + slack;
    case Bfr::Parameterization::QUAD_SUBFACES: {
      const SubFacePoint sub = faceUvToSubFace(scheme, face_size, uv);
      // Sub-face coordinates are normalised, so the slack doubles with them.
      const double s = 2 * slack;
      return sub.st.x >= -s && sub.st.y >= -s && sub.st.x <= 1 + s && sub.st.y <= 1 + s;
    }
  }
  return false;
}

mesh::Vec2d faceUvToEmbreeUv(int face_size, mesh::Vec2d uv) {
  if (face_size == 4) return uv;
  const SubFacePoint sub = faceUvToSubFace(osd::Scheme::kCatmullClark, face_size, uv);
  return {2.0 * (sub.sub_face % 4) + sub.st.x + 0.5, 2.0 * (sub.sub_face / 4) + sub.st.y + 0.5};
}

}  // namespace tb::ref
