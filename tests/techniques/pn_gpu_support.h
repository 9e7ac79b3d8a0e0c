// Shared by the PN and Phong GPU tests: runs a technique's GPU program on lavapipe and
// compares every captured vertex with SurfacePatches::evaluateFloat at the same
// gl_TessCoord bits (the oracle: the CPU float model in the shader's operation order).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "core/gpu/patch_program.h"
#include "core/mesh/float_ulp.h"
#include "core/mesh/obj_loader.h"
#include "techniques/technique.h"
#include "tests/test_support.h"

namespace tb::testing {

struct GpuAgreement {
  size_t vertices = 0;           // captured vertices compared
  size_t expected_vertices = 0;  // patches × CPU-tessellator points
  uint64_t max_position_ulp = 0;
  uint64_t max_normal_ulp = 0;
  size_t positions_not_bitwise = 0;  // +0 and -0 count as equal
};

inline GpuAgreement compareGpuWithFloat(gpu::Context& context,
                                        const techniques::SurfacePatches& patches,
                                        tess::Spacing spacing, float level) {
  const auto programs = patches.gpuPrograms();
  const gpu::GpuPatchProgram* program = programs.empty() ? nullptr : &programs.front();
  GpuAgreement result;
  if (!program) return result;
  tess::Levels levels;
  levels.outer = {level, level, level, level};
  levels.inner = {level, level};
  gpu::PatchProgramOptions options;
  options.spacing = spacing;
  options.patches_per_draw = 64;
  const gpu::PatchProgramCapture capture = gpu::runPatchProgram(context, *program, levels, options);
  const tess::Spacing cpu_spacing =
      spacing == tess::Spacing::kPow2 ? tess::Spacing::kInteger : spacing;
  result.expected_vertices =
      patches.patchCount() *
      tess::tessellate(tess::Domain::kTriangle, cpu_spacing, levels).points.size();
  for (const gpu::CapturedVertex& v : capture.vertices) {
    const techniques::SurfacePointF cpu = patches.evaluateFloat(v.patch, v.coord);
    ++result.vertices;
    bool equal = true;
    for (int k = 0; k < 3; ++k) {
      result.max_position_ulp =
          std::max(result.max_position_ulp, mesh::ulpDistance(v.position[k], cpu.position[k]));
      result.max_normal_ulp =
          std::max(result.max_normal_ulp, mesh::ulpDistance(v.normal[k], cpu.normal[k]));
      equal = equal && mesh::ulpDistance(v.position[k], cpu.position[k]) == 0;
    }
    result.positions_not_bitwise += equal ? 0 : 1;
  }
  return result;
}

// Every bundled triangle-only asset the issue names.
inline std::vector<std::string> triangleAssets() {
  return {"tessbench/flat_cube.obj",
          "tessbench/cylinder_seam.obj",
          "tessbench/tjunction.obj",
          "tessbench/tri_torus.obj",
          "tessbench/tri_pawn.obj",
          "opensubdiv/loop_cube.obj",
          "opensubdiv/loop_cube_creases1.obj",
          "opensubdiv/loop_icos_semisharp.obj",
          "opensubdiv/loop_icosahedron.obj",
          "opensubdiv/loop_toroidal_tet.obj",
          "opensubdiv/loop_triangle_edgecorner.obj",
          "opensubdiv/loop_xord_interior.obj",
          "opensubdiv/catmark_smoothtris0.obj"};
}

}  // namespace tb::testing
