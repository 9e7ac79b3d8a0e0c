#include "harness/lod/factor_policy.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "core/mesh/topology.h"
#include "core/tess/factor_helpers.h"
#include "harness/lod/transition_extents.h"
#include "shaders/common/layout/factor_layout.h"

namespace tb::lod {
namespace {

constexpr uint32_t kFlagOrderDependent = 1, kFlagSilhouette = 2, kFlagRoundness = 4,
                   kFlagDenseEdges = 8;
constexpr const char* kOrderDependentSuffix = "_order_dependent";
constexpr const char* kLooseSuffix = "_loose";
constexpr const char* kDenseSuffix = "_dense";
// error_bound: a sphere is outside a side of the view when the side plane's value at its
// centre is below -radius x |plane| x this (1 + 2^-10: more than the float rounding of the
// value, so no visible sphere is ever taken for an invisible one).
constexpr float kSideMargin = 1.0f + 1.0f / 1024.0f;

// A shared block's vec4 (shaders/common/layout/factor_layout.h): xyz, w 0; or all four.
gpu::layout::vec4 vec4(const mesh::Vec3f& v) { return {v[0], v[1], v[2], 0.0f}; }
gpu::layout::vec4 vec4(const std::array<float, 4>& v) { return {v[0], v[1], v[2], v[3]}; }

// The shader's helpers, in its operation order (shaders/common/float_order.glsl).
float dotF(const mesh::Vec3f& a, const mesh::Vec3f& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
float lengthF(const mesh::Vec3f& v) { return std::sqrt(dotF(v, v)); }
mesh::Vec3f normalizeF(const mesh::Vec3f& v) {
  const float len = std::sqrt(dotF(v, v));
  if (!(len > 0.0f)) return v;
  const float inv = 1.0f / len;
  return {v[0] * inv, v[1] * inv, v[2] * inv};
}
mesh::Vec3f sub(const mesh::Vec3f& a, const mesh::Vec3f& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
mesh::Vec3f add(const mesh::Vec3f& a, const mesh::Vec3f& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

bool positionLess(const mesh::Vec3f& a, const mesh::Vec3f& b) {
  if (a[0] != b[0]) return a[0] < b[0];
  if (a[1] != b[1]) return a[1] < b[1];
  return a[2] < b[2];
}

// tbClipW: row 3 of the matrix times (p, 1), left to right.
float clipW(const FactorParams& params, const mesh::Vec3f& p) {
  const auto& m = params.view_projection;
  return m[0 * 4 + 3] * p[0] + m[1 * 4 + 3] * p[1] + m[2 * 4 + 3] * p[2] + m[3 * 4 + 3];
}

const char* kindName(FactorPolicyKind kind) {
  switch (kind) {
    case FactorPolicyKind::kUniform:
      return "uniform";
    case FactorPolicyKind::kDistance:
      return "distance";
    case FactorPolicyKind::kSphereDiameter:
      return "sphere_diameter";
    case FactorPolicyKind::kLp2Edge:
      return "lp2_edge";
    case FactorPolicyKind::kErrorBound:
      return "error_bound";
  }
  return "?";
}

// Area-weighted (Newell) face normals summed per welded position, normalised.
std::vector<mesh::Vec3f> weldedNormals(const mesh::Mesh& mesh, const mesh::Welding& welding) {
  std::vector<mesh::Vec3d> sums(mesh.positions.size(), mesh::Vec3d{0, 0, 0});
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const std::span<const uint32_t> corners = mesh.facePositions(f);
    mesh::Vec3d normal{0, 0, 0};
    for (size_t i = 0; i < corners.size(); ++i) {
      normal = normal +
               cross(mesh.positions[corners[i]], mesh.positions[corners[(i + 1) % corners.size()]]);
    }
    for (uint32_t c : corners) {
      mesh::Vec3d& sum = sums[welding.canonical[c]];
      sum = sum + normal;
    }
  }
  std::vector<mesh::Vec3f> normals(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const mesh::Vec3d n = normalize(sums[welding.canonical[v]]);
    normals[v] = {float(n[0]), float(n[1]), float(n[2])};
  }
  return normals;
}

// tbClampFactor of tess_factors.glsl.
float clampFactor(float x, tess::Spacing spacing) {
  const float low = spacing == tess::Spacing::kFractionalEven ? 2.0f : 1.0f;
  const float high = spacing == tess::Spacing::kFractionalOdd ? 63.0f : 64.0f;
  const float at_least_low = x > low ? x : low;
  return high < at_least_low ? high : at_least_low;
}

}  // namespace

std::string FactorPolicy::name() const {
  std::string name = kindName(kind);
  if (silhouette) name += "_silhouette";
  if (roundness) name += "_roundness";
  if (loose) name += kLooseSuffix;
  if (dense_edges) name += kDenseSuffix;
  if (order_dependent) name += kOrderDependentSuffix;
  return name;
}

const char* FactorPolicy::targetUnit() const {
  switch (kind) {
    case FactorPolicyKind::kUniform:
      return "level";
    case FactorPolicyKind::kDistance:
      return "level at 1 diagonal";
    case FactorPolicyKind::kSphereDiameter:
      return "px/edge";
    case FactorPolicyKind::kLp2Edge:
      return "C";
    case FactorPolicyKind::kErrorBound:
      return "px";
  }
  return "";
}

double defaultTarget(FactorPolicyKind kind) {
  switch (kind) {
    case FactorPolicyKind::kUniform:
      return 8;
    case FactorPolicyKind::kDistance:
      return 16;
    case FactorPolicyKind::kSphereDiameter:
      return 8;
    case FactorPolicyKind::kLp2Edge:
      return 0.15;
    case FactorPolicyKind::kErrorBound:
      return 1;
  }
  return 1;
}

std::optional<FactorPolicy> parseFactorPolicy(std::string_view name) {
  FactorPolicy policy;
  const std::string_view suffix = kOrderDependentSuffix;
  if (name.size() > suffix.size() && name.substr(name.size() - suffix.size()) == suffix) {
    policy.order_dependent = true;
    name.remove_suffix(suffix.size());
  }
  if (name == "lp2_edge_silhouette") {
    policy.kind = FactorPolicyKind::kLp2Edge;
    policy.silhouette = true;
  } else if (name == "lp2_edge_roundness") {
    policy.kind = FactorPolicyKind::kLp2Edge;
    policy.roundness = true;
  } else if (name == std::string("error_bound") + kLooseSuffix) {
    policy.kind = FactorPolicyKind::kErrorBound;
    policy.loose = true;
  } else if (name == std::string("error_bound") + kDenseSuffix) {
    policy.kind = FactorPolicyKind::kErrorBound;
    policy.dense_edges = true;
  } else {
    bool found = false;
    for (FactorPolicyKind kind : {FactorPolicyKind::kUniform, FactorPolicyKind::kDistance,
                                  FactorPolicyKind::kSphereDiameter, FactorPolicyKind::kLp2Edge,
                                  FactorPolicyKind::kErrorBound}) {
      if (name == kindName(kind)) {
        policy.kind = kind;
        found = true;
      }
    }
    if (!found) return std::nullopt;
  }
  policy.target = defaultTarget(policy.kind);
  return policy;
}

FactorCorners factorCorners(const techniques::SurfacePatches& patches) {
  const mesh::Mesh& mesh = patches.controlMesh();
  const mesh::Welding welding = mesh::weldByPosition(mesh);
  const std::vector<mesh::Vec3f> normals = weldedNormals(mesh, welding);
  FactorCorners out;
  out.patches.resize(patches.patchCount());
  out.domains.resize(patches.patchCount());
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    out.domains[p] = patches.patchDomain(p);
    const size_t count = out.domains[p] == techniques::PatchDomain::kQuad ? 4 : 3;
    const std::array<uint32_t, 4> corners = patches.patchCorners(p);
    for (size_t c = 0; c < count; ++c) {
      const mesh::Vec3d& position = mesh.positions[corners[c]];
      out.patches[p][c] = {{float(position[0]), float(position[1]), float(position[2])},
                           normals[corners[c]]};
    }
  }
  return out;
}

FactorParams factorParams(const FactorPolicy& policy, const view::View& view, tess::Spacing spacing,
                          double world_scale) {
  FactorParams params;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r)
      params.view_projection[c * 4 + r] = float(view.view_projection.m[c][r]);
  }
  params.eye = {float(view.eye[0]), float(view.eye[1]), float(view.eye[2])};
  params.viewport_height_px = float(view.viewport_height_px);
  params.projection_y_scale = float(view.projection_y_scale);
  params.target = float(policy.kind == FactorPolicyKind::kDistance ? policy.target * world_scale
                                                                   : policy.target);
  params.pixel_scale = float(double(view.viewport_height_px) / (2 * policy.target));
  params.min_scale = float(policy.min_scale);
  params.roundness_span = float(1 - std::cos(policy.roundness_angle_deg * std::numbers::pi / 180));
  params.policy = uint32_t(policy.kind);
  params.flags = (policy.order_dependent ? kFlagOrderDependent : 0) |
                 (policy.silhouette ? kFlagSilhouette : 0) |
                 (policy.roundness ? kFlagRoundness : 0) |
                 (policy.dense_edges ? kFlagDenseEdges : 0);
  params.reduction = uint32_t(policy.reduction);
  params.spacing = uint32_t(spacing);
  // error_bound: f_px = H |P11| / 2 pixels per unit of y / w (square pixels: x alike); the
  // projection's Jacobian stretches a world error at depth w by k f_px / w (errorBoundLevel).
  const double tan_y = 1 / view.projection_y_scale;
  const double tan_x = tan_y * double(view.viewport_width_px) / double(view.viewport_height_px);
  const double f_px = double(view.viewport_height_px) * view.projection_y_scale / 2;
  params.error_scale = float(policy.target / f_px * (policy.loose ? 2 : 1));
  params.near_w = float(view.near_plane);
  const auto& m = view.view_projection.m;
  auto rowLength = [&](int r) {
    return float(std::sqrt(m[0][r] * m[0][r] + m[1][r] * m[1][r] + m[2][r] * m[2][r]));
  };
  params.hull_w_scale = rowLength(3);
  params.row_length = {rowLength(0), rowLength(1)};
  params.inv_scale = {float(tan_x), float(tan_y)};  // 1 / |P00| = tan_x, 1 / |P11| = tan_y
  params.tan_half = {float(tan_x), float(tan_y)};
  // |xyz| of rows 3 + 0, 3 - 0, 3 + 1, 3 - 1: the view's side planes w + x, w - x, w + y, w - y.
  for (int k = 0; k < 4; ++k) {
    const int r = k / 2;
    const double sign = k % 2 == 0 ? 1 : -1;
    double sum = 0;
    for (int c = 0; c < 3; ++c) sum += (m[c][3] + sign * m[c][r]) * (m[c][3] + sign * m[c][r]);
    params.side_length[k] = float(std::sqrt(sum));
  }
  return params;
}

