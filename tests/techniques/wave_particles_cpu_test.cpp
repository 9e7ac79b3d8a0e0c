// Wave particles on the CPU against independent oracles: the wave speed (a front at c t),
// the wave-equation reference (arrival at probes), the method of images (a straight wall
// against an open domain with the mirrored source), and the full variant's subdivision
// (lp2 keeps a fixed count and loses coverage with distance). Scenarios are the bundled
// files (assets/scenarios).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/mesh/input_error.h"
#include "harness/measures/wave_error/wave_error.h"
#include "harness/suite/scenario_file.h"
#include "techniques/wave_particles/wave_particles.h"

namespace tb::wave_particles {
namespace {

// The radius of the height field's crest along a ray from the source: where the field
// peaks between the source and the domain border (1 cm steps).
double crestRadius(const HeightField& field, double angle) {
  double best_h = -1, best_r = 0;
  for (double r = 0.3; r < 3.9; r += 0.01) {
    const double h = field.sample(r * std::cos(angle), r * std::sin(angle));
    if (h > best_h) {
      best_h = h;
      best_r = r;
    }
  }
  return best_r;
}

TEST(WaveParticlesCpu, FullWavefrontRadiusIsSpeedTimesTimeWithinOneRadius) {
  const techniques::Scenario scenario = suite::resolveScenario("wave_point_impulse");
  WaveParticleSimulation simulation(scenario, Variant::kFull);
  const double r = simulation.scene().particle_radius_m, c = simulation.scene().wave_speed_m_per_s;
  double worst = 0;
  for (size_t step = 1; step <= scenario.stepCount(); ++step) {
    simulation.step(scenario.time_step_s);
    if (step % 25 != 0 || simulation.timeS() < 2 * r / c) continue;
    const HeightField field = simulation.heightField();
    for (double angle : {0.0, 0.3, 1.1, 2.0, 3.0, 4.4, 5.5}) {
      const double error = std::abs(crestRadius(field, angle) - c * simulation.timeS());
      worst = std::max(worst, error);
      EXPECT_LE(error, r) << "t = " << simulation.timeS() << ", angle " << angle;
    }
  }
  std::printf("full wavefront radius: worst |crest - c t| = %.4f m (r = %.2f m)\n", worst, r);
}

TEST(WaveParticlesCpu, FullArrivalAtProbesMatchesTheReferenceWithinTheTolerance) {
  const techniques::Scenario scenario = suite::resolveScenario("wave_point_impulse");
  WaveParticleSimulation simulation(scenario, Variant::kFull);
  const measures::WaveErrorFigures figures = measures::measureWaveError(simulation, 4);
  ASSERT_FALSE(figures.probes.empty());
  for (const measures::WaveProbeFigures& probe : figures.probes) {
    ASSERT_TRUE(probe.arrivalError().has_value()) << probe.x_m << ", " << probe.y_m;
    std::printf(
        "probe (%.2f, %.2f) at %.2f m: reference %.3f s, particles %.3f s, error %+.3f s "
        "(tolerance %.3f s)\n",
        probe.x_m, probe.y_m, probe.distance_m, *probe.reference_arrival_s,
        *probe.particle_arrival_s, *probe.arrivalError(), figures.arrival_tolerance_s);
    EXPECT_LE(std::abs(*probe.arrivalError()), figures.arrival_tolerance_s);
  }
  for (const measures::WaveTimeFigures& row : figures.times) {
    std::printf(
        "t = %.2f s: rms %.4f, max %.4f (of the amplitude), coverage %.3f, %llu particles\n",
        row.time_s, row.rms_error, row.max_error, row.coverage.value_or(-1),
        (unsigned long long)row.particles);
  }
}

TEST(WaveParticlesCpu, AStraightWallReflectsLikeTheMirrorImageSource) {
  const techniques::Scenario walled = suite::resolveScenario("wave_straight_wall");
  // The oracle: the open domain with the source mirrored across the wall (x = 1).
  techniques::Scenario images = walled;
  images.sections["wave_particles"] =
      R"({"sources": [{"position_m": [0.0, 0.0], "amplitude_m": 0.1},
                      {"position_m": [2.0, 0.0], "amplitude_m": 0.1}]})";
  for (Variant variant : {Variant::kFull, Variant::kLp2}) {
    WaveParticleSimulation a(walled, variant);
    techniques::Scenario oracle = images;
    oracle.parameters["max_particles"] = 64;
    WaveParticleSimulation b(oracle, variant);
    for (size_t step = 0; step < walled.stepCount(); ++step) {
      a.step(walled.time_step_s);
      b.step(walled.time_step_s);
    }
    ASSERT_GT(a.timeS(), 1.5) << "the reflection is back at the source";
    const HeightField fa = a.heightField(), fb = b.heightField();
    const double r = a.scene().particle_radius_m;
    double worst = 0, peak = 0;
    for (uint32_t j = 0; j < fa.nodes; ++j) {
      for (uint32_t i = 0; i < fa.nodes; ++i) {
        const double x = fa.origin_m + i * fa.spacing_m;
        if (x > 1.0 - r - 1e-9) continue;
        worst = std::max(worst, std::abs(fa.at(i, j) - fb.at(i, j)));
        peak = std::max(peak, std::abs(fb.at(i, j)));
      }
    }
    std::printf("%s: wall vs mirror image, max |dh| = %.3g of peak %.3g\n",
                variant == Variant::kFull ? "full" : "lp2", worst, peak);
    EXPECT_GT(peak, 1e-4);
    EXPECT_LT(worst, 1e-4 * peak);
    // Reflected particles lie on the mirror source's ring.
    uint64_t reflected = 0;
    for (const Particle& p : a.particles()) {
      if (p.origin[0] < 1.0f) continue;
      ++reflected;
      float x, y;
      particlePosition(p, 1.0f, &x, &y);
      EXPECT_NEAR(std::hypot(x - 2.0, y), a.timeS(), 1e-4);
    }
    EXPECT_GT(reflected, 0u);
  }
}

