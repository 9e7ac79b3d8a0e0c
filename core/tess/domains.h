// Point generation and connectivity per domain, plus the small pieces they share.
// Internal to tb_tess; tessellator.cpp documents the output order.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/tess/fixed_point.h"
#include "core/tess/patch_plan.h"
#include "core/tess/tessellator.h"

namespace tb::tess {

// Appends domain points converted from 16.16. Triangle points get w = (1 - u) - v in
// float, which is how lavapipe (Mesa draw_llvm.c, TES tess-coord setup) derives
// gl_TessCoord.z from the two coordinates the tessellator stores; for multiples of
// 2^-16 in [0, 1] it is exact. Quad and isoline points get 0.
class PointWriter {
 public:
  PointWriter(Tessellation* out, bool barycentric) : out_(out), barycentric_(barycentric) {}
  uint32_t add(fxp::Fixed u, fxp::Fixed v) {
    const float uf = fxp::toFloat(u);
    const float vf = fxp::toFloat(v);
    const float w = barycentric_ ? (1.0f - uf) - vf : 0.0f;
    out_->points.push_back({uf, vf, w});
    return static_cast<uint32_t>(out_->points.size() - 1);
  }

 private:
  Tessellation* out_;
  bool barycentric_;
};

// One ring's edges as rows of point indices, each row including both of its corners
// (so consecutive rows share a corner, and the last row ends at the ring's first point).
using RingRows = std::array<std::vector<uint32_t>, 4>;

// Adds to every edge row the first point of the next edge (the last edge wraps to the
// first): rows are filled with each edge's points except its end corner.
inline void closeRing(RingRows* ring, size_t edge_count) {
  for (size_t e = 0; e < edge_count; ++e) {
    (*ring)[e].push_back((*ring)[(e + 1) % edge_count].front());
  }
}

inline std::vector<uint32_t> reversedRow(const std::vector<uint32_t>& row) {
  return {row.rbegin(), row.rend()};
}

void tessellateTriangleDomain(const TrianglePlan& plan, const Options& options, Tessellation* out);
void tessellateQuadDomain(const QuadPlan& plan, const Options& options, Tessellation* out);

}  // namespace tb::tess
