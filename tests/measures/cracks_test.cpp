// The crack measure against its oracles: hand counts of shared edges, corners and
// compared points on small grids; test-double patches whose float evaluation is
// symmetric in the edge parameter (must be bitwise watertight) or naive (must show
// cracks); and on the device, the bilinear test shaders, whose captured positions must
// equal the same formulas evaluated on the CPU.
#include "harness/measures/common/cracks/cracks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/mesh/obj_loader.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/measures/face_patches.h"
#include "tests/test_support.h"

namespace tb {
namespace {

// A (cells+1)² grid of positions with irrational-looking coordinates, so float
// arithmetic rounds on nearly every operation.
mesh::Mesh gridMesh(int cells, bool triangles) {
  std::string obj;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      const double x = i * 0.7310585 + 0.1 * std::sin(1.3 * j);
      const double y = j * 0.6224593 + 0.1 * std::cos(0.7 * i);
      const double z = 0.3 * std::sin(i + 2.0 * j) + 0.017;
      obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z) + "\n";
    }
  }
  auto id = [&](int i, int j) { return std::to_string(j * (cells + 1) + i + 1); };
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const std::string a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (!triangles) {
        obj += "f " + a + " " + b + " " + c + " " + d + "\n";
      } else if ((i + j) % 2 == 0) {
        obj += "f " + a + " " + b + " " + c + "\nf " + a + " " + c + " " + d + "\n";
      } else {
        obj += "f " + a + " " + b + " " + d + "\nf " + b + " " + c + " " + d + "\n";
      }
    }
  }
  return mesh::loadObjText(obj, triangles ? "tri_grid.obj" : "quad_grid.obj");
}

// Patch p is face p of the mesh, flat: bilinear on quads, linear on triangles.
// kSymmetric uses sums of products of the corners (the same terms in any edge
// direction); kNaive a corner plus scaled differences (depends on the direction).
enum class Order { kSymmetric, kNaive };

class FlatPatches final : public testing::FacePatches {
 public:
  FlatPatches(mesh::Mesh mesh, Order order) : FacePatches(std::move(mesh)), order_(order) {}
  techniques::SurfacePoint evaluate(size_t patch,
                                    const techniques::DomainCoord& coord) const override {
    const techniques::SurfacePointF f =
        evaluateFloat(patch, {float(coord[0]), float(coord[1]), float(coord[2])});
    return {vecCast<double>(f.position), {0, 0, 1}};
  }
  techniques::SurfacePointF evaluateFloat(size_t patch, const tess::DomainPoint& c) const override {
    const mesh::Vec3f p0 = cornerF(patch, 0), p1 = cornerF(patch, 1), p2 = cornerF(patch, 2);
    if (patchDomain(0) == techniques::PatchDomain::kTriangle) {
      if (order_ == Order::kNaive) return {p0 + (p1 - p0) * c[1] + (p2 - p0) * c[2], {0, 0, 1}};
      return {p0 * c[0] + p1 * c[1] + p2 * c[2], {0, 0, 1}};
    }
    const mesh::Vec3f p3 = cornerF(patch, 3);
    const float u = c[0], v = c[1];
    if (order_ == Order::kNaive) {  // shaders/gpu/test_naive_bilinear.tese
      const mesh::Vec3f bottom = p0 + (p1 - p0) * u, top = p3 + (p2 - p3) * u;
      return {bottom + (top - bottom) * v, {0, 0, 1}};
    }
    // shaders/gpu/test_bilinear.tese with scale 1
    const mesh::Vec3f bottom = p0 * (1 - u) + p1 * u, top = p3 * (1 - u) + p2 * u;
    return {(bottom * (1 - v) + top * v) * 1.0f, {0, 0, 1}};
  }
  std::vector<gpu::GpuPatchProgram> gpuPrograms() const override {
    if (patchDomain(0) != techniques::PatchDomain::kQuad) return {};
    gpu::GpuPatchProgram program;
    program.control_shader = "gpu/test_bilinear.tesc";
    program.evaluation_shader =
        order_ == Order::kNaive ? "gpu/test_naive_bilinear.tese" : "gpu/test_bilinear.tese";
    program.domain = tess::Domain::kQuad;
    program.patch_count = uint32_t(patchCount());
    std::vector<uint32_t> corners;
    for (size_t p = 0; p < patchCount(); ++p) {
      for (int k = 0; k < 4; ++k) {
        const mesh::Vec3f c = cornerF(p, uint32_t(k));
        for (float x : {c.x, c.y, c.z, 1.0f}) corners.push_back(std::bit_cast<uint32_t>(x));
      }
    }
    program.storage_buffers = {corners};
    if (order_ == Order::kSymmetric) program.specialization = {std::bit_cast<uint32_t>(1.0f)};
    return {program};
  }

