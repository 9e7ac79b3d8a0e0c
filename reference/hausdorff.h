// Two-sided Hausdorff and RMS distance between triangle meshes, sampled inside the
// triangles (docs/MEASURES.md, error; Cignoni et al., "Metro", 1998, samples the same way).
//
// Sampling of each source triangle at lattice level m (deterministic):
//  - the (m+1)(m+2)/2 points of the barycentric lattice i/m, corners and edges included;
//  - the centroids of its m^2 congruent sub-triangles, which carry the RMS and mean as a
//    midpoint rule (each weighs area / m^2).
// The maximum is taken over both sets. Every sample's distance is exact (closest point
// over all triangles of the target, in double), or, for a lattice point proved below the
// largest centroid distance, left out: every figure is unchanged, bit for bit (MaxSearch).
#pragma once

#include <cstddef>

#include "reference/triangle_distance_field.h"
#include "reference/triangle_mesh_ref.h"

namespace tb::ref {

inline constexpr int kDefaultLatticeLevel = 4;  // 15 lattice points + 16 centroids
inline constexpr int kMaxLatticeLevel = 256;

struct DirectedDistance {
  double max = 0;      // world units: largest sample distance from the source to the target
  mesh::Vec3d max_at;  // the source sample where it occurs
  double rms = 0;      // world units: area-weighted root mean square distance
  double mean = 0;     // world units: area-weighted mean distance
  double area = 0;     // world units^2: area of the source
  size_t samples = 0;  // samples of the source (lattice points and centroids)
};

struct HausdorffResult {
  DirectedDistance a_to_b;  // samples of a, distances to b
  DirectedDistance b_to_a;
  double hausdorff = 0;  // world units: max(a_to_b.max, b_to_a.max)
  // World units: RMS over both surfaces' samples pooled by area,
  // sqrt((area_a rms_ab^2 + area_b rms_ba^2) / (area_a + area_b)).
  double rms = 0;
};

// How the lattice points (which feed the maximum alone) are measured.
enum class MaxSearch {
  kBoundedSkip,  // skip a point whose bound (its distance to the triangle closest to the
                 // centroid next to it) is below the largest centroid distance: the default
  kEverySample,  // measure every point (the oracle kBoundedSkip equals)
  kBrokenSkip,   // a control: the bound halved, so points that hold the maximum are skipped
};

// Samples of `source` against a prepared target (reuse one field for many sources).
// Throws InputError naming the option when lattice_level is outside [1, kMaxLatticeLevel].
DirectedDistance directedDistance(const TriangleMeshRef& source,
                                  const TriangleDistanceField& target,
                                  int lattice_level = kDefaultLatticeLevel,
                                  MaxSearch search = MaxSearch::kBoundedSkip);

HausdorffResult hausdorff(const TriangleMeshRef& a, const TriangleMeshRef& b,
                          int lattice_level = kDefaultLatticeLevel);

// The same on parts of the two surfaces: samples of `a_part` against `b_around`, samples of
// `b_part` against `a_around`, where each *_around holds its *_part and the surface around it
// that a closest point could fall on (a measure that samples patches: the sampled patches and
// their neighbours). With each part equal to its whole, the same result, bit for bit, as
// hausdorff(a, b).
HausdorffResult hausdorff(const TriangleMeshRef& a_part, const TriangleMeshRef& a_around,
                          const TriangleMeshRef& b_part, const TriangleMeshRef& b_around,
                          int lattice_level = kDefaultLatticeLevel);

}  // namespace tb::ref
