// The math behind SurfacePatches::cullBounds (techniques/common/patch_bounds.h and the
// techniques' Bézier nets) against independent oracles: the normal patches evaluated in
// their Bernstein basis equal the cross product of the patch's own derivatives (analytic
// for the bicubic, central differences of a directly summed triangle patch); the Phong and
// PN nets, summed in the Bernstein basis, reproduce the techniques' double evaluators.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "techniques/common/bernstein_poly.h"
#include "techniques/common/bezier_eval.h"
#include "techniques/common/patch_bounds.h"
#include "techniques/phong/phong_bounds.h"
#include "techniques/phong/phong_eval.h"
#include "techniques/pn_triangles/pn_bounds.h"
#include "techniques/pn_triangles/pn_eval.h"

namespace tb {
namespace {

mesh::Vec3d randomPoint(std::mt19937& rng) {
  std::uniform_real_distribution<double> d(-1, 1);
  return {d(rng), d(rng), d(rng)};
}

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

// Σ n!/(i! j! k!) u^i v^j w^k b_ijk over a net in patch_bounds.h's order.
mesh::Vec3d triangleNetAt(int degree, const std::vector<mesh::Vec3d>& net, double u, double v,
                          double w) {
  mesh::Vec3d sum{};
  for (int i = 0; i <= degree; ++i) {
    for (int j = 0; i + j <= degree; ++j) {
      const int k = degree - i - j;
      const double basis = factorial(degree) / (factorial(i) * factorial(j) * factorial(k)) *
                           std::pow(u, i) * std::pow(v, j) * std::pow(w, k);
      sum = sum + net[techniques::triangleNetSlot(degree, i, j)] * basis;
    }
  }
  return sum;
}

// Σ B5_m(u) B5_n(v) N[m + 6 n].
mesh::Vec3d biquinticAt(const std::array<mesh::Vec3d, 36>& n, double u, double v) {
  const auto basis = [](int i, double t) {
    return factorial(5) / (factorial(i) * factorial(5 - i)) * std::pow(t, i) *
           std::pow(1 - t, 5 - i);
  };
  mesh::Vec3d sum{};
  for (int row = 0; row < 6; ++row) {
    for (int m = 0; m < 6; ++m) sum = sum + n[m + 6 * row] * (basis(m, u) * basis(row, v));
  }
  return sum;
}

const std::array<std::array<double, 3>, 6> kTrianglePoints = {{{0.2, 0.3, 0.5},
                                                               {0.7, 0.1, 0.2},
                                                               {1.0 / 3, 1.0 / 3, 1.0 / 3},
                                                               {0.05, 0.9, 0.05},
                                                               {0.5, 0.45, 0.05},
                                                               {0.1, 0.15, 0.75}}};

TEST(PatchBoundsMath, BicubicNormalPatchIsTheCrossOfTheDerivatives) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    std::array<mesh::Vec3d, 16> b;
    for (mesh::Vec3d& p : b) p = randomPoint(rng);
    std::array<mesh::Vec3d, 12> tu, tv;
    techniques::bicubicDerivativePatches(b, tu, tv);
    const std::array<mesh::Vec3d, 36> n = techniques::bicubicNormalPatch(b);
    for (double u : {0.0, 0.3, 0.8, 1.0}) {
      for (double v : {0.0, 0.45, 1.0}) {
        const mesh::Vec3d expected =
            cross(techniques::evaluateTangentU(tu, u, v), techniques::evaluateTangentV(tv, u, v));
        EXPECT_LE(length(biquinticAt(n, u, v) - expected), 1e-12 * (1 + length(expected)))
            << u << " " << v;
      }
    }
  }
}

