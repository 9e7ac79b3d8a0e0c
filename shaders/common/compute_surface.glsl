// The compute path's entry point (core/gpu/compute_path.h): a technique's surface evaluated
// without the tessellator, by the very code of its TCS and TES, so the float operations are
// the TES's. A technique's .comp includes compute_surface_stage.glsl (tbPatchIndex and
// tbEmitVertex for the shared bodies), its declarations and body fragments, then defines
//   TB_SURFACE                  its surface struct (what the TCS hands the TES)
//   TB_BUILD_SURFACE()          the TCS's work for patch tbPatchIndex(), returning TB_SURFACE
//   TB_EVALUATE_SURFACE(s, coord)   the TES's at one point, ending in tbEmitVertex
//   TB_SURFACE_TRIANGLES        (defined or not) the triangle domain: coord.z = (1 - u) - v
// and includes this file. Two passes, chosen by the push constant `pass`:
//   pass 0  one invocation per program patch builds its TB_SURFACE into tb_surfaces[]
//   pass 1  one invocation per domain point of the compute tessellator (tessellate.comp)
//           finds the point's patch, makes gl_TessCoord's float bits from its 16.16 (u, v)
//           as lavapipe does (core/gpu/compute_tessellator.h toTessellation), evaluates and
//           writes the TES capture's 10-word record (patch_program_tes.glsl).
// Set 0: the technique's storage buffers at bindings 1..7 (GpuPatchProgram order), the
// harness's at 8..12. Each invocation's loops are short (lavapipe's gallivm leaves a loop
// after 65,535 iterations of one invocation).
#ifndef TB_COMPUTE_SURFACE_GLSL
#define TB_COMPUTE_SURFACE_GLSL

#include "layout/bindings.h"
#include "layout/capture_record.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = TB_BINDING_COMPUTE_SURFACES) buffer TbSurfaces {
  TB_SURFACE tb_surfaces[];
};
// The compute tessellator's offsets (first point, first index word per patch) and status
// (totals), tessellate.comp's bindings 2 and 3.
layout(std430, set = 0, binding = TB_BINDING_COMPUTE_TESS_OFFSETS) readonly buffer TbTessOffsets {
  uvec2 tb_tess_offsets[];
};
layout(std430, set = 0, binding = TB_BINDING_COMPUTE_TESS_STATUS) readonly buffer TbTessStatus {
  uint total_points;
  uint total_index_words;
  uint errors;
} tb_tess_status;
layout(std430, set = 0, binding = TB_BINDING_COMPUTE_TESS_POINTS) readonly buffer TbTessPoints {
  uvec2 tb_tess_points[];
};
// kTbCaptureWords per point (layout/capture_record.h TbCaptureRecord).
layout(std430, set = 0, binding = TB_BINDING_COMPUTE_VERTICES) writeonly buffer TbVertices {
  uint tb_vertex_words[];
};

layout(push_constant) uniform TbComputeSurfacePush {
  uint pass;         // 0 build, 1 evaluate
  uint patch_count;  // program patches
  // The tests' broken control: 0 none; 1 evaluate at u one float ulp up inside the domain
  // (the record keeps the true coordinate).
  uint control;
} tb_compute;

// The patch holding point `point`: the last patch whose first point is <= point (an empty
// patch shares its first point with the next one). About 17 steps for 10^5 patches.
uint tbPointPatch(uint point) {
  uint low = 0u, high = tb_compute.patch_count - 1u;
  while (low < high) {
    const uint mid = (low + high + 1u) / 2u;
    if (tb_tess_offsets[mid].x <= point) {
      low = mid;
    } else {
      high = mid - 1u;
    }
  }
  return low;
}

// gl_TessCoord as lavapipe makes it: u, v exactly (16.16 -> float), w = (1 - u) - v on
// triangles, 0 on quads.
vec3 tbTessCoord(uvec2 fixed_uv) {
  const float u = float(fixed_uv.x) * (1.0 / 65536.0), v = float(fixed_uv.y) * (1.0 / 65536.0);
#ifdef TB_SURFACE_TRIANGLES
  precise float w = (1.0 - u) - v;
  return vec3(u, v, w);
#else
  return vec3(u, v, 0.0);
#endif
}

void tbEvaluatePoint(uint point) {
  const uint patch_index = tbPointPatch(point);
  const vec3 coord = tbTessCoord(tb_tess_points[point]);
  vec3 eval_coord = coord;
  if (tb_compute.control == 1u && coord.x > 0.0 && coord.x < 1.0) {
    eval_coord.x = uintBitsToFloat(floatBitsToUint(coord.x) + 1u);
  }
  tb_stage_patch = patch_index;
  TB_EVALUATE_SURFACE(tb_surfaces[patch_index], eval_coord);
  const vec3 position = tb_stage_position, normal = tb_stage_normal;
  const uint base = point * kTbCaptureWords;
  tb_vertex_words[base + 0u] = patch_index;
  tb_vertex_words[base + 1u] = floatBitsToUint(coord.x);
  tb_vertex_words[base + 2u] = floatBitsToUint(coord.y);
  tb_vertex_words[base + 3u] = floatBitsToUint(coord.z);
  tb_vertex_words[base + 4u] = floatBitsToUint(position.x);
  tb_vertex_words[base + 5u] = floatBitsToUint(position.y);
  tb_vertex_words[base + 6u] = floatBitsToUint(position.z);
  tb_vertex_words[base + 7u] = floatBitsToUint(normal.x);
  tb_vertex_words[base + 8u] = floatBitsToUint(normal.y);
  tb_vertex_words[base + 9u] = floatBitsToUint(normal.z);
}

// The pass: the push constant, or fixed at compile time in the "#build" (0) and "#evaluate"
// (1) builds the instructions measure counts (shaders/CMakeLists.txt).
#ifdef TB_COMPUTE_PASS
const uint kTbComputePass = TB_COMPUTE_PASS;
#endif

void main() {
  const uint i = gl_GlobalInvocationID.x;
#ifdef TB_COMPUTE_PASS
  const uint tb_pass = kTbComputePass;
#else
  const uint tb_pass = tb_compute.pass;
#endif
  if (tb_pass == 0u) {
    if (i < tb_compute.patch_count) {
      tb_stage_patch = i;
      tb_surfaces[i] = TB_BUILD_SURFACE();
    }
  } else if (i < tb_tess_status.total_points) {
    tbEvaluatePoint(i);
  }
}

#endif
