// Internal: a tb::Mesh as an OpenSubdiv Far::TopologyRefiner (vertex topology and
// the `t` tags; no face-varying data).
#pragma once

#include <opensubdiv/far/topologyRefiner.h>

#include <memory>

#include "core/mesh/mesh.h"
#include "core/osd/scheme.h"

namespace tb::osd {

// Sdc options from the mesh's tags: boundary interpolation (already mapped from the
// OBJ tag values), the crease method, and Catmark weights on triangles.
OpenSubdiv::Sdc::Options sdcOptions(const mesh::SubdivisionTags& tags);

// Throws InputError when the reference cannot represent the mesh: no faces, a
// non-triangle face under Loop, a tag naming a missing vertex or face, a negative or
// non-finite sharpness, or topology OpenSubdiv rejects (with its message).
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> buildTopologyRefiner(const mesh::Mesh& mesh,
                                                                       Scheme scheme);

}  // namespace tb::osd
