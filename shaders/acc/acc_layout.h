// ACC's buffer bindings, named for acc_surface.glsl and techniques/acc/acc.cpp alike.
#ifndef TB_ACC_LAYOUT_H
#define TB_ACC_LAYOUT_H

#define TB_ACC_BINDING_POSITIONS 1
#define TB_ACC_BINDING_RING_HEADERS 2
#define TB_ACC_BINDING_RING_SLOTS 3
#define TB_ACC_BINDING_PATCHES 4
#define TB_ACC_BINDING_STENCILS 5

#ifdef __cplusplus
#include <cstdint>

namespace tb::gpu::layout {
enum AccBinding : uint32_t {
  kAccBindingPositions = TB_ACC_BINDING_POSITIONS,
  kAccBindingRingHeaders = TB_ACC_BINDING_RING_HEADERS,
  kAccBindingRingSlots = TB_ACC_BINDING_RING_SLOTS,
  kAccBindingPatches = TB_ACC_BINDING_PATCHES,
  kAccBindingStencils = TB_ACC_BINDING_STENCILS,
};
}  // namespace tb::gpu::layout
#endif

#endif