namespace {
// tbProjectionStretch: the Jacobian's largest stretch over the sphere whose centre is at clip
// (cx, cy) and whose nearest clip w is near_w.
float projectionStretch(const FactorParams& params, float cx, float cy, float radius,
                        float near_w) {
  float a = (std::fabs(cx) + radius * params.row_length[0]) * params.inv_scale[0] / near_w;
  float b = (std::fabs(cy) + radius * params.row_length[1]) * params.inv_scale[1] / near_w;
  a = a < params.tan_half[0] ? a : params.tan_half[0];
  b = b < params.tan_half[1] ? b : params.tan_half[1];
  return std::sqrt(1.0f + a * a + b * b);
}
}  // namespace

float errorBoundEps(const FactorParams& params, const std::array<float, 4>& sphere) {
  const auto& m = params.view_projection;
  const float w = clipW(params, {sphere[0], sphere[1], sphere[2]});
  const float r = sphere[3];
  // Wholly behind the near plane, or wholly outside a side of the view (by a margin over the
  // float rounding of the plane's value): no sample can be visible.
  if (w + r * params.hull_w_scale < params.near_w) return std::numeric_limits<float>::infinity();
  const float cx =
      m[0 * 4 + 0] * sphere[0] + m[1 * 4 + 0] * sphere[1] + m[2 * 4 + 0] * sphere[2] + m[3 * 4 + 0];
  const float cy =
      m[0 * 4 + 1] * sphere[0] + m[1 * 4 + 1] * sphere[1] + m[2 * 4 + 1] * sphere[2] + m[3 * 4 + 1];
  const float sides[4] = {w + cx, w - cx, w + cy, w - cy};
  for (int k = 0; k < 4; ++k) {
    if (sides[k] < -(r * params.side_length[k]) * kSideMargin)
      return std::numeric_limits<float>::infinity();
  }
  // Only samples in front of the near plane count (and the segment between two such points
  // stays there): the nearest depth a visible error can have is at least the near plane's.
  const float hull_near_w = w - r * params.hull_w_scale;
  const float near_w = hull_near_w > params.near_w ? hull_near_w : params.near_w;
  return near_w * params.error_scale / projectionStretch(params, cx, cy, r, near_w);
}

