// Camera paths: the views a view-dependent measure runs under (MeasureNeed::kView). The
// suite runs such a measure once per view of each path and keys its rows with the path's
// name and the view's index. The adaptivity issue adds the real paths (orbit, dolly,
// flyby); here is one fixed test path.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"
#include "core/view/view.h"

namespace tb {

// Axis-aligned bounding box, world units; min <= max component-wise.
struct Aabb {
  Vec3d min{0, 0, 0};
  Vec3d max{0, 0, 0};
};

// The bounding box of the mesh's positions; the unit cube [-1, 1]^3 when it has none (a
// simulation's scenario).
Aabb boundsOf(const Mesh& mesh);

struct CameraPath {
  std::string name;         // the rows' "camera_path" key, e.g. "test_orbit"
  std::vector<View> views;  // in path order; the rows' "view" key is the index
};

// Makes a path for the scene inside `bounds`.
using CameraPathFn = std::function<CameraPath(const Aabb& bounds)>;

// "test_orbit": 3 views at 0, 120 and 240 degrees around the box's vertical (y) axis,
// 20 degrees above its centre, at 2.5 box radii, 60 degree vertical field of view,
// 640 x 480 pixels, 8 pixels per edge. Fixed, for tests and plumbing.
CameraPath testOrbitPath(const Aabb& bounds);

}  // namespace tb
