// Displacement maps a run applies (`tessbench run --displacement FILE.exr`, and the bundled
// assets/displacement/*.exr of the default suite): the EXR and its bake sidecar
// (FILE.exr.json, harness/bake/bake_sidecar.h) read and checked together, and the target the
// map was baked against rebuilt for the error measure.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "harness/measures/displaced_input.h"
#include "techniques/technique.h"

namespace tb::suite {

// Reads FILE.exr and FILE.exr.json. Throws InputError (one line naming the file and the
// problem) for a bad EXR (core/displacement/exr_io.h), a missing or malformed sidecar, a
// sidecar that disagrees with the EXR (kind, size, tiles), or a layout other than tiles.
measures::DisplacedInput loadDisplacementFile(const std::string& path);

// The bundled maps, assets/displacement/*.exr, sorted by name, loaded.
std::vector<measures::DisplacedInput> bundledDisplacements();

// The target of `input` for a surface built on its asset: the analytic target (the asset's
// limit displaced by the closed-form h, rebuilt at the sidecar's rate) or the target OBJ.
// Throws InputError when the OBJ cannot be read or the limit cannot be built.
std::shared_ptr<const measures::DisplacementTarget> rebuildTarget(
    const measures::DisplacedInput& input, const techniques::SurfacePatches& undisplaced);

}  // namespace tb::suite
