// gregory_acc's control points against an independent construction of the same paper:
// OpenSubdiv Far's Gregory-basis end caps (PatchTableFactory, ENDCAP_GREGORY_BASIS) at
// isolation level 0, where every irregular base face becomes one 20-point Gregory patch.
#include <gtest/gtest.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/stencilTable.h>

#include "core/mesh/obj_loader.h"
#include "core/osd/topology_refiner_builder.h"
#include "techniques/gregory_acc/gregory_stencils.h"
#include "tests/test_support.h"

namespace tb::gregory_acc {
namespace {

namespace Far = OpenSubdiv::Far;

struct Point3 {
  double p[3] = {0, 0, 0};
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0; }
  void AddWithWeight(const Point3& src, float weight) {
    for (int k = 0; k < 3; ++k) p[k] += double(weight) * src.p[k];
  }
};

mesh::Vec3d stencilValue(const GregoryStencils& stencils, uint32_t s, const mesh::Mesh& mesh) {
  mesh::Vec3d sum{};
  for (uint32_t k = stencils.offsets[s]; k < stencils.offsets[s + 1]; ++k) {
    sum = sum + mesh.positions[stencils.indices[k]] * stencils.weights[k];
  }
  return sum;
}

TEST(GregoryAccOsd, IrregularFacesMatchFarGregoryBasisEndCaps) {
  size_t compared_patches = 0;
  for (const char* name :
       {"opensubdiv/catmark_cube.obj", "opensubdiv/catmark_toroidal_tet.obj",
        "opensubdiv/catmark_quadstrips.obj", "opensubdiv/catmark_xord_interior.obj",
        "opensubdiv/catmark_edgecorner.obj"}) {
    const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(name));
    const GregoryStencils stencils = buildGregoryStencils(mesh, TangentMask::kPaper);
    auto refiner = osd::buildTopologyRefiner(mesh, osd::Scheme::kCatmullClark);
    refiner->RefineAdaptive(Far::TopologyRefiner::AdaptiveOptions(0));
    Far::PatchTableFactory::Options options(0);
    options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    std::unique_ptr<Far::PatchTable> table(Far::PatchTableFactory::Create(*refiner, options));
    ASSERT_NE(table, nullptr);
    const int vertex_count = refiner->GetLevel(0).GetNumVertices();
    std::vector<Point3> points(vertex_count);
    for (int v = 0; v < vertex_count; ++v) {
      for (int k = 0; k < 3; ++k) points[v].p[k] = mesh.positions[v][k];
    }
    // The templated accessor: the untemplated one downcasts to StencilTable, which UBSan
    // flags (the object is a StencilTableReal<float>).
    const Far::StencilTableReal<float>* local = table->GetLocalPointStencilTable<float>();
    if (local == nullptr) continue;  // no irregular face (catmark_edgecorner)
    std::vector<Point3> local_points(local->GetNumStencils());
    local->UpdateValues(points.data(), local_points.data());
    const double diagonal = 4.0;
    for (int array = 0; array < table->GetNumPatchArrays(); ++array) {
      if (table->GetPatchArrayDescriptor(array).GetType() != Far::PatchDescriptor::GREGORY_BASIS) {
        continue;
      }
      for (int patch = 0; patch < table->GetNumPatches(array); ++patch) {
        const Far::ConstIndexArray cvs = table->GetPatchVertices(array, patch);
        const int face = table->GetPatchParam(array, patch).GetFaceId();
        ASSERT_EQ(cvs.size(), 20);
        ++compared_patches;
        for (int i = 0; i < 20; ++i) {
          const Point3& expected =
              cvs[i] < vertex_count ? points[cvs[i]] : local_points[cvs[i] - vertex_count];
          const mesh::Vec3d got = stencilValue(stencils, stencils.patch_points[face][i], mesh);
          const mesh::Vec3d want{expected.p[0], expected.p[1], expected.p[2]};
          EXPECT_LE(length(got - want), 1e-5 * diagonal)
              << name << " face " << face << " point " << i;
        }
      }
    }
  }
  RecordProperty("compared_patches", int(compared_patches));
  EXPECT_GE(compared_patches, 6u + 24u);
}

}  // namespace
}  // namespace tb::gregory_acc