TEST(PatchBoundsMath, TriangleNormalPatchIsTheCrossOfTheDerivativesTowardCorners1And2) {
  std::mt19937 rng(11);
  const double h = 1e-5;
  for (int degree = 1; degree <= 4; ++degree) {
    std::vector<mesh::Vec3d> net(techniques::triangleNetSize(degree));
    for (mesh::Vec3d& p : net) p = randomPoint(rng);
    const std::vector<mesh::Vec3d> normal = techniques::triangleNormalPatch(degree, net);
    ASSERT_EQ(normal.size(), size_t(techniques::triangleNetSize(2 * degree - 2)));
    for (const auto& [u, v, w] : kTrianglePoints) {
      const mesh::Vec3d toward1 = (triangleNetAt(degree, net, u - h, v + h, w) -
                                   triangleNetAt(degree, net, u + h, v - h, w)) *
                                  (0.5 / h);
      const mesh::Vec3d toward2 = (triangleNetAt(degree, net, u - h, v, w + h) -
                                   triangleNetAt(degree, net, u + h, v, w - h)) *
                                  (0.5 / h);
      const mesh::Vec3d expected = cross(toward1, toward2);
      const mesh::Vec3d got = triangleNetAt(2 * degree - 2, normal, u, v, w);
      EXPECT_LE(length(got - expected), 1e-7 * (1 + length(expected))) << "degree " << degree;
    }
  }
  // Corners 0, 1, 2 counter-clockwise in the xy plane: the normal is +z.
  const std::vector<mesh::Vec3d> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};  // b100, b010, b001
  const std::vector<mesh::Vec3d> n = techniques::triangleNormalPatch(1, flat);
  ASSERT_EQ(n.size(), 1u);
  EXPECT_GT(n[0].z, 0);
  EXPECT_THROW(techniques::triangleNormalPatch(3, flat), std::invalid_argument);
}

TEST(PatchBoundsMath, PhongNetReproducesTheEvaluator) {
  std::mt19937 rng(3);
  for (double alpha : {0.0, 0.75, 1.0}) {
    phong::PhongTriangle<double> tri;
    for (int i = 0; i < 3; ++i) {
      tri.position[i] = randomPoint(rng);
      tri.normal[i] = normalize(randomPoint(rng));
    }
    const std::vector<mesh::Vec3d> net = phong::phongQuadraticNet(tri, alpha);
    for (const auto& [u, v, w] : kTrianglePoints) {
      const mesh::Vec3d expected = phong::evaluatePhong(tri, {u, v, w}, alpha).position;
      EXPECT_LE(length(triangleNetAt(2, net, u, v, w) - expected), 1e-13) << alpha;
    }
  }
}

TEST(PatchBoundsMath, PhongEdgeHullContainsTheEdgeVariant) {
  std::mt19937 rng(5);
  phong::PhongEdgeTriangle<double> tri;
  for (int i = 0; i < 3; ++i) {
    tri.position[i] = randomPoint(rng);
    tri.normal[i] = normalize(randomPoint(rng));
  }
  for (auto& edge : tri.edge_normal) {
    for (mesh::Vec3d& n : edge) n = normalize(randomPoint(rng));
  }
  const techniques::PatchCullBounds bounds = phong::phongEdgeCullBounds(tri, 0.75);
  ASSERT_EQ(bounds.hull.size(), 24u);
  EXPECT_TRUE(bounds.normal_generators.empty());
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < 200; ++k) {
    const double a = unit(rng), b = unit(rng) * (1 - a);
    const mesh::Vec3d p = phong::evaluatePhongEdge(tri, {a, b, 1 - a - b}, 0.75).position;
    const mesh::Vec3d d = normalize(randomPoint(rng));
    double support = -1e300;
    for (const mesh::Vec3d& h : bounds.hull) support = std::max(support, dot(d, h));
    EXPECT_LE(dot(d, p), support + 1e-12);
  }
}

TEST(PatchBoundsMath, PnNetReproducesTheEvaluator) {
  std::mt19937 rng(13);
  pn_triangles::PnInput<double> in;
  for (int i = 0; i < 3; ++i) {
    in.position[i] = randomPoint(rng);
    in.normal[i] = normalize(randomPoint(rng));
  }
  for (int e = 0; e < 3; ++e) {
    for (int end = 0; end < 2; ++end) {
      in.edge_own[e][end] = in.normal[techniques::kEdgeEnds[e][end]];
      in.edge_other[e][end] = normalize(randomPoint(rng));
    }
  }
  for (bool aen : {false, true}) {
    in.aen = aen;
    const pn_triangles::PnControl<double> control = pn_triangles::computeControl(in);
    const std::vector<mesh::Vec3d> net = pn_triangles::cubicNet(control);
    for (const auto& [u, v, w] : kTrianglePoints) {
      const mesh::Vec3d expected = pn_triangles::evaluateControl(control, {u, v, w}).position;
      EXPECT_LE(length(triangleNetAt(3, net, u, v, w) - expected), 1e-13) << aen;
    }
  }
}

