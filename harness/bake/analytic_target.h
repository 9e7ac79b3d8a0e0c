// The baker's oracle (docs/derivations/displacement.md): the asset's Bfr limit tessellated
// densely, each vertex moved along its limit normal by
//   h(p) = A (sin(2 pi f qx + 0.3) + sin(2 pi f qy + 1.1) + sin(2 pi f qz + 2.3)) / 3,
// q = (p - c) / D (c, D the control mesh's box centre and diagonal), A = amplitude_fraction
// D, f cycles per diagonal. |grad h| <= A 2 pi f / (D sqrt 3) (0.073 at the defaults), so the
// displaced surface stays a graph over the limit and a normal ray meets it once nearby.
#pragma once

#include <string>

#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"
#include "core/osd/scheme.h"
#include "reference/limit_tessellation.h"

namespace tb::bake {

struct AnalyticDisplacement {
  mesh::Vec3d centre;    // c: bounding-box centre of the control mesh, world units
  double diagonal = 1;   // D: its diagonal, world units (> 0)
  double amplitude = 0;  // A: world units
  double frequency = 2;  // f: cycles per diagonal

  // h(p), world units.
  double height(const mesh::Vec3d& p) const;
  // The formula with its numbers, for the sidecar ("h(p) = ...").
  std::string describe() const;
};

inline constexpr double kAnalyticAmplitudeFraction = 0.01;  // A / D
inline constexpr double kAnalyticFrequency = 2;             // f, cycles per diagonal

// h for `mesh`'s bounding box with the default amplitude and frequency. Throws InputError for
// a mesh without positions or with a zero diagonal.
AnalyticDisplacement analyticDisplacementFor(const mesh::Mesh& mesh);

// The limit surface of `mesh` under `scheme` tessellated at `rate` (ref::tessellateLimit),
// each vertex moved along its unit limit normal by displacement.height(limit position); the
// normals are left as the limit's (they are not the displaced surface's). Faces without a
// limit surface are left out (faces_skipped). Throws InputError like LimitSurface and
// tessellateLimit (rate outside 1..1024).
ref::LimitTessellation analyticTargetMesh(const mesh::Mesh& mesh, osd::Scheme scheme, int rate,
                                          const AnalyticDisplacement& displacement);

// The mesh as an OBJ file (v and f lines, 1-based, triangles counter-clockwise); throws
// InputError naming the path when it cannot be written, and refuses a path that exists.
void writeTriangleObj(const std::string& path, const ref::LimitTessellation& mesh,
                      const std::string& comment);

}  // namespace tb::bake
