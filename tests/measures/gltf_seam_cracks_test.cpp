// Issue 60's seams: the bundled glTF asset (assets/full_suite/gltf/tri_torus_seams.glb, vertices
// split at UV seams with normals computed after splitting) and its OBJ twin crack at the seams
// alike: PN triangles without a crack fix opens every seam, the crack-fixed variants (geometry
// normals, PN-AEN) close them, and no variant cracks away from a seam.
// Oracle: bitwise equality of the two sides' CPU float positions at mirrored domain points,
// counted per edge kind (crack_seams.h); the twin's counts, which must equal the glb's.
#include <gtest/gtest.h>

#include <cstdio>

#include "harness/measures/common/cracks/cracks.h"
#include "tests/measures/bundled_surfaces.h"

namespace tb {
namespace {

constexpr const char* kSeamGlb = "full_suite/gltf/tri_torus_seams.glb";
constexpr const char* kSeamTwin = "full_suite/gltf/tri_torus_seams_twin.obj";

struct SeamCounts {
  uint64_t seam_edges = 0, seam_points = 0, seam_not_equal = 0, interior_not_equal = 0,
           all_not_equal = 0;
};

SeamCounts seamCountsOf(const std::string& variant, const std::string& asset) {
  const techniques::BuiltSurface surface = testing::builtSurface("pn_triangles", variant, asset);
  measures::CrackSession session(*surface);
  EXPECT_TRUE(session.hasSeams()) << asset;
  SeamCounts counts;
  for (float level : {1.0f, 7.3f, 16.0f}) {
    const auto cpu = measures::CrackBackend::kCpuFloat;
    const auto all = session.measure(tess::Spacing::kInteger, level, cpu);
    const auto seam =
        session.measure(tess::Spacing::kInteger, level, cpu, nullptr, measures::EdgeKind::kSeam);
    const auto interior = session.measure(tess::Spacing::kInteger, level, cpu, nullptr,
                                          measures::EdgeKind::kInterior);
    const auto boundary = session.measure(tess::Spacing::kInteger, level, cpu, nullptr,
                                          measures::EdgeKind::kBoundary);
    counts.seam_edges = seam.shared_edges;
    counts.seam_points += seam.points_compared;
    counts.seam_not_equal += seam.points_not_equal;
    counts.interior_not_equal += interior.points_not_equal;
    counts.all_not_equal += all.points_not_equal;
    // The kinds partition the pairs.
    EXPECT_EQ(seam.points_compared + interior.points_compared + boundary.points_compared,
              all.points_compared);
    EXPECT_EQ(seam.shared_edges + interior.shared_edges, all.shared_edges);
  }
  return counts;
}

TEST(GltfSeamCracks, PnCracksAtTheSeamsAndTheFixesCloseThem) {
  for (const char* variant : {"pn", "geometry_normals", "aen", "boundary_flags", "rounding"}) {
    const SeamCounts glb = seamCountsOf(variant, kSeamGlb);
    const SeamCounts twin = seamCountsOf(variant, kSeamTwin);
    std::printf(
        "pn_triangles/%s: %llu seam edges, seam points %llu, not equal %llu at seams, %llu "
        "elsewhere\n",
        variant, (unsigned long long)glb.seam_edges, (unsigned long long)glb.seam_points,
        (unsigned long long)glb.seam_not_equal, (unsigned long long)glb.interior_not_equal);
    EXPECT_EQ(glb.seam_edges, 12u) << "4 edges across the tube, 8 around the ring";
    EXPECT_EQ(glb.seam_not_equal, twin.seam_not_equal) << variant;
    EXPECT_EQ(glb.seam_points, twin.seam_points) << variant;
    EXPECT_EQ(glb.interior_not_equal, 0u) << variant << ": no crack away from a seam";
    EXPECT_EQ(glb.all_not_equal, glb.seam_not_equal) << variant;
    if (std::string(variant) == "pn") {
      EXPECT_GT(glb.seam_not_equal, 0u) << "the control: split normals open the seams";
    } else {
      EXPECT_EQ(glb.seam_not_equal, 0u) << variant << " fixes the cracks";
    }
  }
}

// Control for the kinds: tri_torus (smooth normals computed at load, no UVs) has no seam.
TEST(GltfSeamCracks, AMeshWithoutSeamsHasNone) {
  const techniques::BuiltSurface surface =
      testing::builtSurface("pn_triangles", "pn", "tessbench/tri_torus.obj");
  EXPECT_FALSE(measures::CrackSession(*surface).hasSeams());
}

}  // namespace
}  // namespace tb
