// ACC (Loop & Schaefer 2008) as functions the TCS/TES pair and the compute path (acc.comp,
// shaders/common/compute_surface.glsl) share, so both run the same float operations
// (techniques/acc/acc_patch.h is the CPU twin of the build; keep them in step). The build
// (define TB_SURFACE_BUILD before including) reads the storage buffers:
//   binding 1  positions, vec4 per ring centre (per vertex, then per extra crease sector)
//   binding 2  ring header per ring: (offset, valence, boundary, tangent mask offset)
//   binding 3  ring slots: (e_i, f_i)
//   binding 4  per patch 12 words: corner rings, ring slots, class, rotation, 0, 0
//   binding 5  stencil table: per class 4 x 16 weights, then the tangent masks
// tbAccPoint is one TCS invocation's work (one geometry control point from its corner
// vertex's 1-ring, any valence up to acc::kMaxValence; a corner point also its corner's
// limit tangents), tbAccTangentPatches invocation 0's (the two tangent patches from the
// points and those tangents), tbEvaluateAcc the TES's: the geometry patch in the variant's
// Bézier order (specialisation constant 0, shaders/common/bezier.glsl) and the normal from
// the tangent patches (the geometry derivatives in the no_tangent variant).
#ifndef TB_ACC_SURFACE_GLSL
#define TB_ACC_SURFACE_GLSL

#include "bezier.glsl"

layout(constant_id = 0) const uint kOrder = 2u;
layout(constant_id = 1) const uint kTangentPatches = 1u;

// What the TCS hands the TES: the 16 geometry points and the tangent patches' 12 + 12.
struct TbAccSurface {
  vec3 b[16];
  vec3 tu[12];
  vec3 tv[12];
};

#ifdef TB_SURFACE_BUILD
layout(std430, set = 0, binding = 1) readonly buffer Positions { vec4 positions[]; };
layout(std430, set = 0, binding = 2) readonly buffer RingHeaders { uvec4 ring_headers[]; };
layout(std430, set = 0, binding = 3) readonly buffer RingSlots { uvec2 ring_slots[]; };
layout(std430, set = 0, binding = 4) readonly buffer Patches { uint patch_words[]; };
layout(std430, set = 0, binding = 5) readonly buffer Stencils { float stencil[]; };

// Owner corner and role (0 corner, 1 edge to next corner, 2 edge to previous, 3 interior).
const uint kOwnerCorner[16] = uint[](0u, 0u, 1u, 1u, 0u, 0u, 1u, 1u, 3u, 3u, 2u, 2u, 3u, 3u, 2u, 2u);
const uint kOwnerRole[16] = uint[](0u, 1u, 2u, 0u, 2u, 3u, 3u, 1u, 1u, 3u, 3u, 2u, 0u, 2u, 1u, 0u);

struct Corner {
  uint vertex, slot, offset, valence, mask;
  bool boundary;
  uint weights;  // index of the corner's 16 weights in the stencil table
};

Corner loadCorner(uint patch_index, uint k) {
  const uint base = patch_index * 12u;
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

// Control point j of patch `patch_index`; for a corner point of an interior corner (with
// tangent patches) also its corner's limit tangents along the next and previous edge.
void tbAccPoint(uint patch_index, uint j, out vec3 point, out vec3 tangent_next,
                out vec3 tangent_prev) {
  const Corner owner = loadCorner(patch_index, kOwnerCorner[j]);
  point = controlPoint(owner, kOwnerRole[j]);
  tangent_next = vec3(0.0);
  tangent_prev = vec3(0.0);
  if (kTangentPatches != 0u && kOwnerRole[j] == 0u && !owner.boundary) {
    tangent_next = cornerTangent(owner, owner.slot);
    tangent_prev = cornerTangent(owner, owner.slot + 1u);
  }
}

// The tangent patches from the 16 points and the corner points' tangents (indexed by
// point; corner k's point is 0, 3, 15, 12).
void tbAccTangentPatches(uint patch_index, vec3 b[16], vec3 tangent_next[16],
                         vec3 tangent_prev[16], out vec3 tu[12], out vec3 tv[12]) {
  for (int r = 0; r < 4; ++r) {
    for (int i = 0; i < 3; ++i) tu[3 * r + i] = (b[4 * r + i + 1] - b[4 * r + i]) * 3.0;
  }
  for (int r = 0; r < 3; ++r) {
    for (int i = 0; i < 4; ++i) tv[4 * r + i] = (b[4 * (r + 1) + i] - b[4 * r + i]) * 3.0;
  }
  if (kTangentPatches != 0u) {
    Corner c[4] = Corner[](loadCorner(patch_index, 0u), loadCorner(patch_index, 1u),
                           loadCorner(patch_index, 2u), loadCorner(patch_index, 3u));
    float cosine[4];
    for (uint k = 0u; k < 4u; ++k) cosine[k] = W(c[k], 12u);
    // Limit tangents at interior corners (boundary corners keep the geometry's); corner k's
    // point is invocation 0, 3, 15, 12.
    if (!c[0].boundary) { tu[0] = tangent_next[0]; tv[0] = tangent_prev[0]; }
    if (!c[1].boundary) { tu[2] = -tangent_prev[3]; tv[3] = tangent_next[3]; }
    if (!c[2].boundary) { tu[11] = -tangent_next[15]; tv[11] = -tangent_prev[15]; }
    if (!c[3].boundary) { tu[9] = tangent_prev[12]; tv[8] = -tangent_next[12]; }
    vec3 x1, x2;
    crossTangents(cosine[0], cosine[1], tu[0], tu[1], tu[2], (b[5] - b[1]) * 3.0, (b[6] - b[2]) * 3.0, x1, x2);
    tv[1] = x1; tv[2] = x2;
    crossTangents(cosine[1], cosine[2], tv[3], tv[7], tv[11], (b[6] - b[7]) * 3.0, (b[10] - b[11]) * 3.0, x1, x2);
    tu[5] = -x1; tu[8] = -x2;
    crossTangents(cosine[3], cosine[2], tu[9], tu[10], tu[11], (b[9] - b[13]) * 3.0, (b[10] - b[14]) * 3.0, x1, x2);
    tv[9] = -x1; tv[10] = -x2;
    crossTangents(cosine[0], cosine[3], tv[0], tv[4], tv[8], (b[5] - b[4]) * 3.0, (b[9] - b[8]) * 3.0, x1, x2);
    tu[3] = x1; tu[6] = x2;
  }
}

TbAccSurface tbBuildAccSurface(uint patch_index) {
  TbAccSurface s;
  vec3 tangent_next[16], tangent_prev[16];
  for (uint j = 0u; j < 16u; ++j) {
    tbAccPoint(patch_index, j, s.b[j], tangent_next[j], tangent_prev[j]);
  }
  tbAccTangentPatches(patch_index, s.b, tangent_next, tangent_prev, s.tu, s.tv);
  return s;
}
#endif

void tbEvaluateAcc(TbAccSurface s, vec3 tess_coord, out vec3 position, out vec3 normal) {
  const vec2 uv = tess_coord.xy;
  position = (kOrder == kTbBezierSymmetricNoFmaImprecise ? tbEvaluateBicubicImprecise(s.b, uv)
                                                         : tbEvaluateBicubic(s.b, uv, kOrder));
  normal = normalize(cross(tbEvaluateTangentU(s.tu, uv), tbEvaluateTangentV(s.tv, uv)));
}

#endif
