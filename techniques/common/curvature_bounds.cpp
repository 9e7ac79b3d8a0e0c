// Second-derivative bounds of Bezier quads, Bezier triangles and Gregory patches, from the
// convex-hull property of the differences of their nets (Wang's edge bound; Filip, Magedson
// & Markot 1986). Derivation: docs/derivations/curvature_bounds.md; the Gregory blends'
// constants and their proof: docs/derivations/gregory_blend_constants.md (Loop et al. 2009).
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
