// The dense kernel of batched evaluation (techniques/batch_eval.h): basis weights of a
// patch's control points at the points of one pattern, computed once, and the product
// that turns one patch's control points into its points.
//
// A patch that is linear in its K control points c_k for a fixed domain point (ACC's
// Bézier and tangent patches; Gregory patches, whose rational interior blend depends only
// on (u, v)) evaluates as P(i) = Σ_k w_k(i) c_k. With the weights tabulated per point,
// a patch costs 3 K multiply-adds per point and quantity (position, du or dv), in loops
// over blocks of kBatchLanes points that map onto SIMD registers.
#pragma once

#include <array>
#include <cstddef>

#include "core/mesh/vec.h"
#include "techniques/batch_eval.h"

namespace tb::techniques {

// Weights of `control_points` control points at `points` domain points. Stored in blocks
// of kBatchLanes points, block-major: weight of control point k at point i is at
// [((i / kBatchLanes) * control_points + k) * kBatchLanes + i % kBatchLanes], so one
// block's weights for one control point are one aligned SIMD load. Padding points weigh 0.
class BasisTable {
 public:
  BasisTable() = default;
  BasisTable(size_t points, size_t control_points)
      : points_(points),
        control_points_(control_points),
        weights_(batchBlocks(points) * control_points * kBatchLanes) {}

  size_t points() const { return points_; }
  size_t controlPoints() const { return control_points_; }
  size_t blocks() const { return batchBlocks(points_); }
  double& at(size_t point, size_t control_point) { return weights_[slot(point, control_point)]; }
  double at(size_t point, size_t control_point) const {
    return weights_[slot(point, control_point)];
  }
  const double* data() const { return weights_.data(); }

 private:
  size_t slot(size_t point, size_t control_point) const {
    return ((point / kBatchLanes) * control_points_ + control_point) * kBatchLanes +
           point % kBatchLanes;
  }
  size_t points_ = 0, control_points_ = 0;
  AlignedDoubles weights_;
};

// The instruction sets the kernels are written for. kPortable is plain C++ (SSE2 on the
// project's generic x86-64 build: a multiply and an add, two roundings); the others run
// one fused multiply-add per weight and are chosen at run time when the CPU has them.
enum class BatchKernel { kPortable, kAvx2Fma, kAvx512 };

bool batchKernelSupported(BatchKernel kernel);
BatchKernel fastestBatchKernel();          // the widest this CPU supports
const char* toString(BatchKernel kernel);  // "portable", "avx2_fma", "avx512"

// out[c][i] = Σ_k basis.at(i, k) · control[k][c] for every point of the table, padding
// included (it comes out 0); `out` arrays hold basis.blocks() * kBatchLanes values.
// Cost: 3 basis.controlPoints() multiply-adds per point.
void combineControlPoints(const BasisTable& basis, const mesh::Vec3d* control,
                          std::array<AlignedDoubles, 3>& out,
                          BatchKernel kernel = fastestBatchKernel());

// normal = (du x dv) / |du x dv| for the first `count` points rounded up to a block, as
// normalize(cross(du, dv)) does (a zero cross product stays zero).
void normalsFromTangents(const std::array<AlignedDoubles, 3>& du,
                         const std::array<AlignedDoubles, 3>& dv,
                         std::array<AlignedDoubles, 3>& normal, size_t count,
                         BatchKernel kernel = fastestBatchKernel());

}  // namespace tb::techniques
