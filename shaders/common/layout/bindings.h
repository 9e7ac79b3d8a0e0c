// The named bindings of the harness's blocks, for GLSL's layout(binding = ...) and the host.
#ifndef TB_LAYOUT_BINDINGS_H
#define TB_LAYOUT_BINDINGS_H

// Set 0 of a patch program: the TES capture; the technique's buffers follow at 1..N.
#define TB_BINDING_CAPTURE 0
#define TB_BINDING_FIRST_TECHNIQUE 1
// The harness set (TB_HARNESS_SET: 1 in a TCS, 0 in gpu/policy_levels.comp).
#define TB_BINDING_LEVELS 0
#define TB_BINDING_FACTOR_PATCHES 1
#define TB_BINDING_FACTOR_PARAMS 2
#define TB_BINDING_FACTOR_OUT 3
#define TB_BINDING_CULL_PARAMS 4
#define TB_BINDING_CULL_PATCHES 5
#define TB_BINDING_CULL_TANGENT_PLANES 6
// gpu/policy_levels.comp's set 0 and gpu/tessellate.comp's binding 0: the patch records.
#define TB_BINDING_TESS_PATCH_RECORDS 0
// Set 2 of a "#displaced" TES (displace.glsl).
#define TB_BINDING_DISPLACEMENT_MAP 0
#define TB_BINDING_DISPLACEMENT_PATCHES 1
// A compute-path shader's set 0 (compute_surface.glsl): technique buffers 1..7, then these.
#define TB_BINDING_COMPUTE_SURFACES 8
#define TB_BINDING_COMPUTE_TESS_OFFSETS 9
#define TB_BINDING_COMPUTE_TESS_STATUS 10
#define TB_BINDING_COMPUTE_TESS_POINTS 11
#define TB_BINDING_COMPUTE_VERTICES 12

#ifdef __cplusplus
#include <cstdint>

namespace tb::gpu::layout {

enum Binding : uint32_t {
  kBindingCapture = TB_BINDING_CAPTURE,
  kBindingFirstTechnique = TB_BINDING_FIRST_TECHNIQUE,
  kBindingLevels = TB_BINDING_LEVELS,
  kBindingFactorPatches = TB_BINDING_FACTOR_PATCHES,
  kBindingFactorParams = TB_BINDING_FACTOR_PARAMS,
  kBindingFactorOut = TB_BINDING_FACTOR_OUT,
  kBindingCullParams = TB_BINDING_CULL_PARAMS,
  kBindingCullPatches = TB_BINDING_CULL_PATCHES,
  kBindingCullTangentPlanes = TB_BINDING_CULL_TANGENT_PLANES,
  kBindingTessPatchRecords = TB_BINDING_TESS_PATCH_RECORDS,
  kBindingDisplacementMap = TB_BINDING_DISPLACEMENT_MAP,
  kBindingDisplacementPatches = TB_BINDING_DISPLACEMENT_PATCHES,
  kBindingComputeSurfaces = TB_BINDING_COMPUTE_SURFACES,
  kBindingComputeTessOffsets = TB_BINDING_COMPUTE_TESS_OFFSETS,
  kBindingComputeTessStatus = TB_BINDING_COMPUTE_TESS_STATUS,
  kBindingComputeTessPoints = TB_BINDING_COMPUTE_TESS_POINTS,
  kBindingComputeVertices = TB_BINDING_COMPUTE_VERTICES,
};

}  // namespace tb::gpu::layout
#endif

#endif