// Σ B^m_i(u) B^n_j(v) c_ij.
template <class V>
V quadPolyAt(const techniques::QuadPoly<V>& p, double u, double v) {
  V sum{};
  for (int j = 0; j <= p.deg_v; ++j) {
    for (int i = 0; i <= p.deg_u; ++i) {
      const double basis = techniques::binomialCoefficient(p.deg_u, i) * std::pow(u, i) *
                           std::pow(1 - u, p.deg_u - i) *
                           techniques::binomialCoefficient(p.deg_v, j) * std::pow(v, j) *
                           std::pow(1 - v, p.deg_v - j);
      sum = sum + p.at(i, j) * basis;
    }
  }
  return sum;
}

techniques::QuadPoly<double> randomQuadPoly(std::mt19937& rng, int m, int n) {
  std::uniform_real_distribution<double> d(-1, 1);
  techniques::QuadPoly<double> p(m, n);
  for (double& c : p.c) c = d(rng);
  return p;
}

TEST(PatchBoundsMath, QuadBernsteinProductsSumsAndDerivativesAreTheFunctions) {
  std::mt19937 rng(17);
  const techniques::QuadPoly<double> a = randomQuadPoly(rng, 2, 3), b = randomQuadPoly(rng, 4, 1);
  techniques::QuadPoly<mesh::Vec3d> g(3, 2);
  for (mesh::Vec3d& c : g.c) c = randomPoint(rng);
  const mesh::Vec3d fixed = randomPoint(rng);
  const double h = 1e-6;
  for (double u : {0.0, 0.25, 0.7, 1.0}) {
    for (double v : {0.0, 0.4, 1.0}) {
      EXPECT_NEAR(quadPolyAt(a * b, u, v), quadPolyAt(a, u, v) * quadPolyAt(b, u, v), 1e-13);
      EXPECT_NEAR(quadPolyAt(a + b, u, v), quadPolyAt(a, u, v) + quadPolyAt(b, u, v), 1e-13);
      EXPECT_NEAR(quadPolyAt(techniques::elevated(a, 5, 6), u, v), quadPolyAt(a, u, v), 1e-13);
      const mesh::Vec3d product = quadPolyAt(techniques::times(a, fixed) * g, u, v);
      EXPECT_LE(length(product - cross(fixed * quadPolyAt(a, u, v), quadPolyAt(g, u, v))), 1e-13);
      if (u > 0 && u < 1 && v > 0 && v < 1) {
        EXPECT_NEAR(quadPolyAt(techniques::derivativeU(a), u, v),
                    (quadPolyAt(a, u + h, v) - quadPolyAt(a, u - h, v)) / (2 * h), 1e-8);
        EXPECT_NEAR(quadPolyAt(techniques::derivativeV(a), u, v),
                    (quadPolyAt(a, u, v + h) - quadPolyAt(a, u, v - h)) / (2 * h), 1e-8);
      }
    }
  }
  EXPECT_DOUBLE_EQ(quadPolyAt(techniques::bilinear(2, 3, 5, 7), 1, 0), 3);
  EXPECT_DOUBLE_EQ(quadPolyAt(techniques::bilinear(2, 3, 5, 7), 0, 1), 5);
}

TEST(PatchBoundsMath, TriangleBernsteinProductsSumsAndElevationAreTheFunctions) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> d(-1, 1);
  techniques::TrianglePoly<mesh::Vec3d> a(2), b(3);
  for (mesh::Vec3d& c : a.c) c = randomPoint(rng);
  for (mesh::Vec3d& c : b.c) c = randomPoint(rng);
  const techniques::TrianglePoly<double> l = techniques::linear(2, 3, 5);
  for (const auto& [u, v, w] : kTrianglePoints) {
    const mesh::Vec3d av = triangleNetAt(2, a.c, u, v, w), bv = triangleNetAt(3, b.c, u, v, w);
    EXPECT_LE(length(triangleNetAt(5, (a * b).c, u, v, w) - cross(av, bv)), 1e-13);
    EXPECT_LE(length(triangleNetAt(3, (a + b).c, u, v, w) - (av + bv)), 1e-13);
    EXPECT_LE(length(triangleNetAt(6, techniques::elevated(a, 6).c, u, v, w) - av), 1e-13);
    const mesh::Vec3d scaled = triangleNetAt(3, (l * a).c, u, v, w);
    EXPECT_LE(length(scaled - av * (2 * u + 3 * v + 5 * w)), 1e-13);
  }
}

}  // namespace
}  // namespace tb
