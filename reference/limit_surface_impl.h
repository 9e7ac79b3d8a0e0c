// Internal: the state behind LimitSurface, shared with LimitFace.
#pragma once

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surfaceFactoryCache.h>
#include <opensubdiv/far/topologyRefiner.h>

#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"
#include "reference/limit_surface.h"

namespace tb::ref {

// Readers share the cache; a new irregular patch takes it exclusively.
using ThreadedSurfaceCache = OpenSubdiv::Bfr::SurfaceFactoryCacheThreaded<
    std::shared_mutex, std::shared_lock<std::shared_mutex>, std::unique_lock<std::shared_mutex>>;
using ThreadedSurfaceFactory = OpenSubdiv::Bfr::RefinerSurfaceFactory<ThreadedSurfaceCache>;

struct LimitSurface::Impl {
  mesh::Mesh mesh;
  osd::Scheme scheme = osd::Scheme::kCatmullClark;
  std::vector<double> positions;  // xyz per vertex, Bfr's contiguous mesh points
  std::vector<bool> is_hole;      // per face
  std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner;
  std::unique_ptr<ThreadedSurfaceFactory> factory;

  // Throws InputError naming the face when it is out of range or has no limit surface.
  void checkFace(size_t face) const;
};

}  // namespace tb::ref
