#pragma once

#include "core/mesh/mesh.h"

namespace tb::mesh {

// Replaces the mesh's normals with one smooth normal per position: the sum of the
// incident face normals, each weighted by the face's interior angle at that
// corner (Thürmer & Wüthrich 1998), so the result does not depend on how the
// faces around the vertex are triangulated. Sets normals_computed.
void assignAngleWeightedNormals(Mesh* mesh);

}  // namespace tb::mesh