float edgeFactor(const FactorParams& params, const FactorCorner& corner_a,
                 const FactorCorner& corner_b) {
  mesh::Vec3f a = corner_a.position, b = corner_b.position;
  mesh::Vec3f na = corner_a.normal, nb = corner_b.normal;
  if ((params.flags & kFlagOrderDependent) == 0 && positionLess(b, a)) {
    std::swap(a, b);
    std::swap(na, nb);
  }
  const mesh::Vec3f edge = sub(b, a);
  const mesh::Vec3f mid = {a[0] + edge[0] * 0.5f, a[1] + edge[1] * 0.5f, a[2] + edge[2] * 0.5f};
  float factor = 0;
  switch (FactorPolicyKind(params.policy)) {
    case FactorPolicyKind::kUniform:
      factor = params.target;
      break;
    case FactorPolicyKind::kDistance:
      factor = params.target / lengthF(sub(mid, params.eye));
      break;
    case FactorPolicyKind::kSphereDiameter: {
      const float ndc_height =
          std::fabs(lengthF(edge) * params.projection_y_scale / clipW(params, mid));
      factor = ndc_height * params.pixel_scale;
      break;
    }
    case FactorPolicyKind::kLp2Edge: {
      const float lrc = lengthF(edge) * params.viewport_height_px * params.target;
      const float f0 = lrc / lengthF(sub(a, params.eye));
      const float f1 = lrc / lengthF(sub(b, params.eye));
      factor = f0 < f1 ? f1 : f0;
      break;
    }
    case FactorPolicyKind::kErrorBound:  // per edge from its bound (errorBoundLevel), not corners
      break;
  }
  if ((params.flags & kFlagSilhouette) != 0) {
    const mesh::Vec3f n = normalizeF(add(na, nb));
    const mesh::Vec3f v = normalizeF(sub(params.eye, mid));
    const float scale = 1.0f - (1.0f - params.min_scale) * std::fabs(dotF(n, v));
    factor = factor * scale;
  }
  if ((params.flags & kFlagRoundness) != 0) {
    const float turn = (1.0f - dotF(na, nb)) / params.roundness_span;
    const float scale = params.min_scale + (1.0f - params.min_scale) * (turn < 1.0f ? turn : 1.0f);
    factor = factor * scale;
  }
  return factor;
}