TEST(WaveParticlesCpu, Lp2CoverageFallsBelowFullWithDistance) {
  const techniques::Scenario scenario = suite::resolveScenario("wave_point_impulse");
  WaveParticleSimulation full(scenario, Variant::kFull), lp2(scenario, Variant::kLp2);
  const measures::WaveErrorFigures f = measures::measureWaveError(full, 6),
                                   l = measures::measureWaveError(lp2, 6);
  ASSERT_EQ(f.times.size(), l.times.size());
  for (size_t k = 0; k < f.times.size(); ++k) {
    std::printf("coverage at %.2f m: full %.3f, lp2 %.3f (%llu vs %llu particles)\n",
                f.times[k].front_radius_m, f.times[k].coverage.value_or(-1),
                l.times[k].coverage.value_or(-1), (unsigned long long)f.times[k].particles,
                (unsigned long long)l.times[k].particles);
    ASSERT_TRUE(f.times[k].coverage && l.times[k].coverage);
    EXPECT_GE(*f.times[k].coverage, 0.99) << "full subdivides: the ring stays whole";
  }
  EXPECT_LT(*l.times.back().coverage, 0.5 * *f.times.back().coverage);
  for (size_t k = 1; k < l.times.size(); ++k) {
    EXPECT_LE(*l.times[k].coverage, *l.times[k - 1].coverage + 1e-12) << "breaks up with distance";
  }
}

