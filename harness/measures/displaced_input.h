// A displacement map a run applies to one technique's surface (`tessbench run --displacement
// FILE.exr`, or a bundled map): what measures read about it besides the displaced patches
// themselves (MeasureInput::patches is then a DisplacedPatches). Loaded and validated by
// harness/suite/displacement_file.h.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/displacement/displacement_map.h"
#include "core/mesh/vec.h"
#include "reference/triangle_distance_field.h"
#include "techniques/common/displacement_sampling.h"

namespace tb::measures {

// The detailed target a map was baked against, rebuilt for grading.
struct DisplacementTarget {
  std::vector<mesh::Vec3d> positions;  // world units
  std::vector<ref::Triangle> triangles;
  std::shared_ptr<const ref::TriangleDistanceField> field;  // Embree point queries on it
};

struct DisplacedInput {
  std::string name;  // the map's file name ("acc_catmark_torus.exr"): row key `displacement`
  std::string path;  // as shown in results (relative to the source tree when bundled)
  std::shared_ptr<const displacement::DisplacementMap> map;
  std::string technique, variant, asset;  // what the sidecar says it was baked for
  uint32_t resolution = 0;                // texels per patch side (sidecar)
  uint64_t file_bytes = 0;                // the EXR on disk
  std::string target;                     // the sidecar's description of the target
  int target_rate = 0;                    // analytic target: its tessellation rate; else 0
  std::string target_path;                // mesh target: the OBJ
};

// What one displaced record runs with: the map and how it is sampled, and the target (null
// when it could not be rebuilt; the error measure then skips with the reason).
struct DisplacementRun {
  const DisplacedInput* input = nullptr;
  techniques::DisplacementSampling sampling = techniques::DisplacementSampling::kWatertight;
  std::shared_ptr<const DisplacementTarget> target;
  std::string target_unavailable;  // why target is null
};

}  // namespace tb::measures