namespace {

// error_bound's inside level (tbErrorBoundInside): the least whole n for which every triangle
// of the tessellation, with the edges at `outer`, is within the patch's bound: the smaller of
// a du^2 + b dv^2 (du, dv the widest extents) and 4 max(a, b) r^2 (r the largest enclosing
// circle's radius; transition_extents.h) at most 1, with (a, b) the patch's coefficients over
// eps; where no n is, the one that comes closest.
float errorBoundInside(const FactorParams& params, const ErrorBoundPatch& bound,
                       const std::array<float, 4>& outer, uint32_t edges,
                       const std::vector<float>& table, bool* met) {
  *met = true;
  const auto spacing = tess::Spacing(params.spacing);
  const float top = clampFactor(64.0f, spacing);
  // Every sphere of the record holds the patch's hull (an edge's holds every side's), so
  // each one's eps holds for the whole patch: the largest is taken, and it is at least each
  // edge's, which the edge levels were chosen for.
  float eps = errorBoundEps(params, bound.patch_sphere);
  for (uint32_t e = 0; e < edges; ++e) {
    const float edge_eps = errorBoundEps(params, bound.edge_sphere[e]);
    eps = edge_eps > eps ? edge_eps : eps;
  }
  if (!(eps > 0.0f)) return top;
  const float a = bound.inner_a / eps, b = bound.inner_b / eps;
  float best_n = top, best = std::numeric_limits<float>::infinity();
  for (uint32_t n = 1; n <= uint32_t(top); ++n) {
    if (!equalSegmentLevel(n, spacing)) continue;
    float du = 0.0f, dv = 0.0f, r2 = 0.0f;
    for (uint32_t e = 0; e < edges; ++e) {
      const auto o = uint32_t(outer[e]);
      const float eu = table[transitionIndex(e, 0, o, n)], ev = table[transitionIndex(e, 1, o, n)];
      const float er = table[transitionIndex(e, kTransitionCircle, o, n)];
      du = eu > du ? eu : du;
      dv = ev > dv ? ev : dv;
      r2 = er > r2 ? er : r2;
    }
    const float box = a * du * du + b * dv * dv;
    const float circle = 4.0f * (a > b ? a : b) * r2;
    const float need = box < circle ? box : circle;
    if (need <= 1.0f) return float(n);
    if (need < best) {
      best = need;
      best_n = float(n);
    }
  }
  *met = false;
  return best_n;
}

// error_bound's branch of tbPolicyLevels: each edge the least whole level whose longest
// segment keeps its record's bound within eps (m s^2 <= eps, s from the table: a fractional
// spacing's segments are not all 1 / level), the inside from the patch's against the
// tessellation those edges make (a triangle leaves outer[3] and inner[1] at 0, as the shader
// writes them).
tess::Levels errorBoundLevels(const FactorParams& params, techniques::PatchDomain domain,
                              const ErrorBoundPatch& bound, const std::vector<float>& table,
                              bool* met) {
  const auto spacing = tess::Spacing(params.spacing);
  const bool quad = domain == techniques::PatchDomain::kQuad;
  const uint32_t edges = quad ? 4u : 3u;
  const float top = clampFactor(64.0f, spacing);
  const bool dense = (params.flags & kFlagDenseEdges) != 0;
  tess::Levels levels;
  levels.outer = {0, 0, 0, 0};
  for (uint32_t j = 0; j < edges; ++j) {
    const float eps = errorBoundEps(params, bound.edge_sphere[j]);
    levels.outer[j] = top;
    if (!(eps > 0.0f)) continue;
    const float m = bound.edge_m[j] / eps;
    for (uint32_t o = 1; o <= uint32_t(top); ++o) {
      if (!(dense ? equalSegmentLevel(o, spacing) : narrowEdgeLevel(o, spacing))) continue;
      const float s = table[transitionSegmentIndex(edges, o)];
      if (m * s * s <= 1.0f) {
        levels.outer[j] = float(o);
        break;
      }
    }
  }
  const float inside = errorBoundInside(params, bound, levels.outer, edges, table, met);
  levels.inner = {inside, quad ? inside : 0.0f};
  return levels;
}

const std::vector<float>& errorBoundTable(const FactorParams& params,
                                          techniques::PatchDomain domain) {
  return transitionExtents(
      domain == techniques::PatchDomain::kQuad ? tess::Domain::kQuad : tess::Domain::kTriangle,
      tess::Spacing(params.spacing));
}

// The spacing's two tables, each looked up on first use.
class ErrorBoundTables {
 public:
  explicit ErrorBoundTables(const FactorParams& params) : params_(params) {}
  const std::vector<float>& of(techniques::PatchDomain domain) {
    const std::vector<float>*& table = domain == techniques::PatchDomain::kQuad ? quad_ : triangle_;
    if (table == nullptr) table = &errorBoundTable(params_, domain);
    return *table;
  }

