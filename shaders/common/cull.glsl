// Patch culling in every technique's TCS, when the harness turns it on (kTbCullPolicy != 0,
// see patch_program_tcs.glsl): a culled patch gets outer level 0, so the tessellator drops
// it and no TES invocation runs for it. The CPU twin is harness/measures/cull_policy.{h,cpp}:
// same float operations in the same order, so its decision equals the TCS's for every patch
// (tests/measures/cull_policy_gpu_test.cpp).
//
//   set 1, binding 4   the policy and the view (TbCullParams)
//   set 1, binding 5   per patch: corners, the cone of normals and the control hull
//   set 1, binding 6   tangent_plane's Bernstein coefficients, which TbCullPatch::tangent indexes
//
// Policies (TbCullParams::policy):
// - backface_lp2: every corner's normal faces away from the eye, n . (eye - p) < 0 (CAPCOM,
//   "Lost Planet 2: DirectX 11 Features"). Not conservative: a curved patch bulges past its
//   corners' normals.
// - frustum_lp2_global / frustum_lp2_exact: the talk's clip flags, AND-ed over the corners:
//   every corner lies more than a margin outside one of the six frustum planes. The margin is
//   one global distance, or per corner the largest bulge of the patches around it over their
//   corners (the talk's "exact" suggestion, from the control hulls).
// - frustum_hull: every point of the patch's control hull lies outside one plane
//   (conservative: the patch lies in the convex hull of its control points).
// - cone: back-patch culling with the cone of normals (Shirman & Abi-Ezzi, "The Cone of
//   Normals Technique for Fast Processing of Curved Patches", Eurographics 1993): the patch's
//   geometric normals lie within angle t of the axis a; it faces away everywhere when every
//   hull point q has angle(q - eye, a) < 90 deg - t, i.e. (q - eye) . a > |q - eye| sin t.
// - combined: frustum_hull or cone.
// - tangent_plane: back-patch culling with the parametric tangent plane (Loop, Niessner &
//   Eisenacher, "Effective Back-Patch Culling for Hardware Tessellation", VMV 2011): the
//   Bernstein coefficients c_k = (eye - O) . n_k + w_k of f = (eye - P) . (P_u x P_v), O the
//   patch's first corner, precomputed per patch (harness/lod/tangent_plane.h); culled when
//   every c_k < -(margin (|eye - O| max|n_k| + max|w_k|) + chord margin), the chord margin
//   (|eye - O| + R) (G1 G2 K2 + G2^2 K3) covering the tessellated triangles, whose planes are
//   chords of the surface; or the cone culls it (the cone alone for a patch without
//   coefficients: not polynomial), so it culls at least what the cone culls.
// - tangent_plane_frustum: frustum_hull or tangent_plane.
// Each test widens by the patch's displacement bound (world units; 0 until displacement).
#ifndef TB_CULL_GLSL
#define TB_CULL_GLSL

#include "float_order.glsl"

// The descriptor set of the harness's bindings (see tess_factors.glsl): 1 in a TCS, 0 in
// the compute levels pass.
#ifndef TB_HARNESS_SET
#define TB_HARNESS_SET 1
#endif

// TbCullParams::policy
const uint kTbCullBackfaceLp2 = 1u;
const uint kTbCullFrustumLp2Global = 2u;
const uint kTbCullFrustumLp2Exact = 3u;
const uint kTbCullFrustumHull = 4u;
const uint kTbCullCone = 5u;
const uint kTbCullCombined = 6u;
const uint kTbCullTangentPlane = 7u;
const uint kTbCullTangentPlaneFrustum = 8u;

const float kTbCullTangentMargin = 1e-3;  // harness/lod/cull_policy.h kTangentPlaneMargin

// Harness specialisation constant: 0, no culling; 1, the TCS culls with the policy
// TbCullParams::policy names (set 1, bindings 4 and 5) by writing outer level 0;
// kTbCullPolicyFixed + p, policy p fixed at compile time, so one policy's instructions can be
// counted (the culling measure's tcs_instructions). Frozen at 0 where shaders are counted.
layout(constant_id = 202) const uint kTbCullPolicy = 0u;
const uint kTbCullPolicyFixed = 100u;

// TbCullParamsBlock (tb_cull), TbCullPatch and the tangent planes: the host shares them.
#include "layout/cull_layout.h"

// Signed distance of p to plane k (positive inside).
float tbPlaneDistance(uint k, vec3 p) {
  precise float d = tbDot(tb_cull.planes[k].xyz, p) + tb_cull.planes[k].w;
  return d;
}

