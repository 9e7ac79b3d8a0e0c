// Issue 19, acceptance 1 and 2: the projection against hand computations and the analytic
// rest state (double), and the graph-coloured Gauss-Seidel against the serial one.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstring>

#include "core/mesh/input_error.h"
#include "techniques/mass_spring/spring_solvers.h"
#include "tests/techniques/mass_spring_test_support.h"

namespace tb::mass_spring {
namespace {

using tb::testing::buildMassSpring;
using tb::testing::massSpringOf;
using tb::testing::massSpringScenario;

constexpr SolverKind kAllSolvers[] = {SolverKind::kGaussSeidelSerial,
                                      SolverKind::kGaussSeidelColoured, SolverKind::kJacobi,
                                      SolverKind::kJacobiChebyshev};

SpringSystem twoParticles(double stiffness) {
  SpringSystem system;
  system.vertex_count = 2;
  system.springs.push_back({0, 1, 1.0, 0.5 * stiffness, SpringKind::kSurface});
  buildSolverTables(system);
  return system;
}

// Oracle: by hand. x0 = (0,0,0), x1 = (2,0,0), rest 1: d = (2,0,0), |d| = 2,
// f = (stiffness / 2) (2 - 1) / 2 = stiffness / 4, x0 += f d, x1 -= f d.
TEST(MassSpringSolver, TwoParticleSpringMatchesHandComputationAfterOneProjection) {
  for (const double stiffness : {1.0, 0.5}) {
    const SpringSystem system = twoParticles(stiffness);
    for (const SolverKind kind : kAllSolvers) {
      SolverState<double> state;
      state.x = {{0, 0, 0}, {2, 0, 0}};
      SpringSolver<double>(system, {.kind = kind}).iterate(state, 1);
      const double moved = 2 * stiffness / 4;  // f |d|
      EXPECT_DOUBLE_EQ(state.x[0].x, moved) << int(kind) << " stiffness " << stiffness;
      EXPECT_DOUBLE_EQ(state.x[1].x, 2 - moved) << int(kind);
      EXPECT_EQ(state.x[0].y, 0.0);
      EXPECT_EQ(state.x[1].z, 0.0);
    }
  }
}

// A chain hanging from an anchor at the origin: anchor - x0 - x1 - x2, rest 1, stiffness 1.
SpringSystem chain() {
  SpringSystem system;
  system.vertex_count = 3;
  system.anchor_count = 1;
  system.springs.push_back({0, kAnchorBit | 0, 1.0, 1.0, SpringKind::kInner});
  system.springs.push_back({0, 1, 1.0, 0.5, SpringKind::kSurface});
  system.springs.push_back({1, 2, 1.0, 0.5, SpringKind::kSurface});
  system.length_scale_m = 1;
  buildSolverTables(system);
  return system;
}

// Oracle: by hand, the chain stretched along x to 1.5, 3, 4.5 and one sweep in index order:
// anchor spring: x0 = 1.5 - 0.5 = 1; spring (0,1): d = 2, f = 0.25: x0 = 1.5, x1 = 2.5;
// spring (1,2): d = 2, f = 0.25: x1 = 3, x2 = 4.
TEST(MassSpringSolver, HangingChainMatchesHandComputationAfterOneSweep) {
  const SpringSystem system = chain();
  SolverState<double> state;
  state.x = {{1.5, 0, 0}, {3, 0, 0}, {4.5, 0, 0}};
  state.anchors = {{0, 0, 0}};
  SpringSolver<double>(system, {}).iterate(state, 1);
  EXPECT_DOUBLE_EQ(state.x[0].x, 1.5);
  EXPECT_DOUBLE_EQ(state.x[1].x, 3.0);
  EXPECT_DOUBLE_EQ(state.x[2].x, 4.0);
  // Jacobi from the same start, by hand: vertex 0 has 2 ends: anchor (d = -1.5, f = 1/3:
  // -0.5) and (0,1) (d = 1.5, f = 0.5 * 0.5 / 1.5: +0.25), averaged: (-0.25) / 2; vertex 1:
  // -0.25 + 0.25 = 0; vertex 2: one end, -0.25.
  SolverState<double> jacobi;
  jacobi.x = {{1.5, 0, 0}, {3, 0, 0}, {4.5, 0, 0}};
  jacobi.anchors = {{0, 0, 0}};
  SpringSolver<double>(system, {.kind = SolverKind::kJacobi}).iterate(jacobi, 1);
  EXPECT_DOUBLE_EQ(jacobi.x[0].x, 1.5 - 0.125);
  EXPECT_DOUBLE_EQ(jacobi.x[1].x, 3.0);
  EXPECT_DOUBLE_EQ(jacobi.x[2].x, 4.5 - 0.25);
}

// Oracle: the analytic rest state, the chain hanging straight down with every link at its
// rest length: x_i = (0, 0, -(i + 1)). Verlet with gravity and damping from the stretched
// horizontal start until it settles, each solver.
TEST(MassSpringSolver, HangingChainSettlesToTheAnalyticRestState) {
  const SpringSystem system = chain();
  const double dt = 0.01, damping = 0.05;
  const mesh::Vec3d gravity{0, 0, -9.81};
  for (const SolverKind kind : kAllSolvers) {
    const SpringSolver<double> solver(system, {.kind = kind, .rho = 0.5, .delay = 2});
    SolverState<double> state;
    state.x = {{1.5, 0, 0}, {3, 0, 0}, {4.5, 0, 0}};
    state.anchors = {{0, 0, 0}};
    std::vector<mesh::Vec3d> previous = state.x;
    for (int step = 0; step < 4000; ++step) {
      for (size_t v = 0; v < 3; ++v) {
        const mesh::Vec3d next =
            state.x[v] + (1 - damping) * (state.x[v] - previous[v]) + dt * dt * gravity;
        previous[v] = state.x[v];
        state.x[v] = next;
      }
      state.iteration = 0;
      state.previous.clear();
      solver.iterate(state, 200);
    }
    for (size_t i = 0; i < 3; ++i) {
      EXPECT_NEAR(state.x[i].x, 0.0, 1e-6) << int(kind) << " vertex " << i;
      EXPECT_NEAR(state.x[i].y, 0.0, 1e-6) << int(kind);
      EXPECT_NEAR(state.x[i].z, -double(i + 1), 1e-6) << int(kind) << " vertex " << i;
    }
  }
}

TEST(MassSpringColouring, NoBatchHoldsTwoSpringsSharingAVertex) {
  for (const bool goal : {true, false}) {
    auto instance = buildMassSpring(massSpringScenario(), "gs_colored", {{"goal_springs", goal}});
    const SpringSystem& system = massSpringOf(*instance).springs();
    const ColourConflict conflict = findColourConflict(system);
    EXPECT_EQ(conflict.first, -1) << "springs " << conflict.first << " and " << conflict.second;
    EXPECT_GE(system.colour_count, 4u);  // a quad mesh's vertices have 4 edges
    EXPECT_EQ(system.colour_order.size(), system.springs.size());
    // The check can fail: move a spring into the colour of a neighbour.
    SpringSystem broken = system;
    const uint32_t s0 = broken.colour_order[broken.colour_start[0]];
    for (uint32_t c = 1; c < broken.colour_count; ++c) {
      bool moved = false;
      for (uint32_t i = broken.colour_start[c]; i < broken.colour_start[c + 1]; ++i) {
        const Spring& a = broken.springs[s0];
        const Spring& b = broken.springs[broken.colour_order[i]];
        if (b.a == a.a || b.b == a.a || (!a.anchored() && (b.a == a.b || b.b == a.b))) {
          std::swap(broken.colour_order[broken.colour_start[0] + 1], broken.colour_order[i]);
          moved = true;
          break;
        }
      }
      if (moved) break;
    }
    EXPECT_NE(findColourConflict(broken).first, -1);
  }
}

std::vector<mesh::Vec3f> solveFromConvergenceFrame(const std::string& variant,
                                                   const std::map<std::string, double>& extra,
                                                   size_t iterations) {
  auto instance = buildMassSpring(massSpringScenario(), variant, extra);
  MassSpringSimulation& simulation = massSpringOf(*instance);
  simulation.setConvergenceFrame();
  simulation.iterate(iterations);
  return simulation.solverState().x;
}

bool bitwiseEqual(const std::vector<mesh::Vec3f>& a, const std::vector<mesh::Vec3f>& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(mesh::Vec3f)) == 0;
}

// Oracle: the serial sweep in colour-major order (amendment to acceptance 2: bitwise),
// whatever the thread count.
TEST(MassSpringColouring, ColouredGaussSeidelEqualsSerialColourMajorBitwise) {
  for (const bool goal : {true, false}) {
    const std::map<std::string, double> extra{{"goal_springs", goal}};
    const auto serial =
        solveFromConvergenceFrame("gs_serial", {{"goal_springs", goal}, {"colour_major", 1}}, 20);
    std::vector<mesh::Vec3f> coloured;
    {
      tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
      coloured = solveFromConvergenceFrame("gs_colored", extra, 20);
    }
    EXPECT_TRUE(bitwiseEqual(serial, coloured)) << "goal_springs " << goal;
    EXPECT_TRUE(bitwiseEqual(serial, solveFromConvergenceFrame("gs_colored", extra, 20)));
    // The order matters: the index-order sweep is a different float computation.
    EXPECT_FALSE(bitwiseEqual(serial, solveFromConvergenceFrame("gs_serial", extra, 20)));
  }
}

// Oracle: whole sweeps. A budget of 8 dispatches cuts a sweep of more colours; the next
// budget goes on where it stopped, so two budgets that add up to the colour count are one
// sweep, bitwise.
TEST(MassSpringColouring, ADispatchBudgetGoesOnWhereTheLastStopped) {
  for (const char* variant : {"gs_colored", "gs_serial"}) {
    auto whole = buildMassSpring(massSpringScenario(), variant, {{"colour_major", 1}});
    auto cut = buildMassSpring(massSpringScenario(), variant, {{"colour_major", 1}});
    MassSpringSimulation& a = massSpringOf(*whole);
    MassSpringSimulation& b = massSpringOf(*cut);
    const uint32_t colours = a.springs().colour_count;
    ASSERT_GT(colours, 8u);
    a.setConvergenceFrame();
    b.setConvergenceFrame();
    a.iterate(2);
    b.iterateDispatches(8);
    EXPECT_FALSE(bitwiseEqual(a.solverState().x, b.solverState().x));
    b.iterateDispatches(colours - 8);
    b.iterateDispatches(colours);
    EXPECT_TRUE(bitwiseEqual(a.solverState().x, b.solverState().x)) << variant;
  }
}

TEST(MassSpringScenario, BadFieldsNameTheFileAndTheField) {
  techniques::Scenario scenario = massSpringScenario();
  scenario.path = "stomp.json";
  scenario.sections["mass_spring"] =
      R"({"bone_chain_m": [[0,0,0],[0,0,1]], "stiffness": {"surface": 1.5, "inner": 0, "goal": 0}})";
  try {
    buildMassSpring(scenario, "jacobi");
    FAIL() << "no InputError";
  } catch (const mesh::InputError& error) {
    EXPECT_EQ(error.file(), "stomp.json");
    EXPECT_EQ(error.element(), "mass_spring.stiffness.surface");
  }
  scenario.sections["mass_spring"] = R"({"bone_chain_m": [[0,0,0]]})";
  EXPECT_THROW(buildMassSpring(scenario, "jacobi"), mesh::InputError);
  scenario.sections.clear();
  EXPECT_THROW(buildMassSpring(scenario, "jacobi"), mesh::InputError);
}

}  // namespace
}  // namespace tb::mass_spring
