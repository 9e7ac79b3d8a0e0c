// evaluateBicubicFast (techniques/common/bezier_eval.h): the double bicubic with its fused
// multiply-adds as the processor's FMA instruction. Oracle: evaluateBicubic, whose std::fma is
// libm's correctly rounded one; they must agree bit for bit in every order, on random nets and
// parameters. Control (made to fail): the same sums with each fused multiply-add rounded twice
// (a multiply, then an add), which differs in the last bits somewhere on the same inputs.
#include <gtest/gtest.h>

#include <bit>
#include <random>

#include "techniques/common/bezier_eval.h"

namespace tb {
namespace {

using techniques::BezierOrder;

std::array<mesh::Vec3d, 16> randomNet(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coordinate(-10, 10);
  std::array<mesh::Vec3d, 16> net;
  for (mesh::Vec3d& p : net) p = {coordinate(rng), coordinate(rng), coordinate(rng)};
  return net;
}

bool bitEqual(const mesh::Vec3d& a, const mesh::Vec3d& b) {
  for (int k = 0; k < 3; ++k) {
    if (std::bit_cast<uint64_t>(a[k]) != std::bit_cast<uint64_t>(b[k])) return false;
  }
  return true;
}

// The control's sum: kChain's order (p3 w3 + (p2 w2 + (p1 w1 + p0 w0))) with two roundings
// per step, as a build that did not fuse would compute it.
mesh::Vec3d twiceRoundedChain(const std::array<mesh::Vec3d, 16>& b, double u, double v) {
  const std::array<double, 4> bu = techniques::cubicBasis(u), bv = techniques::cubicBasis(v);
  auto chain = [](const mesh::Vec3d& p0, const mesh::Vec3d& p1, const mesh::Vec3d& p2,
                  const mesh::Vec3d& p3, const std::array<double, 4>& w) {
    return p3 * w[3] + (p2 * w[2] + (p1 * w[1] + p0 * w[0]));
  };
  std::array<mesh::Vec3d, 4> rows;
  for (int j = 0; j < 4; ++j)
    rows[j] = chain(b[4 * j], b[4 * j + 1], b[4 * j + 2], b[4 * j + 3], bu);
  return chain(rows[0], rows[1], rows[2], rows[3], bv);
}

TEST(BezierFma, TheFmaInstructionGivesLibmsPointsBitForBit) {
  std::mt19937_64 rng(62);
  std::uniform_real_distribution<double> parameter(0, 1);
  size_t control_differs = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const std::array<mesh::Vec3d, 16> net = randomNet(rng);
    const double u = parameter(rng), v = parameter(rng);
    for (BezierOrder order :
         {BezierOrder::kAsymmetric, BezierOrder::kSymmetricNoFma, BezierOrder::kSymmetricFma,
          BezierOrder::kSymmetricEdges, BezierOrder::kSymmetricNoFmaImprecise}) {
      ASSERT_TRUE(bitEqual(techniques::evaluateBicubicFast(net, u, v, order),
                           techniques::evaluateBicubic(net, u, v, order)))
          << "trial " << trial << " order " << int(order);
    }
    control_differs += !bitEqual(twiceRoundedChain(net, u, v),
                                 techniques::evaluateBicubic(net, u, v, BezierOrder::kAsymmetric));
  }
  // The control is caught: two roundings differ from one on most random inputs.
  EXPECT_GT(control_differs, 1000u);
}

}  // namespace
}  // namespace tb
