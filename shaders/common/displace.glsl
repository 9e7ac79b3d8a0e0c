// Displacement after evaluation (docs/derivations/displacement.md): every
// technique's TES reaches it through tbEmitVertex (patch_program_tes.glsl) when compiled as
// its "#displaced" build (TB_DISPLACEMENT defined; shaders/CMakeLists.txt). The CPU twin is
// techniques/common/displacement_sampling.h, DisplacedPatches::evaluateFloat: the same
// operations in the same order, `precise` so nothing is fused or reassociated.
//
//   set 2, binding 0   the map, a sampled image read with texelFetch (no filtering: the
//                      bilinear blend is done here, in the twin's order)
//   set 2, binding 1   TbDisplacePatches: header (resolution, border, tile_size,
//                      tiles_per_row), then kTbDisplacePatchWords words per program patch
//   constant_id 203    kTbDisplaceKind: 1 scalar (along the direction), 2 vector
//   constant_id 204    kTbDisplaceSampling: 0 naive, 1 watertight (seed 000: a shared
//                      corner or edge reads its owner's tile at the owner's (u, v))
//   constant_id 205    kTbDisplaceTriangle: the program's domain
#ifndef TB_DISPLACE_GLSL
#define TB_DISPLACE_GLSL

#include "float_order.glsl"
#include "patch_program.glsl"

layout(constant_id = 203) const uint kTbDisplaceKind = 1u;
layout(constant_id = 204) const uint kTbDisplaceSampling = 0u;
// 1 for a triangle-domain program (a TES cannot ask its own domain); (u, v) are then the
// weights of corners 0 and 1, else gl_TessCoord.xy.
layout(constant_id = 205) const uint kTbDisplaceTriangle = 0u;

#include "layout/bindings.h"
layout(set = 2, binding = TB_BINDING_DISPLACEMENT_MAP) uniform sampler2D tb_displacement_map;
// TbDisplacePatches (tb_displace) and its word counts: the host shares them.
#include "layout/displace_layout.h"

uint tbDisplaceWord(uint k) {
  return tb_displace.words[kTbDisplaceHeaderWords + tbPatchIndex() * kTbDisplacePatchWords + k];
}

// The local corner of c, or -1 (displacementSampling.h domainCorner).
int tbDomainCorner(bool triangle, vec3 c) {
  if (triangle) {
    for (int k = 0; k < 3; ++k) {
      if (c[k] == 1.0) return k;
    }
    return -1;
  }
  if ((c.x == 0.0 || c.x == 1.0) && (c.y == 0.0 || c.y == 1.0)) {
    if (c.y == 0.0) return c.x == 0.0 ? 0 : 1;
    return c.x == 1.0 ? 2 : 3;
  }
  return -1;
}

// The local edge of c strictly between corners, or -1; t from corner e to e + 1.
int tbDomainEdge(bool triangle, vec3 c, out float t) {
  t = 0.0;
  if (triangle) {
    for (int e = 0; e < 3; ++e) {
      if (c[(e + 2) % 3] == 0.0) {
        t = c[(e + 1) % 3];
        return e;
      }
    }
    return -1;
  }
  if (c.y == 0.0) { t = c.x; return 0; }
  if (c.x == 1.0) { t = c.y; return 1; }
  if (c.y == 1.0) { t = 1.0 - c.x; return 2; }
  if (c.x == 0.0) { t = 1.0 - c.y; return 3; }
  return -1;
}

vec2 tbCornerUv(bool triangle, uint corner) {
  if (triangle) return corner == 0u ? vec2(1.0, 0.0) : (corner == 1u ? vec2(0.0, 1.0) : vec2(0.0));
  const vec2 quad[4] = vec2[4](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));
  return quad[corner];
}

vec2 tbEdgeUv(bool triangle, uint edge, float t) {
  if (!triangle) {
    if (edge == 0u) return vec2(t, 0.0);
    if (edge == 1u) return vec2(1.0, t);
    if (edge == 2u) return vec2(1.0 - t, 1.0);
    return vec2(0.0, 1.0 - t);
  }
  float w[3] = float[3](0.0, 0.0, 0.0);
  w[edge] = 1.0 - t;
  w[(edge + 1u) % 3u] = t;
  return vec2(w[0], w[1]);
}

