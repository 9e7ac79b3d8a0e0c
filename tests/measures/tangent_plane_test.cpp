// The tangent_plane policy's coefficients (harness/lod/tangent_plane.h) against an
// independent evaluation of f = (E - P) . (P_u x P_v): the patch by its explicit Bernstein
// sums, its derivatives by central differences. The coefficients' Bernstein sum equals f at
// every sampled domain point, for bicubic and biquadratic quads and quadratic, cubic and
// quartic triangles (a mirrored net gives -f); and on a bumpy sheet seen from below every
// coefficient is negative (the patch is culled) while from above none is.
#include "harness/lod/tangent_plane.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "techniques/common/bernstein_poly.h"

namespace tb {
namespace {

using techniques::PatchDomain;

double bernstein(int n, int i, double t) {
  return techniques::binomialCoefficient(n, i) * std::pow(t, i) * std::pow(1 - t, n - i);
}

// Triangle domain point (u, v, w = 1 - u - v): weights of corners 0, 1, 2.
struct Tri {
  double u, v, w;
};

mesh::Vec3d quadValue(const std::vector<mesh::Vec3d>& net, int d, double u, double v) {
  mesh::Vec3d p{0, 0, 0};
  for (int j = 0; j <= d; ++j) {
    for (int i = 0; i <= d; ++i)
      p = p + net[size_t(i + (d + 1) * j)] * (bernstein(d, i, u) * bernstein(d, j, v));
  }
  return p;
}

mesh::Vec3d triangleValue(const std::vector<mesh::Vec3d>& net, int d, Tri t) {
  mesh::Vec3d p{0, 0, 0};
  for (int i = 0; i <= d; ++i) {
    for (int j = 0; i + j <= d; ++j) {
      const int k = d - i - j;
      const double weight = techniques::trinomialCoefficient(i, j, k) * std::pow(t.u, i) *
                            std::pow(t.v, j) * std::pow(t.w, k);
      p = p + net[size_t(techniques::triangleNetSlot(d, i, j))] * weight;
    }
  }
  return p;
}

// f by central differences at a quad point.
double quadOracle(const std::vector<mesh::Vec3d>& net, int d, const mesh::Vec3d& eye, double u,
                  double v) {
  constexpr double h = 1e-6;
  const mesh::Vec3d pu = (quadValue(net, d, u + h, v) - quadValue(net, d, u - h, v)) * (0.5 / h);
  const mesh::Vec3d pv = (quadValue(net, d, u, v + h) - quadValue(net, d, u, v - h)) * (0.5 / h);
  return dot(eye - quadValue(net, d, u, v), cross(pu, pv));
}

// f at a triangle point: D_1 = d/dv - d/du, D_2 = d/dw - d/du.
double triangleOracle(const std::vector<mesh::Vec3d>& net, int d, const mesh::Vec3d& eye, Tri t) {
  constexpr double h = 1e-6;
  const mesh::Vec3d d1 = (triangleValue(net, d, {t.u - h, t.v + h, t.w}) -
                          triangleValue(net, d, {t.u + h, t.v - h, t.w})) *
                         (0.5 / h);
  const mesh::Vec3d d2 = (triangleValue(net, d, {t.u - h, t.v, t.w + h}) -
                          triangleValue(net, d, {t.u + h, t.v, t.w - h})) *
                         (0.5 / h);
  return dot(eye - triangleValue(net, d, t), cross(d1, d2));
}

// The coefficients' Bernstein sum at a point, and the scale of its terms.
struct Sum {
  double value = 0, scale = 0;
};
Sum coefficientSum(const std::vector<lod::TangentPlaneCoefficient>& c, PatchDomain domain,
                   const mesh::Vec3d& eye_from_origin, Tri t) {
  Sum sum;
  auto term = [&](size_t k, double weight) {
    const double value = eye_from_origin[0] * c[k][0] + eye_from_origin[1] * c[k][1] +
                         eye_from_origin[2] * c[k][2] + c[k][3];
    sum.value += weight * value;
    sum.scale = std::max(sum.scale, std::abs(value));
  };
  if (domain == PatchDomain::kQuad) {
    const int n = int(std::lround(std::sqrt(double(c.size())))) - 1;
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i)
        term(size_t(i + (n + 1) * j), bernstein(n, i, t.u) * bernstein(n, j, t.v));
    }
    return sum;
  }
  int n = 0;
  while (size_t(techniques::triangleNetSize(n)) < c.size()) ++n;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const int k = n - i - j;
      term(size_t(techniques::triangleNetSlot(n, i, j)), techniques::trinomialCoefficient(i, j, k) *
                                                             std::pow(t.u, i) * std::pow(t.v, j) *
                                                             std::pow(t.w, k));
    }
  }
  return sum;
}

struct NetCase {
  PatchDomain domain;
  int degree;
  size_t expected_coefficients;
};

