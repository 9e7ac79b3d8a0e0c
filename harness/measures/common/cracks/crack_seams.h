// Where a shared edge or corner lies: on a seam (the control mesh's faces disagree there on a
// corner's normal or uv, or use different positions welded together: where an engine's mesh
// splits its vertices, as a glTF file stores them), on the mesh's boundary, or inside. The
// crack measure counts each kind's gaps apart (row key edge_kind; docs/MEASURES.md).
#pragma once

#include <cstdint>

namespace tb::mesh {
struct Mesh;
struct Welding;
}  // namespace tb::mesh

namespace tb::measures {

enum class EdgeKind : uint8_t { kInterior, kSeam, kBoundary };
const char* toString(EdgeKind kind);  // "interior", "seam", "boundary"
inline constexpr EdgeKind kEdgeKinds[] = {EdgeKind::kSeam, EdgeKind::kInterior,
                                          EdgeKind::kBoundary};

struct SharedBoundaries;

// Sets the kind of every edge and corner of `shared` from `control` (the patches' control
// mesh) welded by `welding`: an edge is a seam when it is one already (SharedEdge::seam) or
// its faces' corners at either end carry different normal or uv values (bitwise); a corner
// is a seam at a welded vertex whose faces disagree so or that welds several positions, else
// boundary on an edge of one face, else interior. Shared edges are never boundary.
void classifySeams(const mesh::Mesh& control, const mesh::Welding& welding,
                   SharedBoundaries* shared);

}  // namespace tb::measures
