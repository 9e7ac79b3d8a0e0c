// Patch culling policies: the CPU twin of shaders/common/cull.glsl (same float operations in
// the same order, so its decision equals every technique's TCS's) and the packing of the
// policy and per-patch bounds for the device (gpu::TcsCullPolicy); the policies are described
// in cull.glsl and cullPolicyDescription(). The bounds (SurfacePatches::cullBounds) are
// rounded to float here, the cone widened by 1e-3 and a hull over 20 points replaced by its
// box: why, in docs/derivations/chord_margins.md ("The cone margin").
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "core/gpu/patch_program.h"
#include "core/mesh/vec.h"
#include "core/view/view.h"
#include "harness/lod/factor_policy.h"
#include "techniques/technique.h"

namespace tb::lod {

enum class CullPolicy : uint32_t {  // TbCullParams::policy
  kNone = 0,
  kBackfaceLp2 = 1,
  kFrustumLp2Global = 2,
  kFrustumLp2Exact = 3,
  kFrustumHull = 4,
  kCone = 5,
  kCombined = 6,
  kTangentPlane = 7,
  kTangentPlaneFrustum = 8,
};

// Every policy, kNone first.
std::span<const CullPolicy> allCullPolicies();
// "none", "backface_lp2", "frustum_lp2_global", "frustum_lp2_exact", "frustum_hull",
// "cone", "combined", "tangent_plane", "tangent_plane_frustum".
std::string_view cullPolicyName(CullPolicy policy);
std::optional<CullPolicy> parseCullPolicy(std::string_view name);
// One line for reports, with the source it follows.
std::string_view cullPolicyDescription(CullPolicy policy);
// True for the policies that never cull a patch covering a pixel (the hull, cone and
// tangent-plane tests): frustum_hull, cone, combined, tangent_plane, tangent_plane_frustum.
bool isConservative(CullPolicy policy);

// A policy's two halves, judged apart by the culling measure's efficiency by cause: the test
// that removes back-facing patches and the one that removes patches outside the frustum
// (kNone where the policy has no such half). combined = {cone, frustum_hull},
// tangent_plane_frustum = {tangent_plane, frustum_hull}.
struct CullPolicyHalves {
  CullPolicy back_facing = CullPolicy::kNone;
  CullPolicy outside_frustum = CullPolicy::kNone;
};
CullPolicyHalves cullPolicyHalves(CullPolicy policy);

// frustum_lp2_global's margin as a fraction of the asset's bounding-box diagonal.
inline constexpr double kGlobalMarginOfDiagonal = 0.02;
inline constexpr size_t kCullHullPoints = 20;  // kTbCullHullPoints
// tangent_plane culls only when every coefficient is below -margin (|E - O| max|n_k| +
// max|w_k|) (kTbCullTangentMargin): the float rounding of the coefficients and of the dot
// products is some 1e-7 of that, and like the cone's widening it keeps patches seen within
// about 0.06 degrees of edge-on, whose flat triangles the rasteriser's snapping can flip.
inline constexpr float kTangentPlaneMargin = 1e-3f;

// One patch as cull.glsl reads it (TbCullPatch), in float.
struct CullPatchBounds {
  uint32_t corner_count = 4;  // 3 for a triangle patch
  std::array<mesh::Vec3f, 4> corner_position{};
  // frustum_lp2_exact's margin at each corner (world units): the largest bulge over the
  // corners' flat triangle or quad of any patch around the corner's welded position.
  std::array<float, 4> corner_margin{};
  std::array<mesh::Vec3f, 4> corner_normal{};
  mesh::Vec3f cone_axis{0, 0, 0};
  float cone_sine = 2;            // sin of the cone's half angle; > 1: no cone (cone never culls)
  std::vector<mesh::Vec3f> hull;  // at most kCullHullPoints
  float displacement_bound = 0;   // world units; 0 until displacement maps exist
  // tangent_plane's Bernstein coefficients {n_k, w_k} of f = (E - O) . n_k + w_k
  // (tangent_plane.h) with O = corner_position[0], in float; empty when the patch has no
  // Bézier net or a displacement bound: then tangent_plane is the cone alone (it is the
  // cone or the tangent-plane hull test).
  std::vector<std::array<float, 4>> tangent_plane;
  float tangent_normal_max = 0;  // max |n_k| (world units squared), rounded up
  float tangent_offset_max = 0;  // max |w_k| (world units cubed), rounded up
  // The chord margin's constants (tangent_plane.h), rounded up: the net's reach R from O
  // (world units), G1 G2 and G2^2 (world units squared).
  float tangent_reach = 0, tangent_first_times_second = 0, tangent_second_squared = 0;
};

struct CullBounds {
  std::vector<CullPatchBounds> patches;      // SurfacePatches order
  float global_margin = 0;                   // world units
  size_t patches_without_hull = 0;           // technique gave no bounds: hull = the corners
  size_t patches_without_cone = 0;           // no bounds, or normals spanning 90 degrees or more
  size_t patches_without_tangent_plane = 0;  // no Bézier net: tangent_plane uses the cone
  // The chord margin's pattern factors at the level the bounds were made for
  // (tangent_plane.h chordFactors): quad K2, K3, triangle K2, K3, rounded up.
  std::array<float, 4> chord_factors{};
};

// The bytes of per-patch cull data (TbCullPatch) the policy's test reads for one patch, mean
// over the patches: the header (16) and, per policy, each used corner's position (16) and
// normal (16), the cone (16), each used hull point (16), and tangent_plane's header (16),
// chord bound (16) and coefficients (16 each; the cone and hull where a patch has none). What a
// user pays per patch for the policy's culls; 0 for none. (The device's TbCullPatch stride is 512
// bytes whatever the policy: every policy's data in one layout; the coefficients are apart.)
double cullBytesPerPatch(CullPolicy policy, const std::vector<CullPatchBounds>& patches);

// The bounds of every patch: corners from `corners` (factorCorners), hull and cone from
// SurfacePatches::cullBounds. world_scale: the bounding-box diagonal (the global margin).
// level: the lowest uniform integer tessellation level the patches are drawn at, for
// tangent_plane's chord margin (a higher level only makes the margin more generous).
CullBounds cullBounds(const techniques::SurfacePatches& patches, const FactorCorners& corners,
                      double world_scale, float level);

// The policy and the view as the shader reads them (TbCullParamsBlock), in float.
struct CullParams {
  // Unit-normal world-space frustum planes (x, y, z, w), inside when xyz . p + w >= 0: left,
  // right, top, bottom, near, far of Vulkan's clip volume (|x|, |y| <= w, 0 <= z <= w).
  std::array<std::array<float, 4>, 6> planes{};
  mesh::Vec3f eye{0, 0, 0};
  float global_margin = 0;
  CullPolicy policy = CullPolicy::kNone;
  std::array<float, 4> chord_factors{};  // CullBounds::chord_factors
};
CullParams cullParams(CullPolicy policy, const view::View& view, const CullBounds& bounds);

// The twin of tbCullPatch: true when the policy culls the patch.
bool cullsPatch(const CullParams& params, const CullPatchBounds& patch);
// Per SurfacePatches patch: 1 when culled.
std::vector<uint8_t> cullDecisions(const CullParams& params, const CullBounds& bounds);

// The device's input for `program` (one of the patches' gpuPrograms()): bounds in program
// patch order (GpuPatchProgram::patch_ids). The two halves apart, for callers that pack the
// bounds once and the view per frame: cullParamWords (TcsCullPolicy::param_words) and
// cullPatchData (::patch_words and ::tangent_words; param_words left empty).
gpu::TcsCullPolicy tcsCullPolicy(const CullParams& params, const CullBounds& bounds,
                                 const gpu::GpuPatchProgram& program);
std::vector<uint32_t> cullParamWords(const CullParams& params);
gpu::TcsCullPolicy cullPatchData(const CullBounds& bounds, const gpu::GpuPatchProgram& program);

}  // namespace tb::lod