bool tbCullBackfaceLp2(uint patch_index) {
  const uint corners = tb_cull_patches[patch_index].header.x;
  const vec3 eye = tb_cull.eye.xyz;
  for (uint c = 0u; c < corners; ++c) {
    const vec3 p = tb_cull_patches[patch_index].corner_position[c].xyz;
    const vec3 n = tb_cull_patches[patch_index].corner_normal[c].xyz;
    precise vec3 to_eye = eye - p;
    if (!(tbDot(n, to_eye) < 0.0)) return false;
  }
  return true;
}

bool tbCullFrustumCorners(uint patch_index, bool exact) {
  const uint corners = tb_cull_patches[patch_index].header.x;
  const float displacement = uintBitsToFloat(tb_cull_patches[patch_index].header.z);
  for (uint k = 0u; k < 6u; ++k) {
    bool outside = true;
    for (uint c = 0u; c < corners && outside; ++c) {
      const vec4 corner = tb_cull_patches[patch_index].corner_position[c];
      precise float margin = (exact ? corner.w : tb_cull.global_margin) + displacement;
      outside = tbPlaneDistance(k, corner.xyz) < -margin;
    }
    if (outside) return true;
  }
  return false;
}

bool tbCullFrustumHull(uint patch_index) {
  const uint points = tb_cull_patches[patch_index].header.y;
  const float displacement = uintBitsToFloat(tb_cull_patches[patch_index].header.z);
  for (uint k = 0u; k < 6u; ++k) {
    bool outside = true;
    for (uint i = 0u; i < points && outside; ++i) {
      outside = tbPlaneDistance(k, tb_cull_patches[patch_index].hull[i].xyz) < -displacement;
    }
    if (outside) return true;
  }
  return false;
}

bool tbCullCone(uint patch_index) {
  const vec4 cone = tb_cull_patches[patch_index].cone;
  if (!(cone.w <= 1.0)) return false;
  const uint points = tb_cull_patches[patch_index].header.y;
  const float displacement = uintBitsToFloat(tb_cull_patches[patch_index].header.z);
  const vec3 eye = tb_cull.eye.xyz;
  for (uint i = 0u; i < points; ++i) {
    precise vec3 d = tb_cull_patches[patch_index].hull[i].xyz - eye;
    precise float along = tbDot(d, cone.xyz) - displacement;
    precise float reach = (sqrt(tbDot(d, d)) + displacement) * cone.w;
    if (!(along > reach)) return false;
  }
  return true;
}

bool tbCullTangentPlaneHull(uint patch_index) {
  const uvec4 tangent = tb_cull_patches[patch_index].tangent;
  if (tangent.y == 0u) return false;
  precise vec3 d = tb_cull.eye.xyz - tb_cull_patches[patch_index].corner_position[0].xyz;
  precise float distance = sqrt(tbDot(d, d));
  precise float reach = distance * uintBitsToFloat(tangent.z) + uintBitsToFloat(tangent.w);
  const vec4 bound = tb_cull_patches[patch_index].tangent_chord;
  const bool quad = tb_cull_patches[patch_index].header.x == 4u;
  const float k2 = quad ? tb_cull.chord_factors.x : tb_cull.chord_factors.z;
  const float k3 = quad ? tb_cull.chord_factors.y : tb_cull.chord_factors.w;
  precise float chord = (distance + bound.x) * (bound.y * k2 + bound.z * k3);
  precise float tolerance = kTbCullTangentMargin * reach + chord;
  for (uint k = 0u; k < tangent.y; ++k) {
    const vec4 c = tb_cull_tangent_planes[tangent.x + k];
    precise float f = tbDot(d, c.xyz) + c.w;
    if (!(f < -tolerance)) return false;
  }
  return true;
}

bool tbCullTangentPlane(uint patch_index) {
  return tbCullCone(patch_index) || tbCullTangentPlaneHull(patch_index);
}

// True when the policy culls patch `patch_index`.
bool tbCullPatch(uint patch_index) {
  const uint policy =
      kTbCullPolicy >= kTbCullPolicyFixed ? kTbCullPolicy - kTbCullPolicyFixed : tb_cull.policy;
  if (policy == kTbCullBackfaceLp2) return tbCullBackfaceLp2(patch_index);
  if (policy == kTbCullFrustumLp2Global) return tbCullFrustumCorners(patch_index, false);
  if (policy == kTbCullFrustumLp2Exact) return tbCullFrustumCorners(patch_index, true);
  if (policy == kTbCullFrustumHull) return tbCullFrustumHull(patch_index);
  if (policy == kTbCullCone) return tbCullCone(patch_index);
  if (policy == kTbCullCombined) return tbCullFrustumHull(patch_index) || tbCullCone(patch_index);
  if (policy == kTbCullTangentPlane) return tbCullTangentPlane(patch_index);
  if (policy == kTbCullTangentPlaneFrustum) {
    return tbCullFrustumHull(patch_index) || tbCullTangentPlane(patch_index);
  }
  return false;
}

#endif
