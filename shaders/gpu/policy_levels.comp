#version 460
// Every patch's tessellation levels in compute, one invocation a patch, with the same factor
// and culling policies every technique's TCS runs through tbWriteHarnessLevels
// (common/patch_program_tcs.glsl): the same includes, common/tess_factors.glsl and
// common/cull.glsl, so the levels are the TCS's bit for bit. The levels go (a) into the compute tessellator's patch records
// (tessellate.comp, binding 0 here and there), which its count pass then reads in the same
// command buffer, and (b) into the read-back buffer the TCS also writes (binding 3, the
// TbFactorOut layout). Host side: core/gpu/compute_levels.h.
//
// One dispatch is one job: one policy (and view) over one program's patches, whose records
// start at record `first_record` of the batch. The harness bindings sit at set 0 here:
//   binding 0      the tessellator's patch records, 8 words a record (see below)
//   bindings 1..3  tess_factors.glsl: corners, TbFactorParams, the read-back levels
//   bindings 4..6  cull.glsl: TbCullParams, per-patch bounds, tangent-plane coefficients
#extension GL_GOOGLE_include_directive : require

#define TB_HARNESS_SET 0
#include "tess_factors.glsl"
#include "cull.glsl"
#include "layout/tess_patch_record.h"

layout(local_size_x = 64) in;

// Per record kTbTessPatchRecordWords words (layout/tess_patch_record.h TbTessPatchRecord). This pass
// writes the levels and leaves the host's code and flags words alone.
layout(std430, set = 0, binding = TB_BINDING_TESS_PATCH_RECORDS) buffer TessPatchRecords {
  uint tb_record_words[];
};

layout(push_constant) uniform Job {
  uint patch_count;   // patches of this job (its program's)
  uint first_record;  // record of its patch 0, in binding 0 and in the read-back (binding 3)
  uint factor;        // 1: levels from the factor policy; 0: the record's levels as given
  uint cull;          // 1: outer levels 0 where the culling policy culls the patch
} job;

void main() {
  const uint patch_index = gl_GlobalInvocationID.x;
  if (patch_index >= job.patch_count) return;
  const uint record = job.first_record + patch_index;
  const uint w = kTbTessPatchRecordWords * record;
  float outer[4];
  float inner[2];
  if (job.factor != 0u) {
    tbPolicyLevels(patch_index, outer, inner);
  } else {
    for (uint j = 0u; j < 4u; ++j) outer[j] = uintBitsToFloat(tb_record_words[w + j]);
    for (uint j = 0u; j < 2u; ++j) inner[j] = uintBitsToFloat(tb_record_words[w + kTbTessPatchInner + j]);
  }
  if (job.cull != 0u && tbCullPatch(patch_index)) outer = float[4](0.0, 0.0, 0.0, 0.0);
  for (uint j = 0u; j < 4u; ++j) tb_record_words[w + j] = floatBitsToUint(outer[j]);
  for (uint j = 0u; j < 2u; ++j) tb_record_words[w + kTbTessPatchInner + j] = floatBitsToUint(inner[j]);
  tbWriteBackLevels(record, outer, inner);
}