 private:
  const FactorParams& params_;
  const std::vector<float>* quad_ = nullptr;
  const std::vector<float>* triangle_ = nullptr;
};

}  // namespace

tess::Levels policyLevels(const FactorParams& params, techniques::PatchDomain domain,
                          const std::array<FactorCorner, 4>& corners,
                          const ErrorBoundPatch* bound) {
  if (FactorPolicyKind(params.policy) == FactorPolicyKind::kErrorBound) {
    if (bound == nullptr) throw std::logic_error("policyLevels: error_bound without its bounds");
    bool met = true;
    return errorBoundLevels(params, domain, *bound, errorBoundTable(params, domain), &met);
  }
  const auto spacing = tess::Spacing(params.spacing);
  const auto reduction = InnerReduction(params.reduction);
  if (domain == techniques::PatchDomain::kQuad) {
    // gl_TessLevelOuter order (u = 0, v = 0, u = 1, v = 1): corners (3,0), (0,1), (1,2), (2,3).
    std::array<float, 4> raw{};
    for (size_t j = 0; j < 4; ++j) raw[j] = edgeFactor(params, corners[(j + 3) % 4], corners[j]);
    switch (reduction) {
      case InnerReduction::kMax:
        return tess::processQuadTessFactorsMax(spacing, raw, 1.0f).rounded;
      case InnerReduction::kMin:
        return tess::processQuadTessFactorsMin(spacing, raw, 1.0f).rounded;
      case InnerReduction::kAverage:
        break;
    }
    return tess::processQuadTessFactorsAvg(spacing, raw, 1.0f).rounded;
  }
  // (u = 0, v = 0, w = 0): corners (1,2), (2,0), (0,1).
  std::array<float, 3> raw{};
  for (size_t j = 0; j < 3; ++j) {
    raw[j] = edgeFactor(params, corners[(j + 1) % 3], corners[(j + 2) % 3]);
  }
  switch (reduction) {
    case InnerReduction::kMax:
      return tess::processTriTessFactorsMax(spacing, raw, 1.0f).rounded;
    case InnerReduction::kMin:
      return tess::processTriTessFactorsMin(spacing, raw, 1.0f).rounded;
    case InnerReduction::kAverage:
      break;
  }
  return tess::processTriTessFactorsAvg(spacing, raw, 1.0f).rounded;
}

