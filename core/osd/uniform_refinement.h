// Uniform subdivision of a control mesh with OpenSubdiv (Far::TopologyRefiner::RefineUniform
// and Far::PrimvarRefiner): the mesh `levels` steps finer under the scheme, positions only.
// A refined closed convex mesh is a many-patch convex test object (the culling tests refine
// catmark_cube three times: 6 x 4^3 = 384 quads).
#pragma once

#include "core/mesh/mesh.h"
#include "core/osd/scheme.h"

namespace tb::osd {

// Throws InputError as buildTopologyRefiner does. The result has no normals or uvs; its faces
// are the last level's, and its tags those that give it the input's limit surface: interior
// edges still sharp after `levels` steps (semi-sharp creases lose 1 a step; infinitely sharp
// ones stay), the input's corners at their child vertices, the children of hole faces, and
// the input's boundary rule and crease method. So a production-size asset made from a
// bundled one (asset_catalog.h: `refine`) keeps its creases.
mesh::Mesh refineUniform(const mesh::Mesh& mesh, Scheme scheme, int levels);

}  // namespace tb::osd
