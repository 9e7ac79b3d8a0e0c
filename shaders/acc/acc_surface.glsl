// ACC's declarations shared by acc.tesc, acc.tese and the compute path (acc.comp): the
// variant switches; with TB_SURFACE_BUILD the TCS's buffers and functions (techniques/acc/
// acc_patch.h is the CPU twin; keep them in step):
//   binding 1  positions, vec4 per ring centre (per vertex, then per extra crease sector)
//   binding 2  ring header per ring: (offset, valence, boundary, tangent mask offset)
//   binding 3  ring slots: (e_i, f_i)
//   binding 4  per patch 12 words: corner rings, ring slots, class, rotation, 0, 0
//   binding 5  stencil table: per class 4 x 16 weights, then the tangent masks
// The stages' bodies are acc_point.glsl, acc_tangent_patches.glsl and acc_evaluate.glsl.
#ifndef TB_ACC_SURFACE_GLSL
#define TB_ACC_SURFACE_GLSL

layout(constant_id = 0) const uint kOrder = 2u;
layout(constant_id = 1) const uint kTangentPatches = 1u;

#ifdef TB_SURFACE_BUILD
#include "acc_layout.h"
layout(std430, set = 0, binding = TB_ACC_BINDING_POSITIONS) readonly buffer Positions {
  vec4 positions[];
};
layout(std430, set = 0, binding = TB_ACC_BINDING_RING_HEADERS) readonly buffer RingHeaders {
  uvec4 ring_headers[];
};
layout(std430, set = 0, binding = TB_ACC_BINDING_RING_SLOTS) readonly buffer RingSlots {
  uvec2 ring_slots[];
};
layout(std430, set = 0, binding = TB_ACC_BINDING_PATCHES) readonly buffer Patches {
  uint patch_words[];
};
layout(std430, set = 0, binding = TB_ACC_BINDING_STENCILS) readonly buffer Stencils {
  float stencil[];
};

// Owner corner and role (0 corner, 1 edge to next corner, 2 edge to previous, 3 interior).
const uint kOwnerCorner[16] = uint[](0u, 0u, 1u, 1u, 0u, 0u, 1u, 1u, 3u, 3u, 2u, 2u, 3u, 3u, 2u, 2u);
const uint kOwnerRole[16] = uint[](0u, 1u, 2u, 0u, 2u, 3u, 3u, 1u, 1u, 3u, 3u, 2u, 0u, 2u, 1u, 0u);

struct Corner {
  uint vertex, slot, offset, valence, mask;
  bool boundary;
  uint weights;  // index of the corner's 16 weights in the stencil table
};

Corner loadCorner(uint k) {
  const uint base = tbPatchIndex() * 12u;
  Corner c;
  c.vertex = patch_words[base + k];
  c.slot = patch_words[base + 4u + k];
  const uint cls = patch_words[base + 8u];
  const uint rotation = patch_words[base + 9u];
  const uvec4 header = ring_headers[c.vertex];
  c.offset = header.x;
  c.valence = header.y;
  c.boundary = header.z != 0u;
  c.mask = header.w;
  c.weights = cls * 64u + ((k + 4u - rotation) % 4u) * 16u;
  return c;
}

vec3 P(uint i) { return positions[i].xyz; }
vec3 E(Corner c, uint i) { return P(ring_slots[c.offset + i % c.valence].x); }
vec3 F(Corner c, uint i) { return P(ring_slots[c.offset + i % c.valence].y); }
float W(Corner c, uint i) { return stencil[c.weights + i]; }

vec3 controlPoint(Corner c, uint role) {
  const uint n = c.valence;
  const vec3 v = P(c.vertex);
  precise vec3 acc;
  if (role == 0u) {
    acc = v * W(c, 0u);
    if (c.boundary) {
      acc = acc + (E(c, 0u) + E(c, n - 1u)) * W(c, 1u);  // commutative: crease sectors agree
    } else {
      for (uint i = 0u; i < n; ++i) acc = acc + E(c, i) * W(c, 1u) + F(c, i) * W(c, 2u);
    }
  } else if (role == 3u) {
    acc = v * W(c, 7u) + E(c, c.slot) * W(c, 8u) + E(c, c.slot + 1u) * W(c, 8u) +
          F(c, c.slot) * W(c, 9u);
  } else {
    const uint i = c.slot + (role == 2u ? 1u : 0u);
    if (c.boundary && (i == 0u || i == n - 1u)) {
      acc = v * W(c, 10u) + E(c, i) * W(c, 11u);
    } else {
      const uint prev = i + n - 1u;
      acc = v * W(c, 3u) + E(c, i) * W(c, 4u) + E(c, prev) * W(c, 5u) + E(c, i + 1u) * W(c, 5u) +
            F(c, prev) * W(c, 6u) + F(c, i) * W(c, 6u);
    }
  }
  return acc;
}

vec3 cornerTangent(Corner c, uint i) {
  const uint n = c.valence;
  precise vec3 acc = vec3(0.0);
  for (uint j = 0u; j < n; ++j) {
    const uint r = (j + n - i % n) % n;
    acc = acc + E(c, j) * stencil[c.mask + r] + F(c, j) * stencil[c.mask + n + r];
  }
  return acc;
}

void crossTangents(float ca, float cb, vec3 a0, vec3 a1, vec3 a2, vec3 d1, vec3 d2,
                   out vec3 x1, out vec3 x2) {
  const float third = 1.0 / 3.0;
  x1 = (a1 * (2.0 * ca) - a0 * cb) * third + d1;
  x2 = (a2 * ca - a1 * (2.0 * cb)) * third + d2;
}
#endif

#endif
