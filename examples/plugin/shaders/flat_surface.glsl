// `flat`'s surface as functions its TCS/TES and its compute shader (flat.comp) share, so the
// compute path (tessbench's core/gpu/compute_path.h) runs the TES's float operations bit for
// bit. tbBuildFlatSurface (define TB_SURFACE_BUILD before including; it reads the storage
// buffers) is the TCS's work for one patch, tbEvaluateFlatSurface the TES's at one point.
#ifndef FLAT_SURFACE_GLSL
#define FLAT_SURFACE_GLSL

#include "float_order.glsl"

// What the TCS hands the TES: the triangle's corners and normals in the face's corner order.
struct TbFlatSurface {
  vec3 p[3];
  vec3 n[3];
};

#ifdef TB_SURFACE_BUILD
layout(std430, set = 0, binding = 1) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 2) readonly buffer Normals { vec4 normals[]; };
// 6 words per patch: position index (3), normal index (3), in the face's corner order.
layout(std430, set = 0, binding = 3) readonly buffer Corners { uint corners[]; };

TbFlatSurface tbBuildFlatSurface(uint patch_index) {
  const uint base = patch_index * 6u;
  TbFlatSurface s;
  for (uint i = 0u; i < 3u; ++i) {
    s.p[i] = positions[corners[base + i]].xyz;
    s.n[i] = normals[corners[base + 3u + i]].xyz;
  }
  return s;
}
#endif

// Linear interpolation at tess_coord, in the operation order of flat_technique.cpp
// evaluateLinear (the float twin the crack measure compares against).
void tbEvaluateFlatSurface(TbFlatSurface s, vec3 tess_coord, out vec3 position,
                           out vec3 normal) {
  const vec3 w = tess_coord;
  precise vec3 p = s.p[0] * w.x + s.p[1] * w.y + s.p[2] * w.z;
  precise vec3 normal_sum = s.n[0] * w.x + s.n[1] * w.y + s.n[2] * w.z;
  position = p;
  normal = tbNormalize(normal_sum);
}

#endif
