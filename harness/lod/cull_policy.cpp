#include "harness/lod/cull_policy.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>

#include "harness/lod/tangent_plane.h"

namespace tb::lod {
namespace {

constexpr double kConeSineWidening = 1e-3;  // see cull_policy.h
constexpr int kConeAxisIterations = 32;

constexpr CullPolicy kAllPolicies[] = {
    CullPolicy::kNone,
    CullPolicy::kBackfaceLp2,
    CullPolicy::kFrustumLp2Global,
    CullPolicy::kFrustumLp2Exact,
    CullPolicy::kFrustumHull,
    CullPolicy::kCone,
    CullPolicy::kCombined,
    CullPolicy::kTangentPlane,
    CullPolicy::kTangentPlaneFrustum,
};

// The shader's helpers, in its operation order (shaders/common/float_order.glsl).
float dotF(const mesh::Vec3f& a, const mesh::Vec3f& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
mesh::Vec3f subF(const mesh::Vec3f& a, const mesh::Vec3f& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

mesh::Vec3f toFloat(const mesh::Vec3d& v) { return {float(v[0]), float(v[1]), float(v[2])}; }
mesh::Vec3d toDouble(const mesh::Vec3f& v) { return {v[0], v[1], v[2]}; }

// tbPlaneDistance.
float planeDistance(const std::array<float, 4>& plane, const mesh::Vec3f& p) {
  return dotF({plane[0], plane[1], plane[2]}, p) + plane[3];
}

// Closest distance from p to the triangle (a, b, c) (Ericson, "Real-Time Collision
// Detection", 5.1.5: by the Voronoi region of p).
double pointTriangleDistance(const mesh::Vec3d& p, const mesh::Vec3d& a, const mesh::Vec3d& b,
                             const mesh::Vec3d& c) {
  const mesh::Vec3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return length(p - a);
  const mesh::Vec3d bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return length(p - b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return length(p - (a + ab * (d1 / (d1 - d3))));
  const mesh::Vec3d cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return length(p - c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return length(p - (a + ac * (d2 / (d2 - d6))));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
  }
  const double denom = 1 / (va + vb + vc);
  return length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

// How far the control hull reaches beyond the corners' flat triangle (a quad: the nearer
// of its two triangles (0,1,2), (0,2,3)). Bounds the surface's bulge over any point of the
// corners' convex hull, since the surface lies in the control hull.
double bulge(const std::vector<mesh::Vec3d>& hull, const std::array<mesh::Vec3d, 4>& corner,
             bool quad) {
  double worst = 0;
  for (const mesh::Vec3d& h : hull) {
    double d = pointTriangleDistance(h, corner[0], corner[1], corner[2]);
    if (quad) d = std::min(d, pointTriangleDistance(h, corner[0], corner[2], corner[3]));
    worst = std::max(worst, d);
  }
  return worst;
}

// A cone (unit axis, sine of the half angle) containing every generator's direction, or
// nullopt when they span 90 degrees or more. The axis starts at the mean direction and moves
// towards the worst generator (Badoiu-Clarkson steps); the narrowest cone seen is kept.
std::optional<std::pair<mesh::Vec3d, double>> normalCone(
    const std::vector<mesh::Vec3d>& generators) {
  std::vector<mesh::Vec3d> units;
  for (const mesh::Vec3d& g : generators) {
    const double len = length(g);
    if (len > 0) units.push_back(g * (1 / len));
  }
  if (units.empty()) return std::nullopt;
  mesh::Vec3d sum{0, 0, 0};
  for (const mesh::Vec3d& u : units) sum = sum + u;
  if (!(length(sum) > 1e-12)) return std::nullopt;
  mesh::Vec3d axis = normalize(sum);
  mesh::Vec3d best_axis = axis;
  double best_cos = -2;
  for (int step = 0; step < kConeAxisIterations; ++step) {
    double worst_cos = 2;
    const mesh::Vec3d* worst = nullptr;
    for (const mesh::Vec3d& u : units) {
      const double c = dot(axis, u);
      if (c < worst_cos) worst_cos = c, worst = &u;
    }
    if (worst_cos > best_cos) best_cos = worst_cos, best_axis = axis;
    const mesh::Vec3d moved = axis + (*worst - axis) * (1.0 / (step + 2));
    if (!(length(moved) > 1e-12)) break;
    axis = normalize(moved);
  }
  if (!(best_cos > 1e-3)) return std::nullopt;
  const double sine = std::sqrt(std::max(0.0, 1 - best_cos * best_cos));
  return std::make_pair(best_axis, sine);
}

std::vector<mesh::Vec3d> boxCorners(const std::vector<mesh::Vec3d>& points) {
  mesh::Vec3d lo = points[0], hi = points[0];
  for (const mesh::Vec3d& p : points) {
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  }
  std::vector<mesh::Vec3d> corners;
  for (int k = 0; k < 8; ++k) {
    corners.push_back({(k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]});
  }
  return corners;
}

using PositionKey = std::array<uint32_t, 3>;
PositionKey positionKey(const mesh::Vec3f& p) {
  return {std::bit_cast<uint32_t>(p[0]), std::bit_cast<uint32_t>(p[1]),
          std::bit_cast<uint32_t>(p[2])};
}

// tangent_plane's coefficients about the patch's first corner, rounded to float, and their
// largest magnitudes rounded up (the margin's scale).
void setTangentPlane(techniques::PatchDomain domain, const techniques::PatchCullBounds& bounds,
                     CullPatchBounds& out) {
  if (out.displacement_bound != 0) return;
  const std::vector<TangentPlaneCoefficient> coefficients =
      tangentPlaneCoefficients(domain, bounds, toDouble(out.corner_position[0]));
  double normal_max = 0, offset_max = 0;
  for (const TangentPlaneCoefficient& c : coefficients) {
    out.tangent_plane.push_back({float(c[0]), float(c[1]), float(c[2]), float(c[3])});
    normal_max = std::max(normal_max, std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
    offset_max = std::max(offset_max, std::abs(c[3]));
  }
  constexpr float kInf = std::numeric_limits<float>::infinity();
  out.tangent_normal_max = std::nextafter(float(normal_max), kInf);
  out.tangent_offset_max = std::nextafter(float(offset_max), kInf);
  const TangentPlaneChordBound chord =
      tangentPlaneChordBound(domain, bounds, toDouble(out.corner_position[0]));
  out.tangent_reach = std::nextafter(float(chord.reach), kInf);
  out.tangent_first_times_second = std::nextafter(float(chord.first_times_second), kInf);
  out.tangent_second_squared = std::nextafter(float(chord.second_squared), kInf);
}

}  // namespace

std::span<const CullPolicy> allCullPolicies() { return kAllPolicies; }

std::string_view cullPolicyName(CullPolicy policy) {
  switch (policy) {
    case CullPolicy::kNone:
      return "none";
    case CullPolicy::kBackfaceLp2:
      return "backface_lp2";
    case CullPolicy::kFrustumLp2Global:
      return "frustum_lp2_global";
    case CullPolicy::kFrustumLp2Exact:
      return "frustum_lp2_exact";
    case CullPolicy::kFrustumHull:
      return "frustum_hull";
    case CullPolicy::kCone:
      return "cone";
    case CullPolicy::kCombined:
      return "combined";
    case CullPolicy::kTangentPlane:
      return "tangent_plane";
    case CullPolicy::kTangentPlaneFrustum:
      return "tangent_plane_frustum";
  }
  return "?";
}

std::optional<CullPolicy> parseCullPolicy(std::string_view name) {
  for (CullPolicy policy : kAllPolicies) {
    if (cullPolicyName(policy) == name) return policy;
  }
  return std::nullopt;
}

std::string_view cullPolicyDescription(CullPolicy policy) {
  switch (policy) {
    case CullPolicy::kNone:
      return "no culling: every patch runs through the TES";
    case CullPolicy::kBackfaceLp2:
      return "culled when every corner normal faces away from the eye, n . (eye - p) < 0 "
             "(CAPCOM, \"Lost Planet 2: DirectX 11 Features\"); not conservative";
    case CullPolicy::kFrustumLp2Global:
      return "culled when every corner is more than a margin (2% of the bounding-box diagonal) "
             "outside one frustum plane: the clip flags AND-ed over the corners (CAPCOM, \"Lost "
             "Planet 2: DirectX 11 Features\"); not conservative";
    case CullPolicy::kFrustumLp2Exact:
      return "the same clip flags with a per-vertex margin: the largest bulge over their flat "
             "corners of the patches around the vertex, from their control hulls (the talk's "
             "\"exact\" suggestion)";
    case CullPolicy::kFrustumHull:
      return "culled when the convex hull of the patch's control points lies outside one "
             "frustum plane; conservative";
    case CullPolicy::kCone:
      return "back-patch culling with a cone of the geometric normals dp/du x dp/dv from the "
             "normal patch's control points (Shirman & Abi-Ezzi, \"The Cone of Normals Technique "
             "for Fast Processing of Curved Patches\", Eurographics 1993; Sederberg & Meyers "
             "1988 for the normal patch): culled when every control-hull point sees the eye "
             "outside the cone's back-facing region; conservative";
    case CullPolicy::kCombined:
      return "frustum_hull or cone; conservative";
    case CullPolicy::kTangentPlane:
      return "back-patch culling with the parametric tangent plane (Loop, Niessner & Eisenacher, "
             "\"Effective Back-Patch Culling for Hardware Tessellation\", VMV 2011): culled when "
             "every Bernstein coefficient of (E - P) . (P_u x P_v) is below minus a chord margin "
             "(the tessellated triangles' planes are chords of the surface: a margin from the "
             "net's first and second differences and the level), one dot product per "
             "coefficient, or when the cone culls it (the cone alone for a patch that is not "
             "polynomial: Gregory with unequal face points, Phong's edge variant, displaced "
             "and osd_adaptive patches); conservative";
    case CullPolicy::kTangentPlaneFrustum:
      return "frustum_hull or tangent_plane; conservative";
  }
  return "";
}

double cullBytesPerPatch(CullPolicy policy, const std::vector<CullPatchBounds>& patches) {
  if (policy == CullPolicy::kNone || patches.empty()) return 0;
  constexpr double kHeader = 16, kVec4 = 16;
  double total = 0;
  for (const CullPatchBounds& patch : patches) {
    const double corners = patch.corner_count * kVec4, hull = double(patch.hull.size()) * kVec4;
    switch (policy) {
      case CullPolicy::kBackfaceLp2:
        total += kHeader + 2 * corners;
        break;
      case CullPolicy::kFrustumLp2Global:
      case CullPolicy::kFrustumLp2Exact:
        total += kHeader + corners;
        break;
      case CullPolicy::kFrustumHull:
        total += kHeader + hull;
        break;
      case CullPolicy::kCone:
      case CullPolicy::kCombined:
        total += kHeader + kVec4 + hull;
        break;
      case CullPolicy::kTangentPlane:
      case CullPolicy::kTangentPlaneFrustum: {
        // The tangent header, then the chord bound and the coefficients, or the cone.
        const double tangent = kVec4 + double(patch.tangent_plane.size()) * kVec4;
        total += kHeader + kVec4 + (patch.tangent_plane.empty() ? kVec4 + hull : tangent);
        if (policy == CullPolicy::kTangentPlaneFrustum && !patch.tangent_plane.empty()) {
          total += hull;
        }
        break;
      }
      case CullPolicy::kNone:
        break;
    }
  }
  return total / double(patches.size());
}

CullPolicyHalves cullPolicyHalves(CullPolicy policy) {
  switch (policy) {
    case CullPolicy::kBackfaceLp2:
    case CullPolicy::kCone:
      return {policy, CullPolicy::kNone};
    case CullPolicy::kFrustumLp2Global:
    case CullPolicy::kFrustumLp2Exact:
    case CullPolicy::kFrustumHull:
      return {CullPolicy::kNone, policy};
    case CullPolicy::kCombined:
      return {CullPolicy::kCone, CullPolicy::kFrustumHull};
    case CullPolicy::kTangentPlane:
      return {policy, CullPolicy::kNone};
    case CullPolicy::kTangentPlaneFrustum:
      return {CullPolicy::kTangentPlane, CullPolicy::kFrustumHull};
    case CullPolicy::kNone:
      break;
  }
  return {};
}

bool isConservative(CullPolicy policy) {
  return policy == CullPolicy::kFrustumHull || policy == CullPolicy::kCone ||
         policy == CullPolicy::kCombined || policy == CullPolicy::kTangentPlane ||
         policy == CullPolicy::kTangentPlaneFrustum;
}

CullBounds cullBounds(const techniques::SurfacePatches& patches, const FactorCorners& corners,
                      double world_scale, float level) {
  CullBounds result;
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const std::array<double, 2> quad_k = chordFactors(tess::Domain::kQuad, level);
  const std::array<double, 2> triangle_k = chordFactors(tess::Domain::kTriangle, level);
  result.chord_factors = {
      std::nextafter(float(quad_k[0]), kInf), std::nextafter(float(quad_k[1]), kInf),
      std::nextafter(float(triangle_k[0]), kInf), std::nextafter(float(triangle_k[1]), kInf)};
  result.global_margin = float(kGlobalMarginOfDiagonal * world_scale);
  const size_t count = patches.patchCount();
  result.patches.resize(count);
  std::vector<double> patch_bulge(count, 0);
  for (size_t p = 0; p < count; ++p) {
    CullPatchBounds& out = result.patches[p];
    const bool quad = corners.domains[p] == techniques::PatchDomain::kQuad;
    out.corner_count = quad ? 4 : 3;
    std::array<mesh::Vec3d, 4> corner_d{};
    for (uint32_t c = 0; c < 4; ++c) {
      out.corner_position[c] = corners.patches[p][c].position;
      out.corner_normal[c] = corners.patches[p][c].normal;
      corner_d[c] = toDouble(out.corner_position[c]);
    }
    const std::optional<techniques::PatchCullBounds> bounds = patches.cullBounds(p);
    std::vector<mesh::Vec3d> hull;
    if (bounds && !bounds->hull.empty()) {
      hull = bounds->hull;
    } else {
      ++result.patches_without_hull;
      hull.assign(corner_d.begin(), corner_d.begin() + out.corner_count);
    }
    patch_bulge[p] = bulge(hull, corner_d, quad);
    if (hull.size() > kCullHullPoints) hull = boxCorners(hull);
    for (const mesh::Vec3d& h : hull) out.hull.push_back(toFloat(h));
    const std::optional<std::pair<mesh::Vec3d, double>> cone =
        bounds ? normalCone(bounds->normal_generators) : std::nullopt;
    if (cone && cone->second + kConeSineWidening < 1) {
      out.cone_axis = toFloat(cone->first);
      const float sine = float(cone->second + kConeSineWidening);
      out.cone_sine = std::nextafter(sine, 2.0f);
    } else {
      ++result.patches_without_cone;
    }
    if (bounds) setTangentPlane(corners.domains[p], *bounds, out);
    if (out.tangent_plane.empty()) ++result.patches_without_tangent_plane;
  }
  // Per welded position, the largest bulge of the patches around it.
  std::map<PositionKey, double> vertex_margin;
  for (size_t p = 0; p < count; ++p) {
    const CullPatchBounds& b = result.patches[p];
    for (uint32_t c = 0; c < b.corner_count; ++c) {
      double& margin = vertex_margin[positionKey(b.corner_position[c])];
      margin = std::max(margin, patch_bulge[p]);
    }
  }
  for (CullPatchBounds& b : result.patches) {
    for (uint32_t c = 0; c < b.corner_count; ++c) {
      const float margin = float(vertex_margin[positionKey(b.corner_position[c])]);
      b.corner_margin[c] = std::nextafter(margin, std::numeric_limits<float>::infinity());
    }
  }
  return result;
}

CullParams cullParams(CullPolicy policy, const view::View& view, const CullBounds& bounds) {
  CullParams params;
  params.policy = policy;
  params.global_margin = bounds.global_margin;
  params.chord_factors = bounds.chord_factors;
  params.eye = {float(view.eye[0]), float(view.eye[1]), float(view.eye[2])};
  const auto& m = view.view_projection.m;
  auto row = [&](int r) { return std::array<double, 4>{m[0][r], m[1][r], m[2][r], m[3][r]}; };
  const std::array<double, 4> x = row(0), y = row(1), z = row(2), w = row(3);
  const std::array<std::array<double, 4>, 6> planes = {{
      {w[0] + x[0], w[1] + x[1], w[2] + x[2], w[3] + x[3]},  // x >= -w
      {w[0] - x[0], w[1] - x[1], w[2] - x[2], w[3] - x[3]},  // x <= w
      {w[0] + y[0], w[1] + y[1], w[2] + y[2], w[3] + y[3]},  // y >= -w
      {w[0] - y[0], w[1] - y[1], w[2] - y[2], w[3] - y[3]},  // y <= w
      z,                                                     // z >= 0
      {w[0] - z[0], w[1] - z[1], w[2] - z[2], w[3] - z[3]},  // z <= w
  }};
  for (size_t k = 0; k < 6; ++k) {
    const double len = std::sqrt(planes[k][0] * planes[k][0] + planes[k][1] * planes[k][1] +
                                 planes[k][2] * planes[k][2]);
    for (int i = 0; i < 4; ++i) params.planes[k][i] = float(len > 0 ? planes[k][i] / len : 0);
  }
  return params;
}

namespace {

bool cullsBackfaceLp2(const CullParams& params, const CullPatchBounds& patch) {
  for (uint32_t c = 0; c < patch.corner_count; ++c) {
    const mesh::Vec3f to_eye = subF(params.eye, patch.corner_position[c]);
    if (!(dotF(patch.corner_normal[c], to_eye) < 0.0f)) return false;
  }
  return true;
}

bool cullsFrustumCorners(const CullParams& params, const CullPatchBounds& patch, bool exact) {
  for (const std::array<float, 4>& plane : params.planes) {
    bool outside = true;
    for (uint32_t c = 0; c < patch.corner_count && outside; ++c) {
      const float margin =
          (exact ? patch.corner_margin[c] : params.global_margin) + patch.displacement_bound;
      outside = planeDistance(plane, patch.corner_position[c]) < -margin;
    }
    if (outside) return true;
  }
  return false;
}

bool cullsFrustumHull(const CullParams& params, const CullPatchBounds& patch) {
  for (const std::array<float, 4>& plane : params.planes) {
    bool outside = true;
    for (size_t i = 0; i < patch.hull.size() && outside; ++i) {
      outside = planeDistance(plane, patch.hull[i]) < -patch.displacement_bound;
    }
    if (outside) return true;
  }
  return false;
}

bool cullsCone(const CullParams& params, const CullPatchBounds& patch) {
  if (!(patch.cone_sine <= 1.0f)) return false;
  for (const mesh::Vec3f& q : patch.hull) {
    const mesh::Vec3f d = subF(q, params.eye);
    const float along = dotF(d, patch.cone_axis) - patch.displacement_bound;
    const float reach = (std::sqrt(dotF(d, d)) + patch.displacement_bound) * patch.cone_sine;
    if (!(along > reach)) return false;
  }
  return true;
}

// tbCullTangentPlaneHull.
bool cullsTangentPlaneHull(const CullParams& params, const CullPatchBounds& patch) {
  if (patch.tangent_plane.empty()) return false;
  const mesh::Vec3f d = subF(params.eye, patch.corner_position[0]);
  const float distance = std::sqrt(dotF(d, d));
  const float reach = distance * patch.tangent_normal_max + patch.tangent_offset_max;
  const bool quad = patch.corner_count == 4;
  const float k2 = quad ? params.chord_factors[0] : params.chord_factors[2];
  const float k3 = quad ? params.chord_factors[1] : params.chord_factors[3];
  const float chord = (distance + patch.tangent_reach) *
                      (patch.tangent_first_times_second * k2 + patch.tangent_second_squared * k3);
  const float tolerance = kTangentPlaneMargin * reach + chord;
  for (const std::array<float, 4>& c : patch.tangent_plane) {
    const float f = dotF(d, {c[0], c[1], c[2]}) + c[3];
    if (!(f < -tolerance)) return false;
  }
  return true;
}

}  // namespace

bool cullsPatch(const CullParams& params, const CullPatchBounds& patch) {
  switch (params.policy) {
    case CullPolicy::kNone:
      return false;
    case CullPolicy::kBackfaceLp2:
      return cullsBackfaceLp2(params, patch);
    case CullPolicy::kFrustumLp2Global:
      return cullsFrustumCorners(params, patch, false);
    case CullPolicy::kFrustumLp2Exact:
      return cullsFrustumCorners(params, patch, true);
    case CullPolicy::kFrustumHull:
      return cullsFrustumHull(params, patch);
    case CullPolicy::kCone:
      return cullsCone(params, patch);
    case CullPolicy::kCombined:
      return cullsFrustumHull(params, patch) || cullsCone(params, patch);
    case CullPolicy::kTangentPlane:
      return cullsCone(params, patch) || cullsTangentPlaneHull(params, patch);
    case CullPolicy::kTangentPlaneFrustum:
      return cullsFrustumHull(params, patch) || cullsCone(params, patch) ||
             cullsTangentPlaneHull(params, patch);
  }
  return false;
}

std::vector<uint8_t> cullDecisions(const CullParams& params, const CullBounds& bounds) {
  std::vector<uint8_t> culled(bounds.patches.size());
  for (size_t p = 0; p < bounds.patches.size(); ++p) {
    culled[p] = cullsPatch(params, bounds.patches[p]) ? 1 : 0;
  }
  return culled;
}

}  // namespace tb::lod
