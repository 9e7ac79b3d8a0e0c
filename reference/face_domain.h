// What (u,v) means on one face of a limit surface. tessbench uses OpenSubdiv Bfr's
// parameterisation (Bfr::Parameterization) everywhere, so a technique's (u,v) can be
// handed to the reference unchanged:
//
//  - Quad, Catmull-Clark: the unit square. Corners 0,1,2,3 of the face sit at
//    (0,0), (1,0), (1,1), (0,1): u runs from corner 0 to corner 1, v from corner 0
//    to corner 3. Embree uses the same convention (checked in the tests).
//  - Triangle, Loop: u, v >= 0, u + v <= 1, corners at (0,0), (1,0), (0,1).
//  - Any other N-gon under Catmull-Clark (triangles included): one subdivision step
//    splits it into N quads, and sub-face k is the quad at corner k. With normalised
//    sub-face coordinates (s,t) in [0,1]^2 (Ptex's), (0,0) is corner k, s runs towards
//    the midpoint of edge k (corner k -> k+1), t towards the midpoint of edge k-1
//    (corner k -> k-1), and (1,1) is the face centre. In face (u,v), sub-face k fills
//    the half-size tile (u,v) = (k % D + s/2, k / D + t/2), D = ceil(sqrt(N)).
//    Derivatives in (u,v) are therefore twice those in (s,t).
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