TEST(TangentPlane, CoefficientsSumToTheTangentPlaneTestOfTheSurface) {
  const NetCase cases[] = {{PatchDomain::kQuad, 3, 81},
                           {PatchDomain::kQuad, 2, 36},
                           {PatchDomain::kTriangle, 2, 15},
                           {PatchDomain::kTriangle, 3, 36},
                           {PatchDomain::kTriangle, 4, 66}};
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  auto randomPoint = [&] { return mesh::Vec3d{coordinate(rng), coordinate(rng), coordinate(rng)}; };
  for (const NetCase& c : cases) {
    const bool quad = c.domain == PatchDomain::kQuad;
    for (int trial = 0; trial < 6; ++trial) {
      techniques::PatchCullBounds bounds;
      bounds.bezier_degree = c.degree;
      bounds.bezier_mirrored = trial % 2 == 1;
      const size_t points = quad ? size_t((c.degree + 1) * (c.degree + 1))
                                 : size_t(techniques::triangleNetSize(c.degree));
      for (size_t i = 0; i < points; ++i)
        bounds.bezier_net.push_back(randomPoint() + mesh::Vec3d{5, -3, 2});
      const mesh::Vec3d origin = bounds.bezier_net[0];
      const auto coefficients = lod::tangentPlaneCoefficients(c.domain, bounds, origin);
      ASSERT_EQ(coefficients.size(), c.expected_coefficients);
      const mesh::Vec3d eye = randomPoint() * 4.0;
      const double sign = bounds.bezier_mirrored ? -1 : 1;
      for (int a = 1; a < 6; ++a) {
        for (int b = 1; b < 6; ++b) {
          const Tri t = quad ? Tri{a / 6.0, b / 6.0, 0} : Tri{a / 7.0, b / 7.0, 1 - (a + b) / 7.0};
          if (!quad && t.w <= 0) continue;
          const double oracle = quad ? quadOracle(bounds.bezier_net, c.degree, eye, t.u, t.v)
                                     : triangleOracle(bounds.bezier_net, c.degree, eye, t);
          const Sum sum = coefficientSum(coefficients, c.domain, eye - origin, t);
          EXPECT_NEAR(sum.value, sign * oracle, 1e-6 * sum.scale)
              << (quad ? "quad" : "triangle") << " degree " << c.degree << " trial " << trial
              << " at " << t.u << ", " << t.v;
        }
      }
    }
  }
}

TEST(TangentPlane, ABumpySheetSeenFromBelowHasEveryCoefficientNegative) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> bump(-0.05, 0.05);
  techniques::PatchCullBounds bounds;
  bounds.bezier_degree = 3;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) bounds.bezier_net.push_back({i / 3.0, j / 3.0, bump(rng)});
  }
  const mesh::Vec3d origin = bounds.bezier_net[0];
  const auto coefficients = lod::tangentPlaneCoefficients(PatchDomain::kQuad, bounds, origin);
  auto signs = [&](const mesh::Vec3d& eye) {
    size_t negative = 0;
    const mesh::Vec3d d = eye - origin;
    for (const auto& c : coefficients)
      negative += d[0] * c[0] + d[1] * c[1] + d[2] * c[2] + c[3] < 0;
    return negative;
  };
  EXPECT_EQ(signs({0.5, 0.5, -3}), coefficients.size());  // below: faces away everywhere
  EXPECT_EQ(signs({0.5, 0.5, 3}), 0u);                    // above: faces the eye everywhere
  // Seen edge-on from the side the sheet's bumps face both ways: neither answer is proved.
  const size_t edge_on = signs({3, 0.5, 0});
  EXPECT_GT(edge_on, 0u);
  EXPECT_LT(edge_on, coefficients.size());
  // A net whose size does not match its degree is refused.
  bounds.bezier_net.pop_back();
  EXPECT_THROW(lod::tangentPlaneCoefficients(PatchDomain::kQuad, bounds, origin),
               std::invalid_argument);
}

}  // namespace
}  // namespace tb

namespace tb {
namespace {

// The chord margin's pattern factors: on the quad's regular grid of integer level L every
// triangle has legs 1/L at a right angle, so K2 = 1/L and K3 = 1/(4 L^2); on the triangle's
// rings they shrink like 1/L and 1/L^2 too.
TEST(TangentPlane, ChordFactorsFollowThePatternsTriangles) {
  for (float level : {2.0f, 4.0f, 8.0f}) {
    const auto quad = lod::chordFactors(tess::Domain::kQuad, level);
    EXPECT_NEAR(quad[0], 1 / level, 1e-6) << level;
    EXPECT_NEAR(quad[1], 0.25 / (level * level), 1e-6) << level;
  }
  const auto t4 = lod::chordFactors(tess::Domain::kTriangle, 4);
  const auto t8 = lod::chordFactors(tess::Domain::kTriangle, 8);
  EXPECT_GT(t4[0], 0);
  EXPECT_NEAR(t8[0] / t4[0], 0.5, 0.15);
  EXPECT_NEAR(t8[1] / t4[1], 0.25, 0.1);
}

}  // namespace
}  // namespace tb
