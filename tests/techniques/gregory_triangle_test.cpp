// The triangle Gregory patch evaluator (gregory_eval.h, evaluateGregoryTriangle) against
// independent oracles: a cubic Bézier triangle summed directly in its Bernstein basis
// (when the two points of every corner agree, the patch IS that cubic, degree-raised),
// and the Gregory property (an edge's cross-boundary derivative does not depend on the
// interior points that belong to the other two edges).
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "techniques/gregory_acc/gregory_eval.h"

namespace tb::gregory_acc {
namespace {

using Cubic = std::array<std::array<mesh::Vec3d, 4>, 4>;  // c[i][j], k = 3 - i - j

Cubic randomCubic(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  Cubic c{};
  for (int i = 0; i <= 3; ++i) {
    for (int j = 0; i + j <= 3; ++j) c[i][j] = {d(rng), d(rng), d(rng)};
  }
  return c;
}

mesh::Vec3d cubicAt(const Cubic& c, double u, double v, double w) {
  const int fact[4] = {1, 1, 2, 6};
  mesh::Vec3d sum{};
  for (int i = 0; i <= 3; ++i) {
    for (int j = 0; i + j <= 3; ++j) {
      const int k = 3 - i - j;
      const double basis =
          6.0 / (fact[i] * fact[j] * fact[k]) * std::pow(u, i) * std::pow(v, j) * std::pow(w, k);
      sum = sum + c[i][j] * basis;
    }
  }
  return sum;
}

// The cubic's points in the patch's slots: boundary from the cubic net, and both interior
// points of corner c its degree-raised interior point (b211 = (2 c111 + c201 + c210)/4).
GregoryPoints<double> fromCubic(const Cubic& c) {
  GregoryPoints<double> cp{};
  auto set = [&cp](int corner, Slot slot, const mesh::Vec3d& p) { cp[corner * 5 + slot] = p; };
  set(0, kP, c[3][0]);
  set(1, kP, c[0][3]);
  set(2, kP, c[0][0]);
  set(0, kEp, c[2][1]);  // toward corner 1
  set(0, kEm, c[2][0]);  // toward corner 2 (c201)
  set(1, kEp, c[0][2]);  // c021, toward corner 2
  set(1, kEm, c[1][2]);  // c120, toward corner 0
  set(2, kEp, c[1][0]);  // c102, toward corner 0
  set(2, kEm, c[0][1]);  // c012, toward corner 1
  const mesh::Vec3d& c111 = c[1][1];
  const mesh::Vec3d b211 = (c111 * 2.0 + c[2][0] + c[2][1]) * 0.25;
  const mesh::Vec3d b121 = (c111 * 2.0 + c[0][2] + c[1][2]) * 0.25;  // (2 c111 + c021 + c120) / 4
  const mesh::Vec3d b112 = (c111 * 2.0 + c[1][0] + c[0][1]) * 0.25;  // (2 c111 + c102 + c012) / 4
  for (Slot s : {kFp, kFm}) {
    set(0, s, b211);
    set(1, s, b121);
    set(2, s, b112);
  }
  return cp;
}

const std::array<std::array<double, 3>, 6> kPoints = {{{0.2, 0.3, 0.5},
                                                       {0.7, 0.1, 0.2},
                                                       {1.0 / 3, 1.0 / 3, 1.0 / 3},
                                                       {0.05, 0.9, 0.05},
                                                       {0.5, 0.5, 0.0},
                                                       {0.0, 0.25, 0.75}}};

TEST(GregoryTriangle, EqualsTheCubicBezierTriangleWhenCornerPointsAgree) {
  for (uint32_t seed = 1; seed <= 5; ++seed) {
    const Cubic c = randomCubic(seed);
    const GregoryPoints<double> cp = fromCubic(c);
    for (bool symmetric : {false, true}) {
      for (const auto& [u, v, w] : kPoints) {
        const GregoryPoint<double> got = evaluateGregoryTriangle(cp, u, v, w, symmetric);
        EXPECT_LE(length(got.position - cubicAt(c, u, v, w)), 1e-14)
            << seed << " " << u << "," << v;
        // Normal: the cubic's finite-difference tangents toward corners 1 and 2.
        const double h = 1e-6;
        const mesh::Vec3d ta =
            (cubicAt(c, u - h, v + h, w) - cubicAt(c, u + h, v - h, w)) * (0.5 / h);
        const mesh::Vec3d tc =
            (cubicAt(c, u - h, v, w + h) - cubicAt(c, u + h, v, w - h)) * (0.5 / h);
        EXPECT_LE(length(got.normal - normalize(cross(ta, tc))), 1e-7) << seed;
      }
    }
  }
}

TEST(GregoryTriangle, FloatEvaluationFollowsTheDoubleOne) {
  const Cubic c = randomCubic(11);
  GregoryPoints<double> cp = fromCubic(c);
  cp[0 * 5 + kFm] = cp[0 * 5 + kFm] + mesh::Vec3d{0.1, -0.2, 0.05};  // a true Gregory patch
  GregoryPoints<float> cpf;
  for (size_t i = 0; i < cp.size(); ++i) cpf[i] = vecCast<float>(cp[i]);
  for (const auto& [u, v, w] : kPoints) {
    const mesh::Vec3d d = evaluateGregoryTriangle(cp, u, v, w, true).position;
    const mesh::Vec3f f = evaluateGregoryTriangle(cpf, float(u), float(v), float(w), true).position;
    EXPECT_LE(length(vecCast<double>(f) - d), 1e-6);
  }
}

// Edge w = 0 (corner 0 -> 1): position and the derivative toward corner 2 there depend
// on Fp0 and Fm1 only; moving Fm0, Fp1, and both points of corner 2 changes neither.
TEST(GregoryTriangle, EachEdgeSeesOnlyItsOwnInteriorPoints) {
  const Cubic c = randomCubic(7);
  const GregoryPoints<double> base = fromCubic(c);
  GregoryPoints<double> moved = base;
  for (int index : {0 * 5 + kFm, 1 * 5 + kFp, 2 * 5 + kFp, 2 * 5 + kFm}) {
    moved[index] = moved[index] + mesh::Vec3d{0.3, 0.1, -0.4};
  }
  GregoryPoints<double> own = base;
  own[0 * 5 + kFp] = own[0 * 5 + kFp] + mesh::Vec3d{0.3, 0.1, -0.4};
  const double h = 1e-6;
  for (double t : {0.1, 0.35, 0.5, 0.8}) {
    auto towardCorner2 = [&](const GregoryPoints<double>& cp) {
      // One-sided difference into the patch from (1 - t, t, 0).
      const mesh::Vec3d inside = evaluateGregoryTriangle(cp, 1 - t - h, t, h, false).position;
      const mesh::Vec3d edge = evaluateGregoryTriangle(cp, 1 - t, t, 0.0, false).position;
      return (inside - edge) * (1 / h);
    };
    EXPECT_LE(length(evaluateGregoryTriangle(moved, 1 - t, t, 0.0, false).position -
                     evaluateGregoryTriangle(base, 1 - t, t, 0.0, false).position),
              1e-15);
    EXPECT_LE(length(towardCorner2(moved) - towardCorner2(base)), 1e-4) << t;
    // The test can fail: the edge's own point does change the cross derivative.
    EXPECT_GT(length(towardCorner2(own) - towardCorner2(base)), 1e-2) << t;
  }
}

}  // namespace
}  // namespace tb::gregory_acc