ErrorBoundUnmet errorBoundUnmetPatches(const FactorParams& params, const FactorCorners& corners) {
  if (FactorPolicyKind(params.policy) != FactorPolicyKind::kErrorBound) return {};
  if (corners.error_bounds.size() != corners.patches.size()) {
    throw std::logic_error("errorBoundUnmetPatches: error_bound without its bounds");
  }
  ErrorBoundTables tables(params);
  const float top = clampFactor(64.0f, tess::Spacing(params.spacing));
  ErrorBoundUnmet unmet;
  for (size_t p = 0; p < corners.patches.size(); ++p) {
    const std::vector<float>& table = tables.of(corners.domains[p]);
    bool met = true;
    errorBoundLevels(params, corners.domains[p], corners.error_bounds[p], table, &met);
    if (met) continue;
    ++unmet.patches;
    const std::array<float, 4> all_top = {top, top, top, top};
    const uint32_t edges = corners.domains[p] == techniques::PatchDomain::kQuad ? 4u : 3u;
    errorBoundInside(params, corners.error_bounds[p], all_top, edges, table, &met);
    unmet.beyond_top += met ? 0 : 1;
  }
  return unmet;
}

std::vector<tess::Levels> policyLevels(const FactorParams& params, const FactorCorners& corners) {
  std::vector<tess::Levels> levels(corners.patches.size());
  if (FactorPolicyKind(params.policy) == FactorPolicyKind::kErrorBound) {
    // The tables once per call, not once per patch (each lookup takes a lock).
    if (corners.error_bounds.size() != levels.size()) {
      throw std::logic_error("policyLevels: error_bound without its bounds");
    }
    ErrorBoundTables tables(params);
    for (size_t p = 0; p < levels.size(); ++p) {
      bool met = true;
      levels[p] = errorBoundLevels(params, corners.domains[p], corners.error_bounds[p],
                                   tables.of(corners.domains[p]), &met);
    }
    return levels;
  }
  for (size_t p = 0; p < levels.size(); ++p) {
    levels[p] = policyLevels(params, corners.domains[p], corners.patches[p], nullptr);
  }
  return levels;
}

