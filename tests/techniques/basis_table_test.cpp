// The batched kernels of techniques/common/basis_table.h, each one this CPU supports.
// Oracles: the product summed directly in long double (1e-14 relative), and
// normalize(cross()) for the normals; padding points must come out 0.
#include "techniques/common/basis_table.h"

#include <gtest/gtest.h>

#include <random>

namespace tb {
namespace {

std::vector<techniques::BatchKernel> supportedKernels() {
  std::vector<techniques::BatchKernel> kernels;
  for (techniques::BatchKernel k :
       {techniques::BatchKernel::kPortable, techniques::BatchKernel::kAvx2Fma,
        techniques::BatchKernel::kAvx512}) {
    if (techniques::batchKernelSupported(k)) kernels.push_back(k);
  }
  return kernels;
}

TEST(BasisTable, WeightsLieInBlocksOfLanes) {
  techniques::BasisTable table(11, 3);
  EXPECT_EQ(table.blocks(), 2u);
  table.at(9, 2) = 5.0;  // block 1, control point 2, lane 1
  EXPECT_EQ(table.data()[(1 * 3 + 2) * techniques::kBatchLanes + 1], 5.0);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(table.data()) % techniques::AlignedDoubles::kAlignment, 0u);
}

TEST(BasisTable, EveryKernelComputesTheDirectSum) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  // Point counts that leave 0, 1, 3 and 4 blocks over the kernels' 4- and 2-block steps.
  for (size_t points : {1u, 8u, 29u, 40u, 289u}) {
    for (size_t k_count : {1u, 12u, 15u, 16u, 20u, 23u}) {  // the unrolled counts and others
      techniques::BasisTable table(points, k_count);
      std::vector<mesh::Vec3d> control(k_count);
      for (mesh::Vec3d& c : control) c = {value(rng), value(rng), value(rng)};
      for (size_t i = 0; i < points; ++i) {
        for (size_t k = 0; k < k_count; ++k) table.at(i, k) = value(rng);
      }
      for (techniques::BatchKernel kernel : supportedKernels()) {
        techniques::BatchPoints out;
        out.reset(points);
        if (points % techniques::kBatchLanes != 0)
          out.position[0][points] = 99.0;  // padding: must become 0
        techniques::combineControlPoints(table, control.data(), out.position, kernel);
        for (size_t i = 0; i < table.blocks() * techniques::kBatchLanes; ++i) {
          for (int axis = 0; axis < 3; ++axis) {
            long double sum = 0, magnitude = 0;
            for (size_t k = 0; k < k_count && i < points; ++k) {
              sum += (long double)table.at(i, k) * control[k][axis];
              magnitude += std::abs((long double)table.at(i, k) * control[k][axis]);
            }
            EXPECT_NEAR(out.position[axis][i], double(sum), 1e-14 * double(magnitude) + 1e-300)
                << toString(kernel) << " points " << points << " K " << k_count << " i " << i;
          }
        }
      }
    }
  }
}

TEST(BasisTable, EveryKernelNormalisesCrossProductsAndKeepsZeroOnes) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  const size_t points = 21;
  techniques::BatchPoints in;
  in.reset(points);
  for (size_t i = 0; i < points; ++i) {
    techniques::BatchPoints::set(in.du, i, {value(rng), value(rng), value(rng)});
    techniques::BatchPoints::set(in.dv, i,
                                 i == 4 ? techniques::BatchPoints::at(in.du, i) * 2.0
                                        : mesh::Vec3d{value(rng), value(rng), value(rng)});
  }
  for (techniques::BatchKernel kernel : supportedKernels()) {
    techniques::normalsFromTangents(in.du, in.dv, in.normal, points, kernel);
    for (size_t i = 0; i < points; ++i) {
      const mesh::Vec3d expected = normalize(
          cross(techniques::BatchPoints::at(in.du, i), techniques::BatchPoints::at(in.dv, i)));
      EXPECT_LE(length(techniques::BatchPoints::at(in.normal, i) - expected), 1e-15)
          << toString(kernel) << " " << i;
    }
    EXPECT_EQ(techniques::BatchPoints::at(in.normal, 4), mesh::Vec3d{}) << toString(kernel);
  }
}

}  // namespace
}  // namespace tb
