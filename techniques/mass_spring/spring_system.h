// The constraints of a mass-spring soft body (seed 003, "mass-spring model"): surface
// springs along the mesh edges, inner springs from each vertex to its closest bone point,
// goal springs from each vertex to its skinned position. Inner and goal springs end at a
// kinematic anchor (moved by the animation, never by the solver). The graph colouring and
// the per-vertex gather lists the parallel solvers need are built here once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace tb::mass_spring {

enum class SpringKind : uint8_t { kSurface, kInner, kGoal };

// Set in Spring::b when the second end is anchor (b & ~kAnchorBit), not a vertex.
inline constexpr uint32_t kAnchorBit = 0x80000000u;

struct Spring {
  uint32_t a = 0;     // vertex
  uint32_t b = 0;     // vertex, or kAnchorBit | anchor index
  double rest_m = 0;  // rest length, metres (0 for a goal spring)
  // Fraction of the stretch a projection removes, (0, 1]: the seed's code moves each of two
  // vertices by half the stretch (weight 0.5 x stiffness); an anchor spring moves its one
  // vertex by the whole (weight = stiffness).
  double weight = 0;
  SpringKind kind = SpringKind::kSurface;
  bool anchored() const { return (b & kAnchorBit) != 0; }
  uint32_t anchor() const { return b & ~kAnchorBit; }
};

// One end of a spring seen from a vertex (the Jacobi gather list).
struct SpringEnd {
  uint32_t other = 0;  // the other vertex, or kAnchorBit | anchor index
  double rest_m = 0;
  double weight = 0;  // as Spring::weight
};

struct SpringSystem {
  size_t vertex_count = 0;
  size_t anchor_count = 0;
  // Surface springs in edge order, then inner springs, then goal springs, each by vertex:
  // the reference (serial Gauss-Seidel) order.
  std::vector<Spring> springs;
  double length_scale_m = 1;  // mean surface rest length: scales anchor distances of rest 0

  // Greedy graph colouring, springs at the busiest vertices first (Welsh-Powell order, ties
  // in spring order): each spring takes the smallest colour used by no other spring at
  // either of its vertices (anchors are never shared: each is read only). colour_of[s] for
  // every spring.
  std::vector<uint32_t> colour_of;
  uint32_t colour_count = 0;
  // The springs of colour c are colour_order[colour_start[c] .. colour_start[c + 1]), each
  // colour in spring order: the colour-major order.
  std::vector<uint32_t> colour_order;
  std::vector<uint32_t> colour_start;

  // Gather lists: vertex v's spring ends are ends[end_start[v] .. end_start[v + 1]), in
  // spring order.
  std::vector<uint32_t> end_start;
  std::vector<SpringEnd> ends;
};

// Fills colour_*, end_* of `system` from its springs.
void buildSolverTables(SpringSystem& system);

// The colour count the same greedy colouring gives the springs of `system` whose kind is
// in `kinds` (in spring order).
uint32_t colourCountOf(const SpringSystem& system, std::initializer_list<SpringKind> kinds);

// A broken colouring's first conflict (two springs of one colour sharing a vertex): their
// indices, or {-1, -1} when the colouring is valid. For tests and assertions.
struct ColourConflict {
  long long first = -1, second = -1;
};
ColourConflict findColourConflict(const SpringSystem& system);

}  // namespace tb::mass_spring
