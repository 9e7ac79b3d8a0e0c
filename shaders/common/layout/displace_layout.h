// The displacement's per-patch words (displace.glsl; host: techniques/common/
// displaced_patches.cpp): a header, then one TbDisplacePatch per program patch.
#ifndef TB_LAYOUT_DISPLACE_H
#define TB_LAYOUT_DISPLACE_H

#include "bindings.h"
#include "tb_layout.h"

TB_LAYOUT_NAMESPACE_BEGIN

TB_READONLY_BUFFER(TbDisplacePatches, 2, TB_BINDING_DISPLACEMENT_PATCHES) {
  TB_RUNTIME_ARRAY(uint, words);
}
TB_INSTANCE(tb_displace);

const uint kTbDisplaceHeaderWords = 4u;
const uint kTbDisplacePatchWords = 33u;

TB_LAYOUT_NAMESPACE_END

#ifdef __cplusplus
namespace tb::gpu::layout {
struct TbDisplaceHeader {
  uint resolution, border, tile_size, tiles_per_row;
};
// displace.glsl's tbDisplaceWord(k) reads word k of its patch's.
struct TbDisplacePatch {
  uint tile;  // own tile
  // Per corner: owner tile, owner corner | (owner is a triangle) << 8.
  uint corner[4][2];
  // Per edge: owner tile, owner edge | triangle << 8, reversed.
  uint edge[4][3];
  uint direction_bits[4][3];  // per corner: the displacement direction's x, y, z float bits
};
static_assert(sizeof(TbDisplaceHeader) == 4 * kTbDisplaceHeaderWords);
static_assert(sizeof(TbDisplacePatch) == 4 * kTbDisplacePatchWords);
static_assert(offsetof(TbDisplacePatch, corner) == 4 && offsetof(TbDisplacePatch, edge) == 36);
static_assert(offsetof(TbDisplacePatch, direction_bits) == 84);
}  // namespace tb::gpu::layout
#endif

#endif