 private:
  Order order_;
};

constexpr tess::Spacing kSpacings[] = {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd,
                                       tess::Spacing::kFractionalEven, tess::Spacing::kPow2};
constexpr float kLevels[] = {1.0f, 7.3f, 16.0f, 64.0f};

TEST(Cracks, UlpDistanceCountsRepresentableFloats) {
  EXPECT_EQ(mesh::ulpDistance(1.0f, std::nextafter(1.0f, 2.0f)), 1u);
  EXPECT_EQ(mesh::ulpDistance(-0.0f, 0.0f), 0u);
  const float tiny = std::numeric_limits<float>::denorm_min();
  EXPECT_EQ(mesh::ulpDistance(-tiny, tiny), 2u);
  EXPECT_EQ(mesh::ulpDistance(2.0f, 1.0f), 1u << 23);
}

TEST(Cracks, SharedEdgesAndCornersOfAQuadGridMatchAHandCount) {
  const FlatPatches patches(gridMesh(3, false), Order::kSymmetric);
  const measures::SharedBoundaries shared = measures::findSharedBoundaries(patches);
  EXPECT_EQ(shared.edges.size(), 12u);    // 2 directions × 3 rows × 2 interior lines
  EXPECT_EQ(shared.corners.size(), 12u);  // 4 interior + 8 boundary non-corner vertices
  for (const measures::SharedEdge& e : shared.edges) {
    ASSERT_EQ(e.sides.size(), 2u);
    // Consistently oriented faces run a shared edge in opposite directions.
    EXPECT_NE(e.sides[0].reversed, e.sides[1].reversed);
    EXPECT_FALSE(e.seam);
  }
  // Integer level n: n - 1 interior points per edge; corners: 4 interior vertices of
  // 4 patches (3 comparisons each) and 8 boundary vertices of 2 patches (1 each).
  for (uint32_t n : {1u, 5u, 16u}) {
    const measures::CrackFigures f = measures::measureCracks(
        patches, tess::Spacing::kInteger, float(n), measures::CrackBackend::kCpuFloat);
    EXPECT_EQ(f.points_compared, 12u * (n - 1) + 4 * 3 + 8) << "level " << n;
    EXPECT_EQ(f.unpaired_points, 0u);
  }
}

TEST(Cracks, SymmetricEvaluationIsBitwiseWatertightOnTheCpuUnderEverySpacing) {
  for (bool triangles : {false, true}) {
    const FlatPatches patches(gridMesh(3, triangles), Order::kSymmetric);
    for (tess::Spacing spacing : kSpacings) {
      for (float level : kLevels) {
        const measures::CrackFigures f =
            measures::measureCracks(patches, spacing, level, measures::CrackBackend::kCpuFloat);
        SCOPED_TRACE(std::string(tess::toString(spacing)) + " level " + std::to_string(level) +
                     (triangles ? " triangles" : " quads"));
        ASSERT_TRUE(f.measured);
        EXPECT_GT(f.points_compared, 0u);
        EXPECT_EQ(f.unpaired_points, 0u);
        EXPECT_EQ(f.points_not_equal, 0u);
        EXPECT_EQ(f.max_gap_ulp, 0u);
        EXPECT_EQ(f.max_gap_scale_ulp, 0.0);
        EXPECT_EQ(f.max_gap_world, 0.0);
        EXPECT_FALSE(f.worst.found);
      }
    }
  }
}

