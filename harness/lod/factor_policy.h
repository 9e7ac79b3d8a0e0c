// View-dependent tessellation-factor policies: the CPU twin of
// shaders/common/tess_factors.glsl (same float operations in the same order, so the levels
// equal every technique's TCS's bit for bit) and the packing for the device
// (gpu::TcsFactorPolicy). Each edge's factor comes from its two welded end corners in
// lexicographic order (docs/ARCHITECTURE.md §5, rule 3). The policies (Dudash 2012, Lost
// Planet 2, error_bound) are specified in docs/derivations/factor_policy.md.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/gpu/patch_program.h"
#include "core/mesh/vec.h"
#include "core/tess/tessellator.h"
#include "core/view/view.h"
#include "harness/lod/error_bound.h"
#include "techniques/technique.h"

namespace tb::lod {

enum class FactorPolicyKind : uint32_t {  // TbFactorParams::policy
  kUniform = 0,
  kDistance = 1,
  kSphereDiameter = 2,
  kLp2Edge = 3,
  kErrorBound = 4,
};

enum class InnerReduction : uint32_t { kAverage = 0, kMax = 1, kMin = 2 };

struct FactorPolicy {
  FactorPolicyKind kind = FactorPolicyKind::kSphereDiameter;
  bool silhouette = false;       // lp2_edge only
  bool roundness = false;        // lp2_edge only
  bool order_dependent = false;  // any policy; not crack-safe
  bool loose = false;            // error_bound only: eps doubled (a control)
  bool dense_edges = false;      // error_bound only: edges at every equal-segment level (a control)
  double target = 8;             // see the header comment for its unit per policy
  InnerReduction reduction = InnerReduction::kAverage;
  double min_scale = 0.25;          // s_min of the reductions, (0, 1]
  double roundness_angle_deg = 20;  // a: end normals turning this much get the full factor

  // "sphere_diameter", "lp2_edge_silhouette", "distance_order_dependent", ...
  std::string name() const;
  // The unit of `target` for this policy ("level", "px/edge", "C").
  const char* targetUnit() const;
};

// The policy named `name` (as name() writes it) with its default target; nullopt when no
// policy has that name.
std::optional<FactorPolicy> parseFactorPolicy(std::string_view name);

// The default target of each kind: uniform 8 (a level), distance 16 (the level at one
// diagonal), sphere_diameter 8 px per edge, lp2_edge 0.15 (about 8 px per edge at a
// 45 degree field of view: C = P[1][1] / (2 * 8)).
double defaultTarget(FactorPolicyKind kind);

// One patch corner as the policy reads it.
struct FactorCorner {
  mesh::Vec3f position;  // welded control-mesh position, world units
  mesh::Vec3f normal;    // the welded position's unit normal (area-weighted face normals)
};

// The corners of every patch (SurfacePatches order; a triangle's 4th is zero).
struct FactorCorners {
  std::vector<std::array<FactorCorner, 4>> patches;
  std::vector<techniques::PatchDomain> domains;
  // error_bound's inputs, one per patch (errorBounds()); empty until a caller that runs
  // error_bound sets them.
  std::vector<ErrorBoundPatch> error_bounds;
};
FactorCorners factorCorners(const techniques::SurfacePatches& patches);

// The policy and the view as the shader reads them (TbFactorParamsBlock), in float.
struct FactorParams {
  std::array<float, 16> view_projection{};  // column-major
  mesh::Vec3f eye;
  float viewport_height_px = 1;
  float projection_y_scale = 1;
  float target = 1;       // distance: already times the diagonal (world_scale)
  float pixel_scale = 1;  // H / (2 target)
  float min_scale = 1;
  float roundness_span = 1;  // 1 - cos(roundness angle)
  uint32_t policy = 0, flags = 0, reduction = 0, spacing = 0;
  // error_bound: world error per unit of clip w (target / (f_px k), doubled when loose), the
  // near plane's clip w, and |row 3 of the matrix's xyz| (a sphere's nearest clip w is
  // w(centre) - radius * this).
  float error_scale = 0;
  float near_w = 0;
  float hull_w_scale = 0;
  // error_bound's projection stretch per screen axis (x, y): |row r of the matrix's xyz|,
  // 1 / |P[r][r]| and tan(fov / 2).
  std::array<float, 2> row_length{}, inv_scale{}, tan_half{};
  // error_bound's view sides w + x, w - x, w + y, w - y: |xyz| of their rows' sums, so a
  // sphere wholly outside one (or behind the near plane) gets the lowest level.
  std::array<float, 4> side_length{};
};
// world_scale: the asset's bounding-box diagonal (distance's unit).
FactorParams factorParams(const FactorPolicy& policy, const view::View& view, tess::Spacing spacing,
                          double world_scale);

// The twin of tbEdgeFactor: the raw factor of the edge from corner a to corner b.
float edgeFactor(const FactorParams& params, const FactorCorner& a, const FactorCorner& b);

// The twin of tbErrorBoundEps: the world error that projects to the pixel target at the
// sphere's nearest clip w, or the near plane's where the sphere reaches it (> 0); +inf when
// the sphere is wholly outside the view: behind the near plane or outside a side.
float errorBoundEps(const FactorParams& params, const std::array<float, 4>& sphere);

// The twin of tbPolicyLevels: one patch's levels (culled patches: all 0). error_bound reads
// `bound` (std::logic_error when null).
tess::Levels policyLevels(const FactorParams& params, techniques::PatchDomain domain,
                          const std::array<FactorCorner, 4>& corners,
                          const ErrorBoundPatch* bound = nullptr);
std::vector<tess::Levels> policyLevels(const FactorParams& params, const FactorCorners& corners);

// error_bound's patches with no inside level within the bound, given their edges (fixed by
// the shared records). The edges take levels from a family that stitches narrowly to a
// common inside level (transition_extents.h, narrowEdgeLevel), and the inside reads the
// largest eps of the record's spheres, which is at least each edge's; so a patch is unmet
// only where it needs more than the tessellator's top level (fractional_odd's 63 is not
// narrow with 33: there this is measured, not proven; error_bound_test.cpp asserts it on
// the CI cases and, on request, on every bundled asset and path).
struct ErrorBoundUnmet {
  size_t patches = 0;     // unmet patches; best 0, worst all of them
  size_t beyond_top = 0;  // of those, unmet even with every level at the top; best = patches
};
// Zeros for other policies.
ErrorBoundUnmet errorBoundUnmetPatches(const FactorParams& params, const FactorCorners& corners);

// The device's input for `program` (one of the patches' gpuPrograms()): corners in program
// patch order (GpuPatchProgram::patch_ids) and the parameter words for its domain.
gpu::TcsFactorPolicy tcsFactorPolicy(const FactorParams& params, const FactorCorners& corners,
                                     const gpu::GpuPatchProgram& program);

}  // namespace tb::lod
