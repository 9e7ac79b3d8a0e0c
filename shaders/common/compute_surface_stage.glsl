// The stage built-ins a technique's shared TCS/TES bodies call, for the compute path
// (compute_surface.glsl): a technique's .comp includes this first, then its surface
// declarations and body fragments (shaders/<technique>/*_build.glsl, *_evaluate.glsl, the
// very text of its TCS's and TES's main), so both paths run the same float operations.
#ifndef TB_COMPUTE_SURFACE_STAGE_GLSL
#define TB_COMPUTE_SURFACE_STAGE_GLSL

// The program patch being built or evaluated (the TCS's and TES's tbPatchIndex()).
uint tb_stage_patch = 0u;
uint tbPatchIndex() { return tb_stage_patch; }

// What the TES body emitted (patch_program_tes.glsl's tbEmitVertex: position before any
// displacement, and normal).
vec3 tb_stage_position = vec3(0.0);
vec3 tb_stage_normal = vec3(0.0);
void tbEmitVertex(vec3 position, vec3 normal) {
  tb_stage_position = position;
  tb_stage_normal = normal;
}

#endif
