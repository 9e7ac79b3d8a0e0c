// Phong's buffers and per-patch record, for phong_surface.glsl / phong_build.glsl and
// techniques/phong/phong.cpp alike (shaders/common/layout/tb_layout.h).
#ifndef TB_PHONG_LAYOUT_H
#define TB_PHONG_LAYOUT_H

#include "../common/layout/tb_layout.h"

#define TB_PHONG_BINDING_POSITIONS 1
#define TB_PHONG_BINDING_NORMALS 2
#define TB_PHONG_BINDING_RECORDS 3

TB_LAYOUT_NAMESPACE_BEGIN

// The record's words: label -> corner (3), position (3), normal (3), edge-end normal (6).
const uint kTbPhongRecordWords = 15u;
const uint kTbPhongPosition = 3u;
const uint kTbPhongNormal = 6u;
const uint kTbPhongEdgeNormal = 9u;

TB_LAYOUT_NAMESPACE_END

#ifdef __cplusplus
namespace tb::gpu::layout {
struct TbPhongRecord {
  uint perm[3];         // canonical label -> face corner
  uint position[3];     // into the positions buffer
  uint normal[3];       // into the normals buffer
  uint edge_normal[6];  // per edge and end (the edge variant; 0 otherwise)
};
static_assert(sizeof(TbPhongRecord) == 4 * kTbPhongRecordWords);
static_assert(offsetof(TbPhongRecord, position) == 4 * kTbPhongPosition);
static_assert(offsetof(TbPhongRecord, normal) == 4 * kTbPhongNormal);
static_assert(offsetof(TbPhongRecord, edge_normal) == 4 * kTbPhongEdgeNormal);
}  // namespace tb::gpu::layout
#endif

#endif