// Bilinear between the four texels around (u, v) of tile `tile` (sampleTile).
vec4 tbSampleTile(uint tile, float u, float v) {
  const uint resolution = tb_displace.words[0], border = tb_displace.words[1];
  const uint tile_size = tb_displace.words[2], per_row = tb_displace.words[3];
  precise float step = float(resolution) - 1.0;
  precise float left = float(border);
  precise float top = (float(tile_size) - 1.0) - float(border);
  precise float x = u * step + left;
  precise float y = top - v * step;
  const float last = float(tile_size) - 2.0;
  float x0 = floor(x), y0 = floor(y);
  x0 = x0 < 0.0 ? 0.0 : (x0 > last ? last : x0);
  y0 = y0 < 0.0 ? 0.0 : (y0 > last ? last : y0);
  precise float fx = x - x0, fy = y - y0;
  precise float gx = 1.0 - fx, gy = 1.0 - fy;
  const ivec2 texel = ivec2(int((tile % per_row) * tile_size + uint(x0)),
                            int((tile / per_row) * tile_size + uint(y0)));
  const vec4 a = texelFetch(tb_displacement_map, texel, 0);
  const vec4 b = texelFetch(tb_displacement_map, texel + ivec2(1, 0), 0);
  const vec4 d = texelFetch(tb_displacement_map, texel + ivec2(0, 1), 0);
  const vec4 e = texelFetch(tb_displacement_map, texel + ivec2(1, 1), 0);
  precise vec4 upper = a * gx + b * fx;
  precise vec4 lower = d * gx + e * fx;
  precise vec4 h = upper * gy + lower * fy;
  return h;
}

vec3 tbCornerDirection(uint k) {
  const uint base = 21u + 3u * k;
  return vec3(uintBitsToFloat(tbDisplaceWord(base)), uintBitsToFloat(tbDisplaceWord(base + 1u)),
              uintBitsToFloat(tbDisplaceWord(base + 2u)));
}

// displacementDirection in displacement_sampling.h.
vec3 tbDisplaceDirection(bool triangle, vec3 c) {
  const int k = tbDomainCorner(triangle, c);
  if (k >= 0) return tbCornerDirection(uint(k));
  const uint corners = triangle ? 3u : 4u;
  float t;
  const int e = tbDomainEdge(triangle, c, t);
  if (e >= 0) {
    const bool reversed = tbDisplaceWord(9u + 3u * uint(e) + 2u) != 0u;
    const vec3 from = tbCornerDirection(uint(e)), to = tbCornerDirection((uint(e) + 1u) % corners);
    precise float s = reversed ? 1.0 - t : t;
    const vec3 start = reversed ? to : from, end = reversed ? from : to;
    precise vec3 blend = start * (1.0 - s) + end * s;
    return tbNormalize(blend);
  }
  if (!triangle) {
    precise vec3 lower = tbCornerDirection(0u) * (1.0 - c.x) + tbCornerDirection(1u) * c.x;
    precise vec3 upper = tbCornerDirection(3u) * (1.0 - c.x) + tbCornerDirection(2u) * c.x;
    precise vec3 blend = lower * (1.0 - c.y) + upper * c.y;
    return tbNormalize(blend);
  }
  precise vec3 blend = (tbCornerDirection(0u) * c.x + tbCornerDirection(1u) * c.y) +
                       tbCornerDirection(2u) * c.z;
  return tbNormalize(blend);
}

// The displaced position of `position`, evaluated at gl_TessCoord of this patch.
vec3 tbDisplace(vec3 position) {
  const bool triangle = kTbDisplaceTriangle != 0u;
  const vec3 c = gl_TessCoord;
  uint tile = tbDisplaceWord(0u);
  vec2 uv = c.xy;
  if (kTbDisplaceSampling == 1u) {
    const int k = tbDomainCorner(triangle, c);
    float t;
    const int e = k >= 0 ? -1 : tbDomainEdge(triangle, c, t);
    if (k >= 0) {
      tile = tbDisplaceWord(1u + 2u * uint(k));
      const uint corner = tbDisplaceWord(2u + 2u * uint(k));
      uv = tbCornerUv((corner & 256u) != 0u, corner & 255u);
    } else if (e >= 0) {
      tile = tbDisplaceWord(9u + 3u * uint(e));
      const uint edge = tbDisplaceWord(10u + 3u * uint(e));
      const bool reversed = tbDisplaceWord(11u + 3u * uint(e)) != 0u;
      precise float s = reversed ? 1.0 - t : t;
      uv = tbEdgeUv((edge & 256u) != 0u, edge & 255u, s);
    }
  }
  const vec4 h = tbSampleTile(tile, uv.x, uv.y);
  if (kTbDisplaceKind == 2u) {
    precise vec3 moved = position + h.xyz;
    return moved;
  }
  precise vec3 moved = position + tbDisplaceDirection(triangle, c) * h.x;
  return moved;
}

#endif
