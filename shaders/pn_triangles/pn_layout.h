// PN triangles' buffers and per-patch record (techniques/common/triangle_records.h), for
// pn_surface.glsl / pn_build.glsl and techniques/pn_triangles/pn_build.cpp alike.
#ifndef TB_PN_LAYOUT_H
#define TB_PN_LAYOUT_H

#include "../common/layout/tb_layout.h"

#define TB_PN_BINDING_POSITIONS 1
#define TB_PN_BINDING_NORMALS 2
#define TB_PN_BINDING_RECORDS 3

TB_LAYOUT_NAMESPACE_BEGIN

// The record's words (TriangleRecordWord): perm, position, normal, geometry normal, flags
// (3 each), the other normal per edge end (6), edge scale float bits (3).
const uint kTbPnRecordWords = 24u;
const uint kTbPnPosition = 3u;
const uint kTbPnNormal = 6u;
const uint kTbPnGeometryNormal = 9u;
const uint kTbPnFlags = 12u;
const uint kTbPnOtherNormal = 15u;
const uint kTbPnEdgeScale = 21u;

TB_LAYOUT_NAMESPACE_END

#ifdef __cplusplus
namespace tb::gpu::layout {
struct TbPnRecord {
  uint perm[3], position[3], normal[3], geometry_normal[3], flags[3];
  uint other_normal[3][2];
  float edge_scale[3];
};
static_assert(sizeof(TbPnRecord) == 4 * kTbPnRecordWords);
static_assert(offsetof(TbPnRecord, position) == 4 * kTbPnPosition);
static_assert(offsetof(TbPnRecord, normal) == 4 * kTbPnNormal);
static_assert(offsetof(TbPnRecord, geometry_normal) == 4 * kTbPnGeometryNormal);
static_assert(offsetof(TbPnRecord, flags) == 4 * kTbPnFlags);
static_assert(offsetof(TbPnRecord, other_normal) == 4 * kTbPnOtherNormal);
static_assert(offsetof(TbPnRecord, edge_scale) == 4 * kTbPnEdgeScale);
}  // namespace tb::gpu::layout
#endif

#endif
