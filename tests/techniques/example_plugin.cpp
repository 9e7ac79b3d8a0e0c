// An out-of-tree technique built the way a plug-in is (a MODULE seeing only the plug-in
// headers), registering through TB_PLUGIN: enough to prove loading and the handshake.
// The measured example, with shaders, is examples/plugin/.
#include "techniques/plugin.h"

namespace {

class FlatTechnique final : public tb::techniques::Technique {
 public:
  const tb::techniques::TechniqueInfo& info() const override {
    static const tb::techniques::TechniqueInfo kInfo{
        "example_flat", tb::techniques::TechniqueFamily::kSurface,
        "Flat triangles (example plug-in)", "none", "triangles"};
    return kInfo;
  }
  std::vector<tb::techniques::VariantInfo> variants() const override {
    return {{"default", "flat", {}}};
  }
  std::string checkSupport(const tb::mesh::Mesh&) const override { return ""; }
  // A technique that throws while building: the suite records the error for its records and
  // completes the others (tests/cli/reliability_test.cpp).
  std::unique_ptr<tb::techniques::TechniqueInstance> build(
      const tb::techniques::TechniqueInput&, const tb::techniques::VariantInfo&) const override {
    throw std::runtime_error("example_flat: deliberately fails to build its patches");
  }
};

// Flat triangles whose GPU program names a shader the plug-in never registered: the GPU
// parts of each measure fail naming it; the CPU parts are measured.
class NoShaderPatches final : public tb::techniques::SurfacePatches {
 public:
  explicit NoShaderPatches(const tb::mesh::Mesh& mesh) : mesh_(mesh) {}
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
    const tb::mesh::Vec3d p = mesh_.positions[face[0]] * w[0] + mesh_.positions[face[1]] * w[1] +
                              mesh_.positions[face[2]] * w[2];
    return {p, {0, 0, 1}};
  }
  tb::techniques::SurfacePointF evaluateFloat(size_t patch,
                                              const tb::tess::DomainPoint& w) const override {
    const auto face = mesh_.facePositions(patch);
    auto f = [&](int i) { return tb::mesh::vecCast<float>(mesh_.positions[face[i]]); };
    return {f(0) * w[0] + f(1) * w[1] + f(2) * w[2], {0, 0, 1}};
  }
  std::vector<tb::gpu::GpuPatchProgram> gpuPrograms() const override {
    tb::gpu::GpuPatchProgram program;
    program.control_shader = "example_no_shader/missing.tesc";
    program.evaluation_shader = "example_no_shader/missing.tese";
    program.domain = tb::tess::Domain::kTriangle;
    program.patch_count = uint32_t(patchCount());
    return {program};
  }
  tb::techniques::DataFootprint footprint() const override { return {}; }
  const std::vector<std::string>& warnings() const override { return warnings_; }

 private:
  tb::mesh::Mesh mesh_;
  std::vector<std::string> warnings_;
};

class NoShaderTechnique final : public tb::techniques::Technique {
 public:
  const tb::techniques::TechniqueInfo& info() const override {
    static const tb::techniques::TechniqueInfo kInfo{
        "example_no_shader", tb::techniques::TechniqueFamily::kSurface,
        "Flat triangles naming a shader never shipped", "none", "triangle meshes"};
    return kInfo;
  }
  std::vector<tb::techniques::VariantInfo> variants() const override {
    return {{"default", "flat", {}}};
  }
  std::string checkSupport(const tb::mesh::Mesh& mesh) const override {
    return mesh.allFacesOfSize(3) ? "" : "example_no_shader: triangles only";
  }
  std::unique_ptr<tb::techniques::TechniqueInstance> build(
      const tb::techniques::TechniqueInput& input,
      const tb::techniques::VariantInfo&) const override {
    const tb::mesh::Mesh& mesh = tb::techniques::requireMesh(info(), input);
    if (std::string reason = checkSupport(mesh); !reason.empty())
      throw tb::techniques::UnsupportedInput(reason);
    return std::make_unique<tb::techniques::SurfaceInstance>(
        std::make_unique<NoShaderPatches>(mesh));
  }
};

}  // namespace

TB_PLUGIN(host) {
  host.addTechnique(std::make_unique<FlatTechnique>());
  host.addTechnique(std::make_unique<NoShaderTechnique>());
}
