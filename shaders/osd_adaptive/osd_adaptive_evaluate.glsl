// What osd_adaptive.tese's main runs, shared with the compute path (osd_adaptive.comp):
// base face tbPatchIndex()'s Far patches at TB_TESS_COORD (gl_TessCoord there), ending in
// tbEmitVertex. Defines the function TB_EVALUATE_FUNCTION names: main() in the TES; on the
// compute path the surface's evaluator, whose fields TB_EVALUATE_PROLOGUE unpacks
// (TB_EVALUATE_EPILOGUE, if any, ends it).
#ifndef TB_OSD_ADAPTIVE_EVALUATE_GLSL
#define TB_OSD_ADAPTIVE_EVALUATE_GLSL

void TB_EVALUATE_FUNCTION {
#ifdef TB_EVALUATE_PROLOGUE
  TB_EVALUATE_PROLOGUE
#endif
  const uint face = tbPatchIndex();
  const float u = clamp(TB_TESS_COORD.x, 0.0, 1.0), v = clamp(TB_TESS_COORD.y, 0.0, 1.0);
  // The first sub-patch of the face covering (u, v); they tile the face, the last is only
  // a fallback (evaluateFloat searches the same way).
  const uvec2 range = face_ranges[face];
  uvec2 sub = sub_patches[range.x + range.y - 1u];
  for (uint k = range.x; k < range.x + range.y; ++k) {
    const uvec2 candidate = sub_patches[k];
    const float scale = float(1u << subDepth(candidate.x));
    if (cellOf(u, scale) == float(candidate.x & 1023u) &&
        cellOf(v, scale) == float((candidate.x >> 10u) & 1023u)) {
      sub = candidate;
      break;
    }
  }
  const float scale = float(1u << subDepth(sub.x));
  precise float s = u * scale - float(sub.x & 1023u);
  precise float t = v * scale - float((sub.x >> 10u) & 1023u);
  float w[20], ws[20], wt[20];
  const int count = subPatchWeights(sub.x, s, t, w, ws, wt);
  precise vec3 position = vec3(0.0), tangent_s = vec3(0.0), tangent_t = vec3(0.0);
  // Two loops of constant length (16, then 4 more for a Gregory end cap), so the compiler
  // unrolls them and keeps the weights in registers.
  for (int k = 0; k < 16; ++k) {
    const vec3 q = points[point_indices[sub.y + uint(k)]].xyz;
    position = position + q * w[k];
    tangent_s = tangent_s + q * ws[k];
    tangent_t = tangent_t + q * wt[k];
  }
  if (count == 20) {
    for (int k = 16; k < 20; ++k) {
      const vec3 q = points[point_indices[sub.y + uint(k)]].xyz;
      position = position + q * w[k];
      tangent_s = tangent_s + q * ws[k];
      tangent_t = tangent_t + q * wt[k];
    }
  }
  // cross(tangent_s, tangent_t) in core/mesh/vec.h's order, then v * (1 / |v|) or zero.
  precise vec3 n = vec3(tangent_s.y * tangent_t.z - tangent_s.z * tangent_t.y,
                        tangent_s.z * tangent_t.x - tangent_s.x * tangent_t.z,
                        tangent_s.x * tangent_t.y - tangent_s.y * tangent_t.x);
  precise float len = sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  precise vec3 normal = len > 0.0 ? n * (1.0 / len) : vec3(0.0);
  tbEmitVertex(position, normal);
#ifdef TB_EVALUATE_EPILOGUE
  TB_EVALUATE_EPILOGUE
#endif
}

#endif
