#include "techniques/mass_spring/mass_spring.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "techniques/registry.h"
#include "techniques/variant_param.h"

namespace tb::mass_spring {
namespace {

// A deterministic value in [-1, 1] for (vertex, axis): splitmix64 of the pair.
double hashUnit(uint64_t v, uint64_t axis) {
  uint64_t z = v * 3 + axis + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53 * 2 - 1;
}

// The convergence frame's displacement: each coordinate off its rest value by up to this
// fraction of the mean spring length.
constexpr double kConvergenceJitter = 0.3;

mesh::Vec3f toFloat(const mesh::Vec3d& v) { return vecCast<float>(v); }
mesh::Vec3d toDouble(const mesh::Vec3f& v) { return vecCast<double>(v); }

std::vector<mesh::Vec3d> toDouble(const std::vector<mesh::Vec3f>& v) {
  std::vector<mesh::Vec3d> out(v.size());
  for (size_t i = 0; i < v.size(); ++i) out[i] = toDouble(v[i]);
  return out;
}

mesh::Vec3d boundingBoxCentre(const std::vector<mesh::Vec3d>& points) {
  if (points.empty()) return {0, 0, 0};
  mesh::Vec3d lo = points[0], hi = points[0];
  for (const mesh::Vec3d& p : points) {
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  }
  return 0.5 * (lo + hi);
}

}  // namespace

MassSpringSimulation::MassSpringSimulation(const techniques::Scenario& scenario,
                                           const SolverSettings& settings, bool goal_springs)
    : scenario_(scenario),
      input_(std::make_unique<SoftBodyInput>(parseSoftBody(scenario))),
      rig_(*input_, boundingBoxCentre(input_->skin.positions)),
      system_(buildSpringSystem(*input_, rig_, goal_springs)),
      solver_(system_, settings),
      goal_springs_(goal_springs) {
  origin_ = rig_.origin();
  for (size_t v = 0; v < system_.vertex_count; ++v) {
    rest_f_.push_back(toFloat(rig_.restPositions()[v]));
    bone_f_.push_back(toFloat(rig_.restBonePoint(v)));
    for (size_t s = 0; s < input_->stomps.size(); ++s) {
      stomp_amplitude_.push_back(toFloat(rig_.stompAmplitude(v, s)));
    }
  }
  state_.x = rest_f_;
  x_previous_ = state_.x;
  setAnchors(0, scenario.time_step_s);
  goal_previous_.resize(system_.vertex_count);
  for (size_t v = 0; v < system_.vertex_count; ++v) {
    goal_previous_[v] = toDouble(state_.anchors[system_.vertex_count + v]);
  }
  dispatches_per_step_ = input_->dispatches_per_step;
  render_mesh_ = tessellateForRendering(input_->skin, kRenderLevel, system_.length_scale_m);
}

void MassSpringSimulation::setAnchors(size_t j, double dt_s) {
  state_.anchors = anchorsAt(j, dt_s);
}

float MassSpringSimulation::stompSine(size_t s, size_t j, double dt_s) const {
  return float(
      std::sin(2 * std::numbers::pi * input_->stomps[s].frequency_hz * (double(j) * dt_s)));
}

std::vector<mesh::Vec3f> MassSpringSimulation::anchorsAt(size_t j, double dt_s) const {
  const size_t n = system_.vertex_count, stomps = input_->stomps.size();
  std::vector<float> sines(stomps);
  for (size_t s = 0; s < stomps; ++s) sines[s] = stompSine(s, j, dt_s);
  std::vector<mesh::Vec3f> anchors(system_.anchor_count);
  for (size_t v = 0; v < n; ++v) {
    mesh::Vec3f offset{0, 0, 0};
    for (size_t s = 0; s < stomps; ++s)
      offset = offset + stomp_amplitude_[v * stomps + s] * sines[s];
    anchors[v] = bone_f_[v] + offset;
    anchors[n + v] = rest_f_[v] + offset;
  }
  return anchors;
}

std::vector<mesh::Vec3f> MassSpringSimulation::convergenceStart() const {
  std::vector<mesh::Vec3f> x(system_.vertex_count);
  for (size_t v = 0; v < x.size(); ++v) {
    mesh::Vec3d p = toDouble(rest_f_[v]);
    for (int i = 0; i < 3; ++i)
      p[i] += kConvergenceJitter * system_.length_scale_m * hashUnit(v, i);
    x[v] = toFloat(p);
  }
  return x;
}

void MassSpringSimulation::step(double dt_s) {
  const size_t n = system_.vertex_count;
  const double t1 = double(steps_done_ + 1) * dt_s;
  for (size_t v = 0; v < n; ++v) goal_previous_[v] = toDouble(state_.anchors[n + v]);
  setAnchors(steps_done_ + 1, dt_s);
  // Verlet (seed 003): x' = x + (1 - damping) (x - x_prev) + g dt^2 (+ a blast's kick), in
  // the float operations of shaders/mass_spring/verlet.comp.
  const float keep = float(1 - input_->damping);
  const mesh::Vec3f gravity_step = toFloat((dt_s * dt_s) * input_->gravity_m_per_s2);
  const float dt = float(dt_s);
  std::vector<mesh::Vec3f> kick(n, mesh::Vec3f{0, 0, 0});
  for (const Blast& blast : input_->blasts) {
    // A blast fires on the first step that reaches its time.
    if (!(t1 >= blast.time_s) || (steps_done_ > 0 && double(steps_done_) * dt_s >= blast.time_s)) {
      continue;
    }
    const mesh::Vec3f centre = toFloat(blast.center_m - origin_);
    const float radius = float(blast.radius_m), speed0 = float(blast.speed_m_per_s);
    for (size_t v = 0; v < n; ++v) {
      const mesh::Vec3f away = state_.x[v] - centre;
      const float distance = std::sqrt(away.x * away.x + away.y * away.y + away.z * away.z);
      if (!(distance < radius) || !(distance > 0.0f)) continue;
      const float speed = speed0 * (1.0f - distance / radius);
      kick[v] = kick[v] + away * ((speed * dt) / distance);
    }
  }
  for (size_t v = 0; v < n; ++v) {
    const mesh::Vec3f x = state_.x[v], p = x_previous_[v];
    const mesh::Vec3f next{x.x + keep * (x.x - p.x) + gravity_step.x + kick[v].x,
                           x.y + keep * (x.y - p.y) + gravity_step.y + kick[v].y,
                           x.z + keep * (x.z - p.z) + gravity_step.z + kick[v].z};
    x_previous_[v] = x;
    state_.x[v] = next;
  }
  state_.iteration = 0;
  state_.previous.clear();
  solver_.iterateDispatches(state_, dispatches_per_step_);
  time_s_ = t1;
  last_dt_s_ = dt_s;
  ++steps_done_;
}

techniques::SimulationState MassSpringSimulation::state() const {
  techniques::SimulationState s;
  s.time_s = time_s_;
  s.element_count = system_.vertex_count;
  techniques::StateChannel position{"position", "m", 3, {}}, velocity{"velocity", "m/s", 3, {}};
  for (size_t v = 0; v < system_.vertex_count; ++v) {
    const mesh::Vec3d x = toDouble(state_.x[v]) + origin_;
    const mesh::Vec3f dx{state_.x[v].x - x_previous_[v].x, state_.x[v].y - x_previous_[v].y,
                         state_.x[v].z - x_previous_[v].z};
    const double inv_dt = last_dt_s_ > 0 ? 1 / last_dt_s_ : 0;
    for (int i = 0; i < 3; ++i) {
      position.values.push_back(float(x[i]));
      velocity.values.push_back(float(double(dx[i]) * inv_dt));
    }
  }
  s.channels = {std::move(position), std::move(velocity)};
  return s;
}

techniques::SolverCounts MassSpringSimulation::counts() const {
  techniques::SolverCounts c;
  const SolverKind kind = solver_.settings().kind;
  const bool gauss_seidel =
      kind == SolverKind::kGaussSeidelSerial || kind == SolverKind::kGaussSeidelColoured;
  c.dispatches_per_iteration = gauss_seidel ? system_.colour_count : 1;
  c.colours = gauss_seidel ? system_.colour_count : 0;
  c.constraints = system_.springs.size();
  c.vertices = system_.vertex_count;
  c.constraint_ends = system_.ends.size();
  if (kind == SolverKind::kJacobi || kind == SolverKind::kJacobiChebyshev) {
    // Gather reads of a neighbour in the same 64-vertex tile (shared memory when tiled).
    uint64_t vertex_ends = 0, in_tile = 0;
    for (size_t v = 0; v < system_.vertex_count; ++v) {
      for (uint32_t e = system_.end_start[v]; e < system_.end_start[v + 1]; ++e) {
        const uint32_t o = system_.ends[e].other;
        if (o & kAnchorBit) continue;
        ++vertex_ends;
        if (o / 64 == v / 64) ++in_tile;
      }
    }
    c.tile_local_fraction = vertex_ends ? double(in_tile) / double(vertex_ends) : 0;
  }
  c.colours_surface = colourCountOf(system_, {SpringKind::kSurface});
  c.colours_surface_goal = colourCountOf(system_, {SpringKind::kSurface, SpringKind::kGoal});
  c.whole_iterations_under_budget =
      kind == SolverKind::kGaussSeidelSerial && !solver_.settings().colour_major;
  return c;
}

void MassSpringSimulation::setConvergenceFrame() {
  setAnchors(0, scenario_.time_step_s);  // the stomp's offset is 0 at t = 0: the rest pose
  state_.x = convergenceStart();
  x_previous_ = state_.x;
  state_.iteration = 0;
  state_.previous.clear();
  state_.chebyshev_weight = 1;
  state_.sweep_cursor = 0;
}

void MassSpringSimulation::iterate(size_t iterations) { solver_.iterate(state_, iterations); }

double MassSpringSimulation::residual() const {
  return measureStretch(system_, toDouble(state_.x), toDouble(state_.anchors)).rms;
}

std::vector<mesh::Vec3d> MassSpringSimulation::positions() const {
  std::vector<mesh::Vec3d> out = toDouble(state_.x);
  for (mesh::Vec3d& x : out) x = x + origin_;
  return out;
}

techniques::ReferenceSolution MassSpringSimulation::referenceSolution(double relative_tolerance,
                                                                      size_t max_iterations) const {
  // The same start as setConvergenceFrame (the float values, widened), solved in double.
  SolverState<double> state;
  state.x = toDouble(convergenceStart());
  state.anchors = toDouble(anchorsAt(0, scenario_.time_step_s));
  const SpringSolver<double> solver(system_, SolverSettings{});
  const double r0 = measureStretch(system_, state.x, state.anchors).rms;
  techniques::ReferenceSolution reference;
  double r = r0;
  while (r0 > 0 && reference.iterations < max_iterations && r / r0 > relative_tolerance) {
    solver.iterate(state, 1);
    ++reference.iterations;
    r = measureStretch(system_, state.x, state.anchors).rms;
  }
  reference.relative_residual = r0 > 0 ? r / r0 : 0;
  reference.converged = reference.relative_residual <= relative_tolerance;
  reference.positions = state.x;
  for (mesh::Vec3d& x : reference.positions) x = x + origin_;
  return reference;
}

techniques::StepDiagnostics MassSpringSimulation::diagnostics() const {
  techniques::StepDiagnostics d;
  const size_t n = system_.vertex_count;
  const std::vector<mesh::Vec3d> x = toDouble(state_.x);
  double energy = 0;
  for (size_t v = 0; v < n; ++v) {
    if (!std::isfinite(x[v].x) || !std::isfinite(x[v].y) || !std::isfinite(x[v].z))
      d.finite = false;
    if (last_dt_s_ > 0) {
      const mesh::Vec3d velocity = (1 / last_dt_s_) * (x[v] - toDouble(x_previous_[v]));
      const mesh::Vec3d goal_velocity =
          (1 / last_dt_s_) * (toDouble(state_.anchors[n + v]) - goal_previous_[v]);
      const mesh::Vec3d relative = velocity - goal_velocity;
      energy += 0.5 * dot(relative, relative);
    }
  }
  d.relative_kinetic_energy = n ? energy / double(n) : 0;
  const StretchFigures stretch = measureStretch(system_, x, toDouble(state_.anchors), true);
  d.max_stretch = stretch.max_abs;
  d.rms_stretch = stretch.rms;
  if (!std::isfinite(stretch.rms)) d.finite = false;
  return d;
}

std::vector<mesh::Vec3f> MassSpringSimulation::renderPositionsFloat() const {
  std::vector<mesh::Vec3f> out;
  out.reserve(render_mesh_.bindings.size());
  for (const TetBinding& binding : render_mesh_.bindings) {
    out.push_back(drawVertexFloat(binding, state_.x));
  }
  return out;
}

std::vector<mesh::Vec3d> MassSpringSimulation::renderPositions() const {
  const std::vector<mesh::Vec3d> x = positions();
  std::vector<mesh::Vec3d> out;
  out.reserve(render_mesh_.bindings.size());
  for (const TetBinding& binding : render_mesh_.bindings) out.push_back(drawVertex(binding, x));
  return out;
}

// ---------------------------------------------------------------------------------------

SolverSettings settingsOf(const techniques::TechniqueInfo& info,
                          const techniques::VariantInfo& variant) {
  SolverSettings settings;
  if (variant.name.rfind("gs_serial", 0) == 0) {
    settings.kind = SolverKind::kGaussSeidelSerial;
  } else if (variant.name == "gs_colored") {
    settings.kind = SolverKind::kGaussSeidelColoured;
  } else if (variant.name.rfind("jacobi_chebyshev", 0) == 0) {
    settings.kind = SolverKind::kJacobiChebyshev;
  } else if (variant.name.rfind("jacobi", 0) == 0) {
    settings.kind = SolverKind::kJacobi;
  } else {
    throw techniques::UnsupportedInput(info.id + ": unknown variant \"" + variant.name + "\"");
  }
  settings.colour_major = techniques::paramOr<bool>(info, variant, "colour_major", false);
  settings.omega = techniques::paramOr<double>(info, variant, "omega", 1.0);
  settings.rho = techniques::paramOr<double>(info, variant, "rho", settings.rho);
  settings.delay = techniques::paramOr<size_t>(info, variant, "delay", settings.delay);
  settings.tiled = techniques::paramOr<bool>(info, variant, "tiled", settings.tiled);
  if (!(settings.omega > 0 && settings.omega < 2)) {
    throw techniques::UnsupportedInput(info.id + "/" + variant.name + ": omega must be in (0, 2)");
  }
  if (!(settings.rho > 0 && settings.rho < 1)) {
    throw techniques::UnsupportedInput(info.id + "/" + variant.name + ": rho must be in (0, 1)");
  }
  return settings;
}

const techniques::TechniqueInfo& MassSpringTechnique::info() const {
  static const techniques::TechniqueInfo kInfo{
      "mass_spring", techniques::TechniqueFamily::kSimulation,
      "Mass-spring soft body (Verlet, position-based)",
      "CAPCOM, Lost Planet 2 DirectX 11 talk (soft-body boss skin); Wang, SIGGRAPH Asia 2015",
      "a mass_spring scenario: a skin mesh, a bone chain and its animation"};
  return kInfo;
}

std::vector<techniques::VariantInfo> MassSpringTechnique::variants() const {
  return {
      {"gs_serial", "Gauss-Seidel, one spring at a time in index order (the reference order)", {}},
      {"gs_colored",
       "Gauss-Seidel by independent batches from a greedy graph colouring (one dispatch per "
       "colour)",
       {}},
      {"jacobi",
       "Jacobi: each vertex averages its springs' corrections (one dispatch per iteration)",
       {{"omega", 1.0}}},
      {"jacobi_chebyshev",
       "Jacobi with Chebyshev semi-iterative acceleration (Wang, SIGGRAPH Asia 2015)",
       {{"omega", 1.0}, {"rho", 0.97}, {"delay", 4}}},
  };
}

std::string MassSpringTechnique::checkSupport(const mesh::Mesh&) const {
  return "mass_spring: runs on mass_spring scenarios, not on mesh assets";
}

std::unique_ptr<techniques::TechniqueInstance> MassSpringTechnique::build(
    const techniques::TechniqueInput& input, const techniques::VariantInfo& variant) const {
  if (input.scenario == nullptr) {
    throw techniques::UnsupportedInput("mass_spring: needs a mass_spring scenario as input");
  }
  const SolverSettings settings = settingsOf(info(), variant);
  const bool goal_springs = techniques::paramOr<bool>(info(), variant, "goal_springs", true);
  return std::make_unique<techniques::SimulationInstance>(
      std::make_unique<MassSpringSimulation>(*input.scenario, settings, goal_springs));
}

TB_REGISTER_TECHNIQUE(MassSpringTechnique);

}  // namespace tb::mass_spring
