// Uniform subdivision of a control mesh with OpenSubdiv (Far::TopologyRefiner::RefineUniform
// and Far::PrimvarRefiner): the mesh `levels` steps finer under the scheme, positions only.
// A refined closed convex mesh is a many-patch convex test object (the culling tests refine
// catmark_cube three times: 6 x 4^3 = 384 quads).
#pragma once

#include "core/mesh/mesh.h"
#include "core/osd/scheme.h"

namespace tb::osd {

// Throws InputError as buildTopologyRefiner does. The result has no normals, uvs or tags
// (creases are applied while refining, then dropped); its faces are the last level's.
mesh::Mesh refineUniform(const mesh::Mesh& mesh, Scheme scheme, int levels);

}  // namespace tb::osd
