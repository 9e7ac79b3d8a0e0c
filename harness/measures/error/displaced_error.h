// The error of a displaced surface against the detailed target its map was baked from
// (issue 17's `error` rows with the `displacement` key): where the map, not the patch,
// limits accuracy. Distances are fractions of the control mesh's bounding-box diagonal.
#pragma once

#include <cstdint>

#include "harness/measures/displaced_input.h"
#include "techniques/technique.h"

namespace tb::measures {

struct DisplacedErrorFigures {
  // Two-sided Hausdorff distance between the displaced surface tessellated at `level` and
  // the target: max of the next two. Best 0; worst about the displacement amplitude (the map
  // missing) or the patch error.
  double hausdorff = 0;
  // Max distance from the displaced surface's lattice points (level segments per patch edge)
  // to the target.
  double hausdorff_tech_to_target = 0;
  // Max distance from the target's vertices to the displaced surface's triangles at `level`
  // (includes that tessellation's own chordal error, which falls with the level).
  double hausdorff_target_to_tech = 0;
  double rms_distance = 0;   // RMS of the lattice points' distances to the target
  uint64_t samples = 0;      // lattice points
  double bbox_diagonal = 0;  // world units
  // Texels per patch side of the map (a baked map's resolution): the map's sampling
  // density, against which the level's own density is read.
  uint32_t map_texels_per_side = 0;
};

// `displaced`: the technique's surface with the map applied (DisplacedPatches); `level`:
// segments per patch edge of the lattice (>= 1).
DisplacedErrorFigures measureDisplacedError(const techniques::SurfacePatches& displaced,
                                            const DisplacementTarget& target, int level,
                                            uint32_t map_texels_per_side);

}  // namespace tb::measures