// Oracle: the linear search over every wall (full's). Random walls and moves; the tree must
// find the same first crossing, so the reflected particle is the same bit for bit. A tree
// whose skip indices jumped too far would miss walls.
TEST(WaveParticlesCpu, Lp2TreeReflectsExactlyLikeTheLinearSearch) {
  uint32_t seed = 12345;
  auto uniform = [&](float lo, float hi) {
    seed = seed * 1664525u + 1013904223u;
    return lo + (hi - lo) * float(seed >> 8) / float(1u << 24);
  };
  std::vector<WallSegment> walls;
  for (int w = 0; w < 37; ++w) {
    const float ax = uniform(-4, 4), ay = uniform(-4, 4);
    const float bx = ax + uniform(-1, 1), by = ay + uniform(-1, 1);
    const float len = std::hypot(bx - ax, by - ay);
    walls.push_back({{ax, ay}, {bx, by}, {-(by - ay) / len, (bx - ax) / len}});
  }
  const std::vector<AabbNode> tree = buildWallTree(walls);
  ASSERT_EQ(tree.size(), 2 * walls.size() - 1);
  StepSettings linear;
  linear.dt_s = 0.5f;  // 1 m moves: many cross a wall
  linear.speed_m_per_s = 2.0f;
  linear.capacity = 10;
  linear.subdivide_fraction = 1e30f;  // no subdivision: only the reflection differs
  StepSettings lp2 = linear;
  lp2.variant = Variant::kLp2;
  const SubdivisionTable table = subdivisionTable(0.1f, 2);
  // A broken tree (the root's first child skips past the end) must show.
  std::vector<AabbNode> broken = tree;
  broken[1].skip = uint32_t(broken.size());
  int reflected = 0, broken_differs = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    Particle p{};
    p.origin[0] = uniform(-4, 4);
    p.origin[1] = uniform(-4, 4);
    const float angle = uniform(0, 6.2831853f);
    p.direction[0] = std::cos(angle);
    p.direction[1] = std::sin(angle);
    p.age_s = uniform(0, 0.5f);
    p.lifetime_s = 100;
    p.amplitude_m = 1;
    p.dispersion_rad = 0.1f;
    p.radius_m = 0.1f;
    std::vector<Particle> a, b;
    uint64_t dropped = 0;
    updateParticle(p, linear, walls, {}, table, &a, &dropped);
    updateParticle(p, lp2, walls, tree, table, &b, &dropped);
    ASSERT_EQ(a.size(), 1u);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(std::memcmp(a[0].origin, b[0].origin, sizeof(float) * 4), 0) << "trial " << trial;
    reflected += a[0].direction[0] != p.direction[0] || a[0].direction[1] != p.direction[1];
    std::vector<Particle> c;
    updateParticle(p, lp2, walls, broken, table, &c, &dropped);
    broken_differs += std::memcmp(a[0].origin, c[0].origin, sizeof(float) * 4) != 0;
  }
  EXPECT_GT(broken_differs, 0) << "the comparison catches a tree that misses walls";
  std::printf("AABB tree vs linear search: %d of 4000 moves reflected, all identical\n", reflected);
  EXPECT_GT(reflected, 100) << "the trials hit walls";
}

TEST(WaveParticlesCpu, Lp2ExpiresAtTheLifetimeAndKeepsItsBuffer) {
  techniques::Scenario scenario = suite::resolveScenario("wave_point_impulse");
  scenario.parameters["particle_lifetime_s"] = 1.0;
  WaveParticleSimulation lp2(scenario, Variant::kLp2);
  EXPECT_EQ(lp2.capacity(), 32u);
  for (int step = 0; step < 49; ++step) lp2.step(scenario.time_step_s);
  EXPECT_EQ(lp2.particles().size(), 32u);
  // 50 float steps of 0.02 s sum to 0.99999994 s: expired one step later, at 1.02 s.
  lp2.step(scenario.time_step_s);
  lp2.step(scenario.time_step_s);
  EXPECT_EQ(lp2.particles().size(), 0u);
}

TEST(WaveParticlesCpu, BadScenarioSectionsAreOneLineInputErrors) {
  techniques::Scenario scenario = suite::resolveScenario("wave_point_impulse");
  scenario.sections["wave_particles"] =
      R"({"sources": [{"position_m": [9, 0], "amplitude_m": 1}]})";
  try {
    WaveParticleSimulation simulation(scenario, Variant::kFull);
    FAIL() << "accepted a source outside the domain";
  } catch (const mesh::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("wave_particles.sources[0].position_m: outside"),
              std::string::npos)
        << error.what();
  }
  scenario.sections["wave_particles"] = R"({"sources": []})";
  EXPECT_THROW(WaveParticleSimulation(scenario, Variant::kFull), mesh::InputError);
  scenario.sections.erase("wave_particles");
  EXPECT_THROW(WaveParticleSimulation(scenario, Variant::kFull), techniques::UnsupportedInput);
}

}  // namespace
}  // namespace tb::wave_particles
