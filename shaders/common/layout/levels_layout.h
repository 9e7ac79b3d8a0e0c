// The harness's per-patch levels (patch_program_tcs.glsl; host: core/gpu/patch_program.cpp).
#ifndef TB_LAYOUT_LEVELS_H
#define TB_LAYOUT_LEVELS_H

#include "bindings.h"
#include "tb_layout.h"

TB_LAYOUT_NAMESPACE_BEGIN

// One patch's levels as float bits, written by the CPU (runPatchProgram's per-patch
// levels; uniform levels are the same entry for every patch). 32 bytes per patch.
struct TbPatchLevels {
  uvec4 outer_bits;  // gl_TessLevelOuter[0..3]
  uvec4 inner_bits;  // gl_TessLevelInner[0..1] in .xy; .zw unused
};

TB_READONLY_BUFFER(TbLevels, 1, TB_BINDING_LEVELS) {
  TB_RUNTIME_ARRAY(TbPatchLevels, tb_patch_levels);
};

TB_LAYOUT_NAMESPACE_END

#ifdef __cplusplus
namespace tb::gpu::layout {
static_assert(sizeof(TbPatchLevels) == 32 && offsetof(TbPatchLevels, inner_bits) == 16);
}  // namespace tb::gpu::layout
#endif

#endif
