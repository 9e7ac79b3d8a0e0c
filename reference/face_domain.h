// What (u,v) means on one face of a limit surface: OpenSubdiv Bfr's parameterisation
// (Bfr::Parameterization) everywhere, so a technique's (u,v) goes to the reference unchanged.
// Quads: the unit square, corner 0 at (0,0), u towards corner 1, v towards corner 3 (Embree's
// too). Loop triangles: u, v >= 0, u + v <= 1. Other N-gons: N quad sub-faces, sub-face k
// in the half-size tile (k % D + s/2, k / D + t/2), D = ceil(sqrt(N)), so derivatives in
// (u,v) are twice those in (s,t). Details: docs/derivations/parameterisation.md.
#pragma once

#include "core/mesh/vec.h"
#include "core/osd/scheme.h"

namespace tb::ref {

// d(u,v)/d(s,t) inside a sub-face: a sub-face spans half a unit of face (u,v).
inline constexpr double kSubFaceSpan = 0.5;

struct SubFacePoint {
  int sub_face = 0;  // 0 for faces without sub-faces
  mesh::Vec2d st;    // normalised sub-face coordinates, [0,1]^2
};

// True when a face of this size is split into quad sub-faces (Catmull-Clark, N != 4).
bool hasSubFaces(osd::Scheme scheme, int face_size);

// N for faces with sub-faces, else 1.
int subFaceCount(osd::Scheme scheme, int face_size);

// Face (u,v) of normalised sub-face coordinates; identity on faces without sub-faces.
mesh::Vec2d subFaceToFaceUv(osd::Scheme scheme, int face_size, int sub_face, mesh::Vec2d st);

// Inverse of subFaceToFaceUv; points on a tile edge go to the lower sub-face index
// OpenSubdiv picks.
SubFacePoint faceUvToSubFace(osd::Scheme scheme, int face_size, mesh::Vec2d uv);

// True when uv lies in the face's domain, up to `slack` in parameter units.
bool insideFaceDomain(osd::Scheme scheme, int face_size, mesh::Vec2d uv, double slack = 1e-12);

// Embree's subdivision-geometry (U,V) for a Catmull-Clark face (u,v): the identity on
// quads; on other N-gons sub-face k at (s,t) is U = 2 (k % 4) + s + 0.5,
// V = 2 (k / 4) + t + 0.5 (rtcInterpolate's sub-patch encoding). Embree's derivatives
// are per unit of (s,t), so dP/du = dP/dU / kSubFaceSpan there.
mesh::Vec2d faceUvToEmbreeUv(int face_size, mesh::Vec2d uv);

}  // namespace tb::ref
