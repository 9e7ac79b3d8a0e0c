// One evaluated point of a limit surface, shared by the Bfr reference and the
// Embree cross-check so the two compare field by field.
#pragma once

#include "core/mesh/vec.h"

namespace tb::ref {

struct LimitPoint {
  mesh::Vec3d position;  // world units
  mesh::Vec3d du;        // dP/du: world units per unit of the face's u (face_domain.h)
  mesh::Vec3d dv;        // dP/dv: world units per unit of the face's v
  // Unit length, along du x dv (outward for counter-clockwise faces). At a cone point
  // (the vertex of an infinitely sharp corner) the surface has no tangent plane and
  // the normal is only what the derivatives there give.
  mesh::Vec3d normal;
};

}  // namespace tb::ref
