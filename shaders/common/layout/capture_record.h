// Word records the shaders index by hand in a uint[] (no block of their own): the word count
// here, the C++ record struct asserted against it. GLSL emits every const a shader declares,
// so each record has a header of its own.
#ifndef TB_LAYOUT_CAPTURE_RECORD_H
#define TB_LAYOUT_CAPTURE_RECORD_H

#include "tb_layout.h"

TB_LAYOUT_NAMESPACE_BEGIN

// The TES capture's and the compute path's vertex record (patch_program_tes.glsl,
// compute_surface.glsl): patch, gl_TessCoord bits (3), position (3), normal (3).
const uint kTbCaptureWords = 10u;

TB_LAYOUT_NAMESPACE_END

#ifdef __cplusplus
namespace tb::gpu::layout {
struct TbCaptureRecord {
  uint patch;
  uint coord_bits[3];
  uint position_bits[3];
  uint normal_bits[3];
};
static_assert(sizeof(TbCaptureRecord) == 4 * kTbCaptureWords);
static_assert(offsetof(TbCaptureRecord, position_bits) == 16);
static_assert(offsetof(TbCaptureRecord, normal_bits) == 28);
}  // namespace tb::gpu::layout
#endif

#endif
