// A mass-spring soft body's input, read from a scenario's "mass_spring" section (format in
// docs/derivations/simulations.md, "Mass-spring soft body"): the skin mesh, a bone chain and its
// animation, stiffness per spring kind, and the painted softness (seed 003: the artist
// paints how soft each part of the skin is). Also builds the springs from them.
#pragma once

#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"
#include "techniques/mass_spring/spring_system.h"
#include "techniques/simulation.h"

namespace tb::mass_spring {

// A periodic motion of the bone chain: joint j moves by direction * amplitude_m[j] *
// sin(2 pi frequency_hz t); points between two joints interpolate linearly.
struct Stomp {
  mesh::Vec3d direction{0, 0, 1};
  double frequency_hz = 1;
  std::vector<double> joint_amplitudes_m;
};

// An impulse: at the first step at or after time_s, every vertex within radius_m of the
// centre gets a velocity away from it of speed_m_per_s * (1 - distance / radius_m).
struct Blast {
  double time_s = 0;
  mesh::Vec3d center_m{0, 0, 0};
  double radius_m = 1;
  double speed_m_per_s = 1;
};

// A paint stroke of the softness map: softness moves towards `value` by 1 - d / radius_m
// inside the sphere.
struct SoftnessSphere {
  mesh::Vec3d center_m{0, 0, 0};
  double radius_m = 1;
  double value = 1;
};

struct SoftBodyInput {
  std::string source;                      // the scenario file (or name), for errors
  mesh::Mesh skin;                         // the simulated mesh
  std::vector<mesh::Vec3d> bone_joints_m;  // the bone chain, >= 2 joints
  double surface_stiffness = 1;            // (0, 1]
  double inner_stiffness = 0.5;            // [0, 1]; 0: no inner springs
  double goal_stiffness = 0.5;             // [0, 1]; scaled per vertex by 1 - softness
  double softness_default = 0.5;           // [0, 1]: 0 follows the skinning, 1 free
  std::vector<SoftnessSphere> softness_spheres;
  double damping = 0.01;  // fraction of the Verlet velocity lost per step, [0, 1)
  mesh::Vec3d gravity_m_per_s2{0, 0, 0};
  std::vector<Stomp> stomps;
  std::vector<Blast> blasts;
  // Solver dispatches a step may spend ("dispatches_per_step" parameter; seed 003's
  // fixed per-frame budget), spent as SpringSolver::iterateDispatches.
  size_t dispatches_per_step = 8;
};

// Parses scenario.sections["mass_spring"] and loads scenario.mesh_path. Throws InputError
// naming the scenario file and the field ("mass_spring.stiffness.goal").
SoftBodyInput parseSoftBody(const techniques::Scenario& scenario);

// The skin's pose at a time: where each bone-chain point and each skinned vertex is, in
// coordinates relative to `origin` and rounded to float, so that the rest pose the springs
// are built from is exactly representable in float (the convergence frame is then exactly
// satisfiable in the solvers' float and in the reference's double).
class SoftBodyRig {
 public:
  SoftBodyRig(const SoftBodyInput& input, const mesh::Vec3d& origin);
  const mesh::Vec3d& origin() const { return origin_; }
  size_t vertexCount() const { return rest_.size(); }
  const std::vector<mesh::Vec3d>& restPositions() const { return rest_; }
  const std::vector<double>& softness() const { return softness_; }
  // The chain point closest to vertex v at rest.
  const mesh::Vec3d& restBonePoint(size_t v) const { return bone_point_[v]; }
  // Stomp s's translation of vertex v's closest chain point at amplitude 1 (direction x the
  // amplitude interpolated between the segment's joints); the skinning is rigid per chain
  // point: the vertex and its bone point move together by the sum over the stomps of
  // stompAmplitude(v, s) * sin(2 pi f_s t).
  mesh::Vec3d stompAmplitude(size_t v, size_t s) const;

 private:
  const SoftBodyInput& input_;
  mesh::Vec3d origin_;
  std::vector<mesh::Vec3d> rest_;
  std::vector<mesh::Vec3d> bone_point_;
  std::vector<uint32_t> bone_segment_;  // chain segment of the closest point
  std::vector<double> bone_parameter_;  // 0 at its first joint, 1 at the next
  std::vector<double> softness_;
};

// The springs: surface (every mesh edge once, in first-seen face order), then one inner
// spring per vertex to anchor v (its bone point; when inner stiffness > 0), then one goal
// spring per vertex to anchor N + v (its skinned position; when goal springs are on and the
// vertex's goal stiffness (1 - softness) * goal_stiffness > 0). Anchors: 2N.
SpringSystem buildSpringSystem(const SoftBodyInput& input, const SoftBodyRig& rig,
                               bool goal_springs);

}  // namespace tb::mass_spring
