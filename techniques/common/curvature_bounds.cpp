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
//   Quad (bicubic B_c, e.g. corner 0: 9 u (1-u)^2 v (1-v)^2, t = (u - v) / (u + v)): over
// the whole domain sup |∂uu g_0| = sup |∂vv g_0| = 36, sup |∂uv g_0| = 9, attained in the
// limit at corner 0. Far from its corner g_0 bends far less, so gregoryQuadNetCurvatureBounds
// bounds each quadrant of the domain on its own (the midpoint patch on its de Casteljau
// quarter net, each blend with its constant on that quadrant) and takes the largest. g_0's
// constants (uu, uv, vv) per quadrant, proven upper bounds (tolerance 2e-3 or 2e-2) rounded
// up: [0, 1/2]^2 (36, 9, 36), the whole domain's (proven 36.00005, 9.0001, 36.00005);
// [1/2, 1] x [0, 1/2] (1.541, 3.000, 13.5) (proven 1.5428, 3.0020, 13.5020); [0, 1/2] x
// [1/2, 1] the same with uu and vv swapped (g_0(v, u) = -g_0(u, v)); [1/2, 1]^2 uu = vv =
// 0.856 (proven 0.8761; the quadrant is its own mirror), uv 0.460 (proven 0.4576, sampled
// 0.4243). (The quadrants away from the corner by interval branch and bound directly in
// (u, v), where g_0 is smooth: scripts/gregory_blend_constants.py --quadrants 10 and
// --far-quadrant; the far quadrant's uv by --far-quadrant-bernstein 4: on each of 512
// sub-triangles the largest Bernstein coefficient of the numerator, exact rationals, over
// the smallest (u + v)^k there.) Corners 1..3 are corner 0
// reflected (g_1(u, v) = -g_0(1 - u, v), g_2 = g_0(1 - u, 1 - v), g_3 = -g_0(u, 1 - v));
// reflections keep |∂uu|, |∂uv|, |∂vv|, so corner c reads g_0's reflected quadrant.
//   Triangle (quartic B_c = 12 x^2 y z, x the corner's own coordinate), per corner since
// w = 1 - u - v breaks the symmetry of the (u, v) derivatives: over the whole domain (uu,
// uv, vv) = (48, 60, 72) at corner 0, (72, 60, 48) at corner 1, (48, 12, 48) at corner 2
// (proven upper bounds within 1e-3 of these; stored + 0.002), the suprema at the corner.
// Per region of the domain cut at its edges' midpoints, away from its corner (where x <= 1/2,
// so a + b >= 1/2 and g_c is smooth) the bounds are smaller: on each of 256 sub-triangles of
// the region the largest Bernstein coefficient of the numerator (exact rationals) over the
// smallest (a + b)^k there (scripts/gregory_blend_constants.py --triangle-regions 4; the
// largest sampled value beside each: 24 of 26.99, 21 of 21.63, 2.31 of 2.54, 4 of 4.41 and
// 4.63, the middle's and 18 exact). Stored + 0.002. The sum over the corners on the worst
// region is about 0.75 of the whole domain's (uu: 26.99 + 72 + 26.99 on v >= 1/2 against 168).
#include "techniques/common/curvature_bounds.h"

#include <algorithm>
#include <stdexcept>

#include "techniques/common/bernstein_poly.h"

