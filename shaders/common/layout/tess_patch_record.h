// The compute tessellator's patch record, which the shaders index by hand in a uint[]
// (gpu/tessellate.comp, gpu/policy_levels.comp): its words here, the C++ struct asserted
// against them.
#ifndef TB_LAYOUT_TESS_PATCH_RECORD_H
#define TB_LAYOUT_TESS_PATCH_RECORD_H

#include "tb_layout.h"

TB_LAYOUT_NAMESPACE_BEGIN

// Outer level bits [4], inner level bits [2], domain | spacing << 8, flags.
const uint kTbTessPatchRecordWords = 8u;
const uint kTbTessPatchInner = 4u;  // word of inner[0]
const uint kTbTessPatchCode = 6u;
const uint kTbTessPatchFlags = 7u;

TB_LAYOUT_NAMESPACE_END

#ifdef __cplusplus
namespace tb::gpu::layout {
struct TbTessPatchRecord {
  uint outer_bits[4];
  uint inner_bits[2];
  uint code;   // domain | spacing << 8
  uint flags;  // 1: cw winding, 2: point mode, 4: the tests' rounding-up control
};
static_assert(sizeof(TbTessPatchRecord) == 4 * kTbTessPatchRecordWords);
static_assert(offsetof(TbTessPatchRecord, inner_bits) == 4 * kTbTessPatchInner);
static_assert(offsetof(TbTessPatchRecord, code) == 4 * kTbTessPatchCode);
static_assert(offsetof(TbTessPatchRecord, flags) == 4 * kTbTessPatchFlags);
}  // namespace tb::gpu::layout
#endif

#endif
