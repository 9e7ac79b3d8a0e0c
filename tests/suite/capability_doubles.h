// Test doubles of the two technique capabilities, registered nowhere (tests pass them to
// runSuite through SuiteSelection): a surface technique whose patch p is face p of the
// asset, flat, and a simulation technique, a 1-D chain of masses and springs. Neither is
// a real technique.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "techniques/technique.h"
#include "tests/measures/face_patches.h"

namespace tb::testing {

// Flat bilinear quads and flat triangles over the asset's faces.
class FlatFacePatches final : public FacePatches {
 public:
  explicit FlatFacePatches(const mesh::Mesh& mesh) : FacePatches(mesh) {}
  techniques::SurfacePoint evaluate(size_t patch, const techniques::DomainCoord& c) const override {
    const auto face = mesh_.facePositions(patch);
    const auto at = [&](size_t k) { return mesh_.positions[face[k]]; };
    if (patchDomain(patch) == techniques::PatchDomain::kTriangle) {
      return {c[0] * at(0) + c[1] * at(1) + c[2] * at(2), {0, 0, 0}};
    }
    const mesh::Vec3d bottom = (1 - c[0]) * at(0) + c[0] * at(1),
                      top = (1 - c[0]) * at(3) + c[0] * at(2);
    return {(1 - c[1]) * bottom + c[1] * top, {0, 0, 0}};
  }
  techniques::SurfacePointF evaluateFloat(size_t patch, const tess::DomainPoint& c) const override {
    const techniques::SurfacePoint p = evaluate(patch, {c[0], c[1], c[2]});
    return {vecCast<float>(p.position), {0, 0, 0}};
  }
};

class SurfaceDoubleTechnique final : public techniques::Technique {
 public:
  const techniques::TechniqueInfo& info() const override {
    static const techniques::TechniqueInfo kInfo{
        "test_flat_faces", techniques::TechniqueFamily::kSurface, "Flat faces (test double)",
        "none", "any polygon mesh"};
    return kInfo;
  }
  std::vector<techniques::VariantInfo> variants() const override {
    return {{"default", "flat", {}}, {"other", "the same, another name", {{"unused", 1}}}};
  }
  std::string checkSupport(const mesh::Mesh&) const override { return {}; }
  std::unique_ptr<techniques::TechniqueInstance> build(
      const techniques::TechniqueInput& input, const techniques::VariantInfo&) const override {
    return std::make_unique<techniques::SurfaceInstance>(
        std::make_unique<FlatFacePatches>(techniques::requireMesh(info(), input)));
  }
};

// A chain of `masses` point masses of 1 kg on a line, joined by springs of rest length
// 1 m and stiffness "stiffness_n_per_m"; mass 0 is fixed at x = 0, the others start
// stretched to twice the rest length. Semi-implicit (symplectic) Euler.
class SpringChain final : public techniques::Simulation {
 public:
  explicit SpringChain(const techniques::Scenario& scenario) : scenario_(scenario) {
    const size_t masses = size_t(scenario.parameters.at("masses"));
    stiffness_ = scenario.parameters.at("stiffness_n_per_m");
    for (size_t i = 0; i < masses; ++i) x_.push_back(2.0 * double(i));
    v_.assign(masses, 0.0);
  }
  const techniques::Scenario& scenario() const override { return scenario_; }
  void step(double dt_s) override {
    std::vector<double> force(x_.size(), 0.0);  // newtons
    for (size_t i = 0; i + 1 < x_.size(); ++i) {
      const double f = stiffness_ * ((x_[i + 1] - x_[i]) - kRestLengthM);
      force[i] += f;
      force[i + 1] -= f;
    }
    for (size_t i = 1; i < x_.size(); ++i) {  // mass 0 is fixed
      v_[i] += dt_s * force[i] / kMassKg;
      x_[i] += dt_s * v_[i];
    }
    time_s_ += dt_s;
  }
  techniques::SimulationState state() const override {
    techniques::SimulationState s;
    s.time_s = time_s_;
    s.element_count = x_.size();
    techniques::StateChannel position{"position", "m", 1, {}}, velocity{"velocity", "m/s", 1, {}};
    for (size_t i = 0; i < x_.size(); ++i) {
      position.values.push_back(float(x_[i]));
      velocity.values.push_back(float(v_[i]));
    }
    s.channels = {position, velocity};
    return s;
  }
  techniques::SimulationFootprint footprint() const override {
    return {x_.size() * 2 * sizeof(float), 0, 0, ""};  // position + velocity per mass, in float
  }

 private:
  static constexpr double kMassKg = 1, kRestLengthM = 1;
  techniques::Scenario scenario_;
  double stiffness_ = 0;
  double time_s_ = 0;
  std::vector<double> x_, v_;  // metres, metres per second
};

class SimulationDoubleTechnique final : public techniques::Technique {
 public:
  const techniques::TechniqueInfo& info() const override {
    static const techniques::TechniqueInfo kInfo{
        "test_spring_chain", techniques::TechniqueFamily::kSimulation,
        "1-D spring chain (test double)", "none", "a scenario with masses and stiffness_n_per_m"};
    return kInfo;
  }
  std::vector<techniques::VariantInfo> variants() const override {
    return {{"default", "Euler", {}}};
  }
  std::string checkSupport(const mesh::Mesh&) const override {
    return "test_spring_chain: takes a scenario";
  }
  std::unique_ptr<techniques::TechniqueInstance> build(
      const techniques::TechniqueInput& input, const techniques::VariantInfo&) const override {
    if (input.scenario == nullptr)
      throw techniques::UnsupportedInput("test_spring_chain: needs a scenario");
    return std::make_unique<techniques::SimulationInstance>(
        std::make_unique<SpringChain>(*input.scenario));
  }
};

inline techniques::Scenario chainScenario() {
  return {"test/chain", "", 0.01, 0.1, {{"masses", 4}, {"stiffness_n_per_m", 10}}, "", {}, ""};
}

}  // namespace tb::testing
