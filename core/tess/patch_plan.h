// From the levels a shader writes to the per-edge spacings the tessellator places
// points with: culling, clamping, rounding, parity and the inside-level fix-ups of the
// D3D11 tessellator (D3D11.3 functional spec §11; Vulkan spec "Tessellation",
// "Tessellator Spacing"). Internal to tb_tess.
#pragma once

#include <array>

#include "core/tess/edge_spacing.h"
#include "core/tess/tessellator.h"

namespace tb::tess {

struct TrianglePlan {
  bool culled = false;
  bool minimal = false;                // every level is 1: one triangle, no rings
  std::array<EdgeSpacing, 3> outer{};  // edges u = 0, v = 0, w = 0
  EdgeSpacing inner{};                 // point_count raised to the ring minimum
};

struct QuadPlan {
  bool culled = false;
  bool minimal = false;                // every level is 1: two triangles, no rings
  std::array<EdgeSpacing, 4> outer{};  // edges u = 0, v = 0, u = 1, v = 1
  std::array<EdgeSpacing, 2> inner{};  // along u, along v; point_count raised to the minimum
};

struct IsolinePlan {
  bool culled = false;
  int line_count = 0;     // lines at v = 0 .. < 1 (the line at v = 1 is never drawn)
  EdgeSpacing density{};  // places the lines along v; always integer spacing
  EdgeSpacing detail{};   // places the points along each line
};

TrianglePlan planTriangle(Spacing spacing, const Levels& levels);
QuadPlan planQuad(Spacing spacing, const Levels& levels);
IsolinePlan planIsoline(Spacing spacing, const Levels& levels);

}  // namespace tb::tess
