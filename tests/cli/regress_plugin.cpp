// `regress`: the plain triangle mesh (each triangle a patch, linear interpolation), built
// twice from this one source as a plug-in (tests/cli/CMakeLists.txt): libregress_good.so as
// it is, and libregress_broken.so with TB_REGRESS_BROKEN, whose patches are lifted off the
// mesh by a patch-dependent offset, so neighbours no longer meet (cracks) and the surface
// moves away from the limit (error). The acceptance tests of `tessbench compare`
// (compare_acceptance_test.cpp) run one against the other, as a change that broke a
// technique would be run against the baseline. CPU only: no GPU program.
//
// Both builds also register `regress_flaky`, whose surface drifts with every evaluation (a
// measure on it gives another figure each time it runs): what `run --repetitions` must warn of.
#include <atomic>

#include "techniques/plugin.h"

namespace {

#ifdef TB_REGRESS_BROKEN
// World units along z, by patch: 0 on every third patch, so shared edges split.
double liftOf(size_t patch) { return 0.02 * double(patch % 3); }
#else
double liftOf(size_t) { return 0; }
#endif

class RegressPatches final : public tb::techniques::SurfacePatches {
 public:
  RegressPatches(const tb::mesh::Mesh& mesh, bool flaky) : mesh_(mesh), flaky_(flaky) {}
  tb::techniques::PatchDomain patchDomain(size_t) const override {
    return tb::techniques::PatchDomain::kTriangle;
  }
  size_t patchCount() const override { return mesh_.faceCount(); }
  const tb::mesh::Mesh& controlMesh() const override { return mesh_; }
  std::array<uint32_t, 4> patchCorners(size_t patch) const override {
    const auto face = mesh_.facePositions(patch);
    return {face[0], face[1], face[2], UINT32_MAX};
  }
  uint32_t sourceFace(size_t patch) const override { return uint32_t(patch); }
  tb::techniques::SurfacePoint evaluate(size_t patch,
                                        const tb::techniques::DomainCoord& w) const override {
    const auto face = mesh_.facePositions(patch);
    const tb::mesh::Vec3d& a = mesh_.positions[face[0]];
    const tb::mesh::Vec3d& b = mesh_.positions[face[1]];
    const tb::mesh::Vec3d& c = mesh_.positions[face[2]];
    const tb::mesh::Vec3d p =
        a * w[0] + b * w[1] + c * w[2] + tb::mesh::Vec3d{0, 0, liftOf(patch) + drift()};
    return {p, tb::mesh::normalize(tb::mesh::cross(b - a, c - a))};
  }
  tb::techniques::SurfacePointF evaluateFloat(size_t patch,
                                              const tb::tess::DomainPoint& w) const override {
    const auto face = mesh_.facePositions(patch);
    auto f = [&](int i) { return tb::mesh::vecCast<float>(mesh_.positions[face[i]]); };
    const tb::mesh::Vec3f lift{0, 0, float(liftOf(patch) + drift())};
    const tb::mesh::Vec3f a = f(0), b = f(1), c = f(2);
    return {a * w[0] + b * w[1] + c * w[2] + lift,
            tb::mesh::normalize(tb::mesh::cross(b - a, c - a))};
  }
  tb::techniques::DataFootprint footprint() const override { return {}; }
  const std::vector<std::string>& warnings() const override { return warnings_; }

 private:
  // 0 unless flaky; then 1e-4 world units times an ever-growing count of evaluations.
  double drift() const { return flaky_ ? 1e-4 * double(evaluations_++ % 1000) : 0.0; }

  tb::mesh::Mesh mesh_;
  bool flaky_;
  mutable std::atomic<uint64_t> evaluations_{0};
  std::vector<std::string> warnings_;
};

class RegressTechnique final : public tb::techniques::Technique {
 public:
  explicit RegressTechnique(bool flaky)
      : flaky_(flaky),
        info_{flaky ? "regress_flaky" : "regress", tb::techniques::TechniqueFamily::kSurface,
              "Flat triangles (compare's acceptance tests)", "none", "triangle meshes"} {}
  const tb::techniques::TechniqueInfo& info() const override { return info_; }
  std::vector<tb::techniques::VariantInfo> variants() const override {
    return {{"default", "flat", {}}};
  }
  std::string checkSupport(const tb::mesh::Mesh& mesh) const override {
    return mesh.allFacesOfSize(3) ? "" : "regress: triangles only";
  }
  std::unique_ptr<tb::techniques::TechniqueInstance> build(
      const tb::techniques::TechniqueInput& input,
      const tb::techniques::VariantInfo&) const override {
    const tb::mesh::Mesh& mesh = tb::techniques::requireMesh(info(), input);
    if (std::string reason = checkSupport(mesh); !reason.empty())
      throw tb::techniques::UnsupportedInput(reason);
    return std::make_unique<tb::techniques::SurfaceInstance>(
        std::make_unique<RegressPatches>(mesh, flaky_));
  }

 private:
  bool flaky_;
  tb::techniques::TechniqueInfo info_;
};

}  // namespace

TB_PLUGIN(host) {
  host.addTechnique(std::make_unique<RegressTechnique>(false));
  host.addTechnique(std::make_unique<RegressTechnique>(true));
}
