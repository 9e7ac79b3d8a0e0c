// The pictures of a finished run (docs/ARCHITECTURE.md §4, "Pictures"): for each technique
// × asset with a record of the technique's default variant whose `error` measure is ok, the
// error and wireframe pictures of surface_picture.h, written as PNG files beside
// results.json with an index (pictures_index.h).
#pragma once

#include <functional>
#include <string>

#include "harness/pictures/pictures_index.h"
#include "harness/pictures/surface_picture.h"
#include "harness/results/results_model.h"

namespace tb::pictures {

// Writes one file of the run folder: a path relative to it ("pictures/x.png") and the bytes.
using WriteFileFn = std::function<void(const std::string& relative_path, const std::string& bytes)>;

// The picture files of one technique × asset, relative to the run folder:
// pictures/<technique>--<asset, '/' as "--", characters other than [A-Za-z0-9._-] as
// '_'>--error.png and ...--wireframe.png.
std::string errorPicturePath(const std::string& technique, const std::string& asset);
std::string wireframePicturePath(const std::string& technique, const std::string& asset);
// ...--cracks.png: where a default variant cracks (crack_picture.h), for the records with a
// cpu_float cracks row whose points_not_equal > 0.
std::string crackPicturePath(const std::string& technique, const std::string& asset);

// Error and wireframe pictures look along the asset's up axis (up_axis.h: z-up assets turned
// upright by the camera). A record that cracks on the CPU also gets its crack picture from
// the same render (worstCpuCrackRow, crackPairsOf, composeCrackPicture).
// Opens the Vulkan device named like the run's (`device_name`: a substring, empty = best;
// only dynamic rendering is required) and renders the run's pictures. Without a usable
// device nothing is rendered: the index says "skipped" with the reason, and only it is
// written. Each picture's PNGs and then kPicturesIndexPath go through `write`, in record
// order. The technique and asset of a record are found again by name (TechniqueRegistry,
// resolveAsset) and rebuilt as the suite builds them; a picture that cannot be made (an
// asset gone, a device error) is an index entry with status "failed" and no files.
// Pictures are made in parallel (TBB, the device's queue taken in turn) into fixed slots,
// so the files are byte-identical whatever the thread count.
// Cost on lavapipe, the default suite's 89 pairs at level 8 and 320 px: 3.5 processor
// seconds over every thread, 2.2 MB of PNG (bench/pictures_bench.cpp; docs/ARCHITECTURE.md §4).
PicturesIndex renderRunPictures(const results::Results& results, const std::string& device_name,
                                const WriteFileFn& write, const PictureSettings& settings = {});

// The same with a device the caller opened; `context` null: skipped with
// `unavailable_reason`.
PicturesIndex renderRunPictures(const results::Results& results, gpu::Context* context,
                                const std::string& unavailable_reason, const WriteFileFn& write,
                                const PictureSettings& settings = {});

}  // namespace tb::pictures