TEST(Cracks, NaiveEvaluationOpensGapsOfAFewUlps) {
  for (bool triangles : {false, true}) {
    const FlatPatches patches(gridMesh(3, triangles), Order::kNaive);
    const measures::CrackFigures f = measures::measureCracks(patches, tess::Spacing::kFractionalOdd,
                                                             16, measures::CrackBackend::kCpuFloat);
    SCOPED_TRACE(triangles ? "triangles" : "quads");
    EXPECT_GT(f.points_not_equal, f.points_compared / 10);
    EXPECT_GE(f.max_gap_ulp, 1u);
    // Rounding, not a wrong formula: a few ulps of the largest coordinate (|x| < 2.5,
    // ulp 2.4e-7). Raw ulps are counted per component, so near-zero ones show more.
    EXPECT_GT(f.max_gap_world, 0.0);
    EXPECT_LT(f.max_gap_world, 8 * 2.4e-7);
    EXPECT_GT(f.max_gap_scale_ulp, 0.0);
    EXPECT_LE(f.max_gap_scale_ulp, 8.0);
    ASSERT_TRUE(f.worst.found);
    // The worst pair lies on an interior edge of the grid: t strictly inside (0, 1).
    EXPECT_FALSE(f.worst.corner);
    EXPECT_GT(f.worst.t, 0.0);
    EXPECT_LT(f.worst.t, 1.0);
  }
}

TEST(Cracks, PositionsDuplicatedAtASeamAreWeldedIntoASharedEdge) {
  // Two triangles over the same square whose shared diagonal uses distinct position
  // indices with identical coordinates (as an exporter writes a UV seam).
  const mesh::Mesh mesh = mesh::loadObjText(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 0\nv 1 1 0\nf 1 2 3\nf 5 6 4\n", "seam.obj");
  const FlatPatches patches(mesh, Order::kSymmetric);
  const measures::CrackFigures f = measures::measureCracks(patches, tess::Spacing::kInteger, 4,
                                                           measures::CrackBackend::kCpuFloat);
  EXPECT_EQ(f.shared_edges, 1u);
  EXPECT_EQ(f.seam_edges, 1u);
  EXPECT_EQ(f.shared_corners, 2u);
  EXPECT_EQ(f.points_compared, 3u + 2u);
  EXPECT_EQ(f.points_not_equal, 0u);
}

TEST(Cracks, GpuBackendIsSkippedWithAReasonWithoutAProgramOrDevice) {
  const FlatPatches triangles(gridMesh(2, true), Order::kSymmetric);
  const measures::CrackFigures no_program = measures::measureCracks(
      triangles, tess::Spacing::kInteger, 4, measures::CrackBackend::kGpu, nullptr);
  EXPECT_FALSE(no_program.measured);
  EXPECT_NE(no_program.skipped_reason.find("no GPU program"), std::string::npos);
  const FlatPatches quads(gridMesh(2, false), Order::kSymmetric);
  const measures::CrackFigures no_device = measures::measureCracks(
      quads, tess::Spacing::kInteger, 4, measures::CrackBackend::kGpu, nullptr);
  EXPECT_FALSE(no_device.measured);
  EXPECT_NE(no_device.skipped_reason.find("Vulkan"), std::string::npos);
}

TEST(Cracks, GpuCaptureMatchesTheCpuModelAndShowsTheSameCracks) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  for (Order order : {Order::kSymmetric, Order::kNaive}) {
    const FlatPatches patches(gridMesh(3, false), order);
    for (tess::Spacing spacing : kSpacings) {
      for (float level : {1.0f, 7.3f, 16.0f}) {
        SCOPED_TRACE(std::string(order == Order::kNaive ? "naive " : "symmetric ") +
                     std::string(tess::toString(spacing)) + " level " + std::to_string(level));
        const measures::CrackFigures cpu =
            measures::measureCracks(patches, spacing, level, measures::CrackBackend::kCpuFloat);
        const measures::CrackFigures gpu = measures::measureCracks(
            patches, spacing, level, measures::CrackBackend::kGpu, &context);
        ASSERT_TRUE(gpu.measured) << gpu.skipped_reason;
        // Oracle: the CPU tessellator's points on the quad's boundary (what the device
        // captures), times the patches.
        const tess::Tessellation t = tess::tessellate(
            tess::Domain::kQuad, spacing, {{level, level, level, level}, {level, level}});
        const size_t boundary_points =
            size_t(std::count_if(t.points.begin(), t.points.end(), [](const tess::DomainPoint& d) {
              return d[0] == 0 || d[0] == 1 || d[1] == 0 || d[1] == 1;
            }));
        EXPECT_EQ(gpu.device_points, boundary_points * patches.patchCount());
        EXPECT_EQ(gpu.device_points_differing, 0u);  // precise: same operations, same bits
        EXPECT_EQ(gpu.points_compared, cpu.points_compared);
        EXPECT_EQ(gpu.points_not_equal, cpu.points_not_equal);
        EXPECT_EQ(gpu.max_gap_ulp, cpu.max_gap_ulp);
        if (order == Order::kSymmetric) {
          EXPECT_EQ(gpu.points_not_equal, 0u);
        }
      }
    }
    if (order == Order::kNaive) {
      const measures::CrackFigures gpu = measures::measureCracks(
          patches, tess::Spacing::kInteger, 16, measures::CrackBackend::kGpu, &context);
      EXPECT_GT(gpu.points_not_equal, 0u);
    }
  }
}

