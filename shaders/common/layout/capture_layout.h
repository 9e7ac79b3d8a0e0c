// The TES capture (patch_program_tes.glsl) and its records, which the compute path's
// vertices share (compute_surface.glsl); host: core/gpu/patch_program.h.
#ifndef TB_LAYOUT_CAPTURE_H
#define TB_LAYOUT_CAPTURE_H

#include "bindings.h"
#include "capture_record.h"
#include "tb_layout.h"

TB_LAYOUT_NAMESPACE_BEGIN

TB_BUFFER(TbCapture, 0, TB_BINDING_CAPTURE) {
  uint count;     // vertices written (atomic); may exceed capacity on overflow
  uint capacity;  // vertices that fit in words[]
  uint reserved0;
  uint reserved1;
  TB_RUNTIME_ARRAY(uint, words);
}
TB_INSTANCE(tb_capture);

TB_LAYOUT_NAMESPACE_END

#ifdef __cplusplus
namespace tb::gpu::layout {
static_assert(sizeof(TbCapture) == 16);  // words[] starts here
}  // namespace tb::gpu::layout
#endif

#endif
