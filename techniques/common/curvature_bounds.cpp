// Second-derivative bounds of Bezier quads, Bezier triangles and Gregory patches.
//
// Bezier quad of bi-degree d (net c_ij, i along u):
//   S_uu = d (d - 1) Σ_{i <= d-2, j <= d} (c_ij - 2 c_{i+1,j} + c_{i+2,j}) B^{d-2}_i(u) B^d_j(v),
//   S_uv = d^2 Σ_{i, j <= d-1} (c_{i+1,j+1} - c_{i+1,j} - c_{i,j+1} + c_ij) B^{d-1}_i B^{d-1}_j,
// and S_vv like S_uu; the Bernstein weights are >= 0 and sum to 1, so the largest norm of a
// coefficient bounds each (exact, not sampled; tight when one difference dominates, e.g. a
// parabolic patch, whose bound is attained).
//
// Bezier triangle of degree d (b_ijk, i + j + k = d; i the power of u, j of v, k of w), with
// (u, v) free and w = 1 - u - v: ∂/∂u = D_u - D_w, ∂/∂v = D_v - D_w (D_x the derivative along
// barycentric x), so over i + j + k = d - 2 with weights B^{d-2}_ijk:
//   S_uu = d (d - 1) Σ (b_{i+2,j,k} - 2 b_{i+1,j,k+1} + b_{i,j,k+2}) B,
//   S_uv = d (d - 1) Σ (b_{i+1,j+1,k} - b_{i+1,j,k+1} - b_{i,j+1,k+1} + b_{i,j,k+2}) B,
//   S_vv = d (d - 1) Σ (b_{i,j+2,k} - 2 b_{i,j+1,k+1} + b_{i,j,k+2}) B.
// A net whose corners are the domain's in another order takes the same differences with the
// net corners of the domain's u, v, w in place of i, j, k.
//
// Edge curves: the boundary row of the net is the edge's Bezier curve from corner to corner
// on [0, 1]; sup |C''| <= d (d - 1) max |Δ²| of that row (Wang's bound), which depends on the
// row alone, so two patches sharing the row agree to rounding.
//
// Gregory blends. Corner c's interior point of a Gregory patch is the rational blend
// (a_c Fp_c + b_c Fm_c) / (a_c + b_c), a_c, b_c >= 0 the linear functions that vanish on the
// corner's two edges. With M_c = (Fp_c + Fm_c) / 2 and δ_c = (Fp_c - Fm_c) / 2 it is
// M_c + t_c δ_c, t_c = (a_c - b_c) / (a_c + b_c) in [-1, 1]; so the patch is the polynomial
// patch S_mid with the midpoints M_c in its interior slots plus Σ_c g_c δ_c with the scalar
// g_c = B_c t_c (B_c the slot's Bernstein weight), the same function on every patch. Hence
//   |S_xy| <= sup |S_mid,xy| + Σ_c sup |∂xy g_c| |δ_c|   (xy in uu, uv, vv).
// g_c is smooth except at corner c, where t_c is homogeneous of degree 0 in (a_c, b_c); its
// second derivatives stay bounded there, as B_c vanishes to first order in each of a_c and
// b_c (near the corner g_c ~ k a b (a - b) / (a + b), homogeneous of degree 2, whose second
// derivatives depend on the direction only). In the coordinates r = a_c + b_c, s = a_c / r
// every second derivative of g_c with respect to the domain's (u, v) is a polynomial in
// (r, s) (checked symbolically: the powers of r from ∂s/∂u = O(1/r) cancel). Its supremum
// over the domain's image in (r, s) was bounded rigorously offline by interval branch and
// bound on that polynomial (scripts/gregory_blend_constants.py: exact rational interval
// arithmetic, boxes halved until their upper bound is within 1e-3 of the best value found at
// a point of the domain; the largest upper bound of the leaves is the bound).
//   Quad (bicubic B_c, e.g. corner 0: 9 u (1-u)^2 v (1-v)^2, t = (u - v) / (u + v)):
// sup |∂uu g| = sup |∂vv g| = 36, sup |∂uv g| = 9 (attained in the limit at the corner;
// proven upper bounds 36.00005 and 9.0001, stored as 36.001 and 9.001). Corners 1..3 are
// corner 0 reflected (u -> 1 - u, v -> 1 - v keep |∂uu|, |∂vv|, |∂uv|) and swapped (u <-> v
// negates g and swaps uu with vv), so they share the constants.
//   Triangle (quartic B_c = 12 x^2 y z, x the corner's own coordinate), per corner since
// w = 1 - u - v breaks the symmetry of the (u, v) derivatives: (uu, uv, vv) = (48, 60, 72)
// at corner 0, (72, 60, 48) at corner 1, (48, 12, 48) at corner 2 (proven upper bounds
// within 1e-3 of these; stored + 0.002).
#include "techniques/common/curvature_bounds.h"

