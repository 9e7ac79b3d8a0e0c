// The pictures of a finished run (docs/REPORTS.md, "Pictures"): for each technique
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

// Error and wireframe pictures look along the asset's up axis (up_axis.h); a record that
// cracks on the CPU also gets its crack picture from the same render. Opens the device named
// like the run's (`device_name`: a substring, empty = best); without one the index says
// "skipped" with the reason. Records are rebuilt by name as the suite builds them; a picture
// that cannot be made is an index entry "failed" with no files. Made in parallel into fixed
// slots, so files are byte-identical whatever the thread count. Cost: docs/PERFORMANCE.md.
PicturesIndex renderRunPictures(const results::Results& results, const std::string& device_name,
                                const WriteFileFn& write, const PictureSettings& settings = {});

// The same with a device the caller opened; `context` null: skipped with
// `unavailable_reason`.
PicturesIndex renderRunPictures(const results::Results& results, gpu::Context* context,
                                const std::string& unavailable_reason, const WriteFileFn& write,
                                const PictureSettings& settings = {});

}  // namespace tb::pictures
