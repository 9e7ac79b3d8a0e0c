// The contract between a technique's TCS/TES and core/gpu/patch_program.h.
// Include it from both stages; then include patch_program_tcs.glsl in the TCS or
// patch_program_tes.glsl in the TES for the stage helpers.
//
//   set 0, binding 0       capture buffer (tbCaptureVertex)
//   set 0, bindings 1..N   the technique's storage buffers, in GpuPatchProgram order
//   set 1, binding 0       the harness's per-patch tessellation levels (TCS only; see
//                          patch_program_tcs.glsl), indexed by tbPatchIndex()
//   set 1, bindings 1..3   the factor policy's corners, parameters and written levels
//                          (TCS only; tess_factors.glsl)
//   set 1, bindings 4..5   the culling policy's parameters and per-patch bounds (TCS only;
//                          cull.glsl)
//   set 2, bindings 0..1   the displacement map and its per-patch words ("#displaced"
//                          TES builds only; displace.glsl)
//   push constants         this block
//   constant_id 0..M-1     GpuPatchProgram::specialization (declare them in the shader)
//   constant_id 200        the harness's kTbCaptureBoundary (patch_program_tes.glsl)
//   constant_id 201        the harness's kTbFactorPolicy (patch_program_tcs.glsl)
//   constant_id 202        the harness's kTbCullPolicy (patch_program_tcs.glsl)
//   constant_id 203..205   the displacement's kind, sampling and domain (displace.glsl)
#ifndef TB_PATCH_PROGRAM_GLSL
#define TB_PATCH_PROGRAM_GLSL

layout(push_constant) uniform TbPatchProgramPush {
  uint first_patch;      // patch index of gl_PrimitiveID 0 in this draw
  uint capture_enabled;  // 0: do not write the capture buffer (timing runs)
} tb_push;

// Index of the patch being processed, into the technique's per-patch data.
uint tbPatchIndex() { return tb_push.first_patch + uint(gl_PrimitiveID); }

#endif
