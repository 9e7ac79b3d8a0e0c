// Oracle: seed 000's published instruction counts of the four Bézier evaluation orders
// (60 asymmetric, 105 symmetric without FMA, 75 symmetric with FMA, 69 symmetric on edges
// only). Absolute counts depend on the ISA; the work each order adds over the asymmetric
// one does not, so our static SPIR-V counts (spirv-opt -O, scalar-expanded float
// arithmetic + fma) of the position-only probe must reproduce the seed's increments.
#include <gtest/gtest.h>

#include "harness/measures/common/instruction_counts/instructions.h"

namespace tb {
namespace {

double alu(const measures::InstructionCounts& c) { return double(c.floatArithmetic() + c.fma); }

TEST(PublishedFigures, BezierOrderIncrementsMatchSeed000) {
  const double seed[4] = {60, 105, 75, 69};  // asymmetric, symmetric_nofma, _fma, _edges
  const double asymmetric =
      alu(measures::countEmbeddedShader("acc/bezier_position.tese", {0}).scalar);
  for (uint32_t order = 1; order < 4; ++order) {
    const double ours =
        alu(measures::countEmbeddedShader("acc/bezier_position.tese", {order}).scalar);
    EXPECT_EQ(ours - asymmetric, seed[order] - seed[0]) << "order " << order;
  }
}

TEST(PublishedFigures, TheOrdersAreNotAllTheSameShader) {
  // Guards the test above: specialisation must reach the probe, or every order would
  // count the same and only a coincidence could pass.
  const double fma = alu(measures::countEmbeddedShader("acc/bezier_position.tese", {2}).scalar);
  const double nofma = alu(measures::countEmbeddedShader("acc/bezier_position.tese", {1}).scalar);
  EXPECT_NE(fma, nofma);
}

}  // namespace
}  // namespace tb