#include <algorithm>
#include <stdexcept>

#include "techniques/common/bernstein_poly.h"

namespace tb::techniques {

const std::array<GregoryBlendConstants, 3> kGregoryTriangleBlend{{
    {48.002, 60.002, 72.002},  // b211: blend (v, w)
    {72.002, 60.002, 48.002},  // b121: blend (w, u)
    {48.002, 12.002, 48.002},  // b112: blend (u, v)
}};

namespace {

// |a - 2 b + c|
double secondDifference(const mesh::Vec3d& a, const mesh::Vec3d& b, const mesh::Vec3d& c) {
  return length(a - b * 2.0 + c);
}

// |a - b - c + d|
double mixedDifference(const mesh::Vec3d& a, const mesh::Vec3d& b, const mesh::Vec3d& c,
                       const mesh::Vec3d& d) {
  return length(a - b - c + d);
}

}  // namespace

double bezierCurveSecondDerivativeBound(const std::vector<mesh::Vec3d>& points) {
  if (points.size() < 3) return 0;
  const double d = double(points.size() - 1);
  double largest = 0;
  for (size_t i = 0; i + 2 < points.size(); ++i) {
    largest = std::max(largest, secondDifference(points[i], points[i + 1], points[i + 2]));
  }
  return d * (d - 1) * largest;
}

CurvatureBounds quadNetCurvatureBounds(const std::vector<mesh::Vec3d>& net, int degree) {
  const int n = degree + 1;
  if (degree < 1 || net.size() != size_t(n * n)) {
    throw std::invalid_argument("quadNetCurvatureBounds: a bi-degree " + std::to_string(degree) +
                                " net needs (d + 1)^2 points, got " + std::to_string(net.size()));
  }
  const auto c = [&](int i, int j) -> const mesh::Vec3d& { return net[size_t(i + n * j)]; };
  double uu = 0, uv = 0, vv = 0;
  for (int j = 0; j <= degree; ++j) {
    for (int i = 0; i + 2 <= degree; ++i) {
      uu = std::max(uu, secondDifference(c(i, j), c(i + 1, j), c(i + 2, j)));
      vv = std::max(vv, secondDifference(c(j, i), c(j, i + 1), c(j, i + 2)));
    }
  }
  for (int j = 0; j < degree; ++j) {
    for (int i = 0; i < degree; ++i) {
      uv = std::max(uv, mixedDifference(c(i + 1, j + 1), c(i + 1, j), c(i, j + 1), c(i, j)));
    }
  }
  const double d = degree;
  CurvatureBounds bounds;
  bounds.uu = d * (d - 1) * uu;
  bounds.uv = d * d * uv;
  bounds.vv = d * (d - 1) * vv;
  // Edges u = 0, v = 0, u = 1, v = 1: column 0, row 0, column d, row d.
  for (int m = 0; m <= degree; ++m) {
    bounds.edge_hull[0].push_back(c(0, m));
    bounds.edge_hull[1].push_back(c(m, 0));
    bounds.edge_hull[2].push_back(c(degree, m));
    bounds.edge_hull[3].push_back(c(m, degree));
  }
  for (int e = 0; e < 4; ++e)
    bounds.edge[e] = bezierCurveSecondDerivativeBound(bounds.edge_hull[e]);
  bounds.hull = net;
  return bounds;
}

CurvatureBounds triangleNetCurvatureBounds(const std::vector<mesh::Vec3d>& net, int degree,
                                           const std::array<int, 3>& labels) {
  if (degree < 1 || net.size() != size_t(triangleNetSize(degree))) {
    throw std::invalid_argument("triangleNetCurvatureBounds: a degree " + std::to_string(degree) +
                                " net needs triangleNetSize(d) points, got " +
                                std::to_string(net.size()));
  }
  std::array<bool, 3> seen{};
  for (int l : labels) {
    if (l < 0 || l > 2 || seen[size_t(l)]) {
      throw std::invalid_argument("triangleNetCurvatureBounds: labels are no permutation");
    }
    seen[size_t(l)] = true;
  }
  // The net point whose powers of the net's corners are p (p[0] + p[1] + p[2] = d).
  const auto b = [&](const std::array<int, 3>& p) -> const mesh::Vec3d& {
    return net[size_t(triangleNetSlot(degree, p[0], p[1]))];
  };
  // max over |m| = d - 2 of |Δ_(x - y) Δ_(z - w) b| at m: the coefficients of the second
  // derivative along (e_x - e_y), (e_z - e_w), over d (d - 1).
  const auto largest = [&](int x, int y, int z, int w) {
    double top = 0;
    for (int i = 0; i <= degree - 2; ++i) {
      for (int j = 0; i + j <= degree - 2; ++j) {
        const std::array<int, 3> m{i, j, degree - 2 - i - j};
        const auto at = [&](int first, int second) -> const mesh::Vec3d& {
          std::array<int, 3> p = m;
          ++p[size_t(first)];
          ++p[size_t(second)];
          return b(p);
        };
        top = std::max(top, mixedDifference(at(x, z), at(x, w), at(y, z), at(y, w)));
      }
    }
    return top;
  };
  const int lu = labels[0], lv = labels[1], lw = labels[2];
  const double d = degree;
  CurvatureBounds bounds;
  bounds.uu = d * (d - 1) * largest(lu, lw, lu, lw);
  bounds.uv = d * (d - 1) * largest(lu, lw, lv, lw);
  bounds.vv = d * (d - 1) * largest(lv, lw, lv, lw);
  // Edge e (u = 0, v = 0, w = 0) is the row where domain corner e's label has power 0, from
  // the next corner to the one after.
  for (int e = 0; e < 3; ++e) {
    const int from = labels[size_t((e + 1) % 3)], to = labels[size_t((e + 2) % 3)];
    for (int m = 0; m <= degree; ++m) {
      std::array<int, 3> p{};
      p[size_t(from)] = degree - m;
      p[size_t(to)] = m;
      bounds.edge_hull[size_t(e)].push_back(b(p));
    }
    bounds.edge[size_t(e)] = bezierCurveSecondDerivativeBound(bounds.edge_hull[size_t(e)]);
  }
  bounds.hull = net;
  return bounds;
}

std::optional<CurvatureBounds> curvatureBoundsFromNet(const PatchCullBounds& bounds,
                                                      PatchDomain domain) {
  if (bounds.bezier_net.empty()) return std::nullopt;
  CurvatureBounds result =
      domain == PatchDomain::kQuad
          ? quadNetCurvatureBounds(bounds.bezier_net, bounds.bezier_degree)
          : triangleNetCurvatureBounds(bounds.bezier_net, bounds.bezier_degree, {0, 1, 2});
  if (!bounds.hull.empty()) result.hull = bounds.hull;
  return result;
}

void addGregoryQuadBlends(CurvatureBounds& bounds, const std::array<double, 4>& half_gaps) {
  for (double gap : half_gaps) {
    bounds.uu += kGregoryQuadBlend.uu * gap;
    bounds.uv += kGregoryQuadBlend.uv * gap;
    bounds.vv += kGregoryQuadBlend.vv * gap;
  }
}

void addGregoryTriangleBlends(CurvatureBounds& bounds, const std::array<double, 3>& half_gaps) {
  for (size_t c = 0; c < 3; ++c) {
    bounds.uu += kGregoryTriangleBlend[c].uu * half_gaps[c];
    bounds.uv += kGregoryTriangleBlend[c].uv * half_gaps[c];
    bounds.vv += kGregoryTriangleBlend[c].vv * half_gaps[c];
  }
}

}  // namespace tb::techniques