gpu::TcsFactorPolicy tcsFactorPolicy(const FactorParams& params, const FactorCorners& corners,
                                     const gpu::GpuPatchProgram& program) {
  gpu::TcsFactorPolicy out;
  out.corner_words.reserve(size_t(program.patch_count) * gpu::kTcsFactorPatchWords);
  for (uint32_t i = 0; i < program.patch_count; ++i) {
    const uint32_t patch = program.patch_ids.empty() ? i : program.patch_ids[i];
    gpu::layout::TbFactorPatch record{};
    const std::array<FactorCorner, 4>& patch_corners = corners.patches.at(patch);
    for (size_t c = 0; c < 4; ++c) {
      record.corner[c] = {vec4(patch_corners[c].position), vec4(patch_corners[c].normal)};
    }
    const ErrorBoundPatch bound =
        corners.error_bounds.empty() ? ErrorBoundPatch{} : corners.error_bounds.at(patch);
    for (size_t e = 0; e < 4; ++e) record.edge_sphere[e] = vec4(bound.edge_sphere[e]);
    record.edge_m = vec4(bound.edge_m);
    record.patch_sphere = vec4(bound.patch_sphere);
    record.inner_ab = {bound.inner_a, bound.inner_b, 0.0f, 0.0f};
    gpu::layout::appendWords(out.corner_words, record);
  }
  gpu::layout::TbFactorParamsBlock block{};
  std::copy(params.view_projection.begin(), params.view_projection.end(), block.view_projection.m);
  block.eye = vec4(params.eye);
  block.viewport_height_px = params.viewport_height_px;
  block.projection_y_scale = params.projection_y_scale;
  block.target = params.target;
  block.pixel_scale = params.pixel_scale;
  block.min_scale = params.min_scale;
  block.roundness_span = params.roundness_span;
  block.policy = params.policy;
  block.flags = params.flags;
  block.reduction = params.reduction;
  block.spacing = params.spacing;
  block.domain = program.domain == tess::Domain::kQuad ? 1u : 0u;
  block.error_scale = params.error_scale;
  block.near_w = params.near_w;
  block.hull_w_scale = params.hull_w_scale;
  block.row_length_x = params.row_length[0];
  block.inv_scale_x = params.inv_scale[0];
  block.tan_half_x = params.tan_half[0];
  block.row_length_y = params.row_length[1];
  block.inv_scale_y = params.inv_scale[1];
  block.tan_half_y = params.tan_half[1];
  block.side_length = vec4(params.side_length);
  gpu::layout::appendWords(out.param_words, block);
  if (FactorPolicyKind(params.policy) == FactorPolicyKind::kErrorBound) {
    for (float f : transitionExtents(program.domain, tess::Spacing(params.spacing))) {
      out.param_words.push_back(std::bit_cast<uint32_t>(f));
    }
  }
  return out;
}

}  // namespace tb::lod