TEST(Cracks, PhongOnTheCpuComparesEverySharedPointOfTheIcosahedron) {
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  ASSERT_NE(phong, nullptr);
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_icosahedron.obj"));
  const auto patches = techniques::buildSurface(*phong, mesh, phong->variants()[0]);
  const measures::CrackFigures f = measures::measureCracks(*patches, tess::Spacing::kInteger, 8,
                                                           measures::CrackBackend::kCpuFloat);
  // Closed icosahedron: 30 edges × 7 interior points; 12 vertices × 5 triangles.
  EXPECT_EQ(f.shared_edges, 30u);
  EXPECT_EQ(f.shared_corners, 12u);
  EXPECT_EQ(f.points_compared, 30u * 7 + 12u * 4);
  EXPECT_EQ(f.unpaired_points, 0u);
}

TEST(Cracks, PhongOnTheDeviceAgreesWithItsCpuModel) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  ASSERT_NE(phong, nullptr);
  // catmark_cube, fan-triangulated, has a normal per face corner (the two sides of a cube
  // edge project onto different planes); loop_icosahedron has shared normals.
  for (const char* asset : {"opensubdiv/catmark_cube.obj", "opensubdiv/loop_icosahedron.obj"}) {
    const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(asset));
    const auto patches = techniques::buildSurface(*phong, mesh, phong->variants()[0]);
    if (patches->gpuPrograms().empty()) GTEST_SKIP() << "phong has no GPU program on this branch";
    const measures::CrackFigures cpu = measures::measureCracks(
        *patches, tess::Spacing::kFractionalOdd, 7.3f, measures::CrackBackend::kCpuFloat);
    const measures::CrackFigures gpu = measures::measureCracks(
        *patches, tess::Spacing::kFractionalOdd, 7.3f, measures::CrackBackend::kGpu, &context);
    SCOPED_TRACE(asset);
    ASSERT_TRUE(gpu.measured) << gpu.skipped_reason;
    EXPECT_GT(gpu.device_points, 0u);
    EXPECT_EQ(gpu.device_points_differing, 0u);  // oracle: evaluateFloat, same gl_TessCoord
    EXPECT_EQ(gpu.points_compared, cpu.points_compared);
    EXPECT_EQ(gpu.points_not_equal, cpu.points_not_equal);
    EXPECT_EQ(gpu.max_gap_world, cpu.max_gap_world);
  }
}

}  // namespace
}  // namespace tb