namespace tb::techniques {

const std::array<std::array<GregoryBlendConstants, 2>, 2> kGregoryQuadBlend{{
    // [qa][qb]: u in [qa / 2, (qa + 1) / 2], v in [qb / 2, (qb + 1) / 2]
    {{{36.001, 9.002, 36.001}, {13.503, 3.003, 1.544}}},
    {{{1.544, 3.003, 13.503}, {0.877, 0.460, 0.877}}},
}};

const std::array<std::array<GregoryBlendConstants, 4>, 3> kGregoryTriangleBlend{{
    // [corner][region]: u >= 1/2, v >= 1/2, w >= 1/2, the middle triangle
    {{{48.002, 60.002, 72.002},
      {26.990, 21.632, 18.002},
      {2.544, 4.408, 18.002},
      {24.002, 21.002, 18.002}}},  // b211: blend (v, w)
    {{{18.002, 21.632, 26.990},
      {72.002, 60.002, 48.002},
      {18.002, 4.408, 2.544},
      {18.002, 21.002, 24.002}}},  // b121: blend (w, u)
    {{{2.544, 4.628, 26.990},
      {26.990, 4.628, 2.544},
      {48.002, 12.002, 48.002},
      {24.002, 3.002, 24.002}}},  // b112: blend (u, v)
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

namespace {

// The half [0, 1/2] (upper = false) or [1/2, 1] of the cubic p[0], p[stride], ..., in place.
void halveCubic(mesh::Vec3d* p, size_t stride, bool upper) {
  const mesh::Vec3d a = p[0], b = p[stride], c = p[2 * stride], d = p[3 * stride];
  const mesh::Vec3d ab = (a + b) * 0.5, bc = (b + c) * 0.5, cd = (c + d) * 0.5;
  const mesh::Vec3d abc = (ab + bc) * 0.5, bcd = (bc + cd) * 0.5, mid = (abc + bcd) * 0.5;
  if (upper) {
    p[0] = mid, p[stride] = bcd, p[2 * stride] = cd;
  } else {
    p[stride] = ab, p[2 * stride] = abc, p[3 * stride] = mid;
  }
}

}  // namespace

CurvatureBounds gregoryQuadNetCurvatureBounds(const std::vector<mesh::Vec3d>& mid_net,
                                              const std::array<double, 4>& half_gaps) {
  CurvatureBounds bounds = quadNetCurvatureBounds(mid_net, 3);  // edges, and the checks
  // Corner c's g_c is g_0 reflected in u (corners 1, 2) and in v (corners 2, 3).
  constexpr int kFlipU[4] = {0, 1, 1, 0}, kFlipV[4] = {0, 0, 1, 1};
  double uu = 0, uv = 0, vv = 0;
  for (int qb = 0; qb < 2; ++qb) {
    for (int qa = 0; qa < 2; ++qa) {
      std::vector<mesh::Vec3d> half = mid_net;
      for (size_t k = 0; k < 4; ++k) halveCubic(&half[4 * k], 1, qa == 1);  // rows, along u
      for (size_t k = 0; k < 4; ++k) halveCubic(&half[k], 4, qb == 1);      // columns, along v
      // d/du = 2 d/ds on the quadrant: second derivatives 4 times the half net's.
      const CurvatureBounds part = quadNetCurvatureBounds(half, 3);
      double q_uu = 4 * part.uu, q_uv = 4 * part.uv, q_vv = 4 * part.vv;
      for (size_t c = 0; c < 4; ++c) {
        const GregoryBlendConstants& k =
            kGregoryQuadBlend[size_t(qa ^ kFlipU[c])][size_t(qb ^ kFlipV[c])];
        q_uu += k.uu * half_gaps[c];
        q_uv += k.uv * half_gaps[c];
        q_vv += k.vv * half_gaps[c];
      }
      uu = std::max(uu, q_uu), uv = std::max(uv, q_uv), vv = std::max(vv, q_vv);
    }
  }
  bounds.uu = uu, bounds.uv = uv, bounds.vv = vv;
  return bounds;
}

void addGregoryTriangleBlends(CurvatureBounds& bounds, const std::array<double, 3>& half_gaps) {
  // The largest over the regions of the domain of the blends' sum there.
  double uu = 0, uv = 0, vv = 0;
  for (size_t region = 0; region < 4; ++region) {
    double r_uu = 0, r_uv = 0, r_vv = 0;
    for (size_t c = 0; c < 3; ++c) {
      const GregoryBlendConstants& k = kGregoryTriangleBlend[c][region];
      r_uu += k.uu * half_gaps[c];
      r_uv += k.uv * half_gaps[c];
      r_vv += k.vv * half_gaps[c];
    }
    uu = std::max(uu, r_uu), uv = std::max(uv, r_uv), vv = std::max(vv, r_vv);
  }
  bounds.uu += uu, bounds.uv += uv, bounds.vv += vv;
}

}  // namespace tb::techniques
