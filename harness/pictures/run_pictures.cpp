#include "harness/pictures/run_pictures.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <utility>

#include "core/gpu/context.h"
#include "core/gpu/render_target.h"
#include "core/mesh/obj_loader.h"
#include "harness/measures/error/error.h"
#include "harness/pictures/crack_picture.h"
#include "harness/pictures/png_writer.h"
#include "harness/suite/asset_catalog.h"
#include "techniques/registry.h"

namespace tb::pictures {
namespace {

constexpr const char* kErrorStatistic = "max_of_3_vertices";

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// One technique × asset to picture.
struct PictureJob {
  const techniques::Technique* technique = nullptr;
  const results::Record* record = nullptr;
};

// What one job produced: the index entry and, when ok, the files' bytes (crack_png only
// for a variant that cracks).
struct PictureOutcome {
  PictureEntry entry;
  std::string error_png, wireframe_png, crack_png;
};

std::string fileStem(const std::string& technique, const std::string& asset) {
  std::string stem = technique + "--";
  for (char c : asset) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '.' || c == '_' || c == '-';
    if (c == '/') {
      stem += "--";
    } else {
      stem += plain ? c : '_';
    }
  }
  return std::string(kPicturesFolder) + "/" + stem;
}

bool errorMeasured(const results::Record& record) {
  for (const results::MeasureResult& measure : record.measures) {
    if (measure.measure == "error" && measure.status == results::MeasureStatus::kOk) return true;
  }
  return false;
}

// Records of a surface technique's default variant with an ok `error` result, in record
// order, one per technique × asset.
std::vector<PictureJob> picturesOf(const results::Results& results) {
  std::vector<PictureJob> jobs;
  std::set<std::pair<std::string, std::string>> seen;
  for (const results::Record& record : results.records) {
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(record.technique);
    if (technique == nullptr || technique->info().family != techniques::TechniqueFamily::kSurface)
      continue;
    const std::vector<techniques::VariantInfo> variants = technique->variants();
    if (variants.empty() || record.variant != variants.front().name) continue;
    if (!errorMeasured(record)) continue;
    // A displaced asset's pictures would need its map; the undisplaced asset has its own.
    if (record.parameters.count("displacement") > 0) continue;
    if (!seen.insert({record.technique, record.asset}).second) continue;
    jobs.push_back({technique, &record});
  }
  return jobs;
}

// The technique instance as the suite builds it: the asset loaded by its name, checked,
// then built with the default variant.
std::unique_ptr<techniques::TechniqueInstance> buildInstance(const techniques::Technique& technique,
                                                             const std::string& asset,
                                                             mesh::Mesh* mesh) {
  const suite::AssetRef ref = suite::resolveAsset(asset);
  *mesh = suite::loadAsset(ref);
  mesh->source = ref.shownPath();
  if (std::string reason = technique.checkSupport(*mesh); !reason.empty()) {
    throw techniques::UnsupportedInput(reason);
  }
  std::unique_ptr<techniques::TechniqueInstance> instance =
      technique.build(techniques::TechniqueInput{mesh, nullptr}, technique.variants().front());
  if (instance == nullptr || instance->surface() == nullptr) {
    throw std::logic_error(technique.info().id + ": the instance has no surface");
  }
  return instance;
}

// A job's surface and render, kept until every surface of its asset is graded (the colour
// scale is the asset's).
struct RenderedSurface {
  SurfaceErrorMesh surface;
  view::View view;
  std::vector<uint32_t> ids;
  UpAxis up = UpAxis::kY;
  std::optional<CrackRow> crack_row;  // the record's worst cpu_float cracks row, if any
  std::vector<measures::UnequalPair> crack_pairs;
};

// One job's first half: CPU tessellation and error, the render (the shared target taken in
// turn). The entry says failed when it could not be made.
PictureOutcome renderSurface(const PictureJob& job, const PictureSettings& settings,
                             gpu::RenderTarget& target, std::mutex& target_mutex,
                             std::optional<RenderedSurface>* rendered) {
  PictureOutcome outcome;
  PictureEntry& entry = outcome.entry;
  entry.technique = job.record->technique;
  entry.variant = job.record->variant;
  entry.asset = job.record->asset;
  entry.level = settings.level;
  entry.error_statistic = kErrorStatistic;
  try {
    mesh::Mesh mesh;
    const std::unique_ptr<techniques::TechniqueInstance> instance =
        buildInstance(*job.technique, entry.asset, &mesh);
    const techniques::SurfacePatches& patches = *instance->surface();
    const ref::LimitSurface limit(patches.controlMesh(),
                                  lod::referenceScheme(patches.approximates()));
    RenderedSurface r;
    r.surface = tessellateWithError(patches, limit, settings.level);
    r.up = detectUpAxis(patches.controlMesh().positions);
    r.view = threeQuarterView(r.surface.bounds, settings.size_px, r.up);
    r.crack_row = worstCpuCrackRow(*job.record);
    if (r.crack_row) r.crack_pairs = crackPairsOf(patches, *r.crack_row);
    {
      const std::lock_guard lock(target_mutex);
      r.ids = renderTriangleIds(target, r.surface, r.view);
    }
    entry.error_max = r.surface.error_max;
    *rendered = std::move(r);
  } catch (const std::exception& error) {
    entry.status = "failed";
    entry.reason = error.what();
  }
  return outcome;
}

// The second half: the composition under the asset's scale and the PNG encoding.
void composePicture(RenderedSurface rendered, const PictureSettings& settings, double scale_max,
                    PictureOutcome* outcome) {
  PictureEntry& entry = outcome->entry;
  try {
    const SurfacePictures pictures =
        composeSurfacePictures(rendered.surface, rendered.view, settings.size_px,
                               std::move(rendered.ids), scale_max, rendered.up);
    outcome->error_png = encodePng(pictures.error);
    outcome->wireframe_png = encodePng(pictures.wireframe);
    entry.error_png = errorPicturePath(entry.technique, entry.asset);
    entry.wireframe_png = wireframePicturePath(entry.technique, entry.asset);
    entry.up_axis = toString(rendered.up);
    if (rendered.crack_row) {
      const RgbImage shaded = shadedPicture(rendered.surface, rendered.view, settings.size_px,
                                            pictures.triangle_ids, rendered.up);
      const CrackPicture crack =
          composeCrackPicture(shaded, rendered.surface, rendered.view, settings.size_px,
                              pictures.triangle_ids, rendered.crack_pairs);
      outcome->crack_png = encodePng(crack.image);
      entry.crack_png = crackPicturePath(entry.technique, entry.asset);
      entry.crack_row = rendered.crack_row->text();
      entry.crack_points = rendered.crack_pairs.size();
      entry.crack_points_visible = crack.points_visible;
      entry.crack_max_gap_world = rendered.crack_row->max_gap_world;
    }
    entry.width_px = pictures.error.width_px;
    entry.height_px = pictures.error.height_px;
    entry.scale_max = pictures.scale_max;
  } catch (const std::exception& error) {
    entry.status = "failed";
    entry.reason = error.what();
  }
}

}  // namespace

std::string errorPicturePath(const std::string& technique, const std::string& asset) {
  return fileStem(technique, asset) + "--error.png";
}

std::string wireframePicturePath(const std::string& technique, const std::string& asset) {
  return fileStem(technique, asset) + "--wireframe.png";
}

std::string crackPicturePath(const std::string& technique, const std::string& asset) {
  return fileStem(technique, asset) + "--cracks.png";
}

PicturesIndex renderRunPictures(const results::Results& results, const std::string& device_name,
                                const WriteFileFn& write, const PictureSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  gpu::ContextOptions options;
  options.device_name = device_name;
  options.required = gpu::DeviceFeatures{};
  options.required.dynamic_rendering = true;  // all gpu::RenderTarget needs
  auto created = gpu::Context::create(options);
  PicturesIndex index = created
                            ? renderRunPictures(results, created.value().get(), "", write, settings)
                            : renderRunPictures(results, nullptr, created.error(), write, settings);
  index.wall_s = secondsSince(start);
  return index;
}

PicturesIndex renderRunPictures(const results::Results& results, gpu::Context* context,
                                const std::string& unavailable_reason, const WriteFileFn& write,
                                const PictureSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  PicturesIndex index;
  if (context == nullptr) {
    index.status = "skipped";
    index.reason = "no Vulkan device (" + unavailable_reason + ")";
    write(kPicturesIndexPath, picturesIndexJson(index));
    return index;
  }
  index.device = context->info().device_name;
  const std::vector<PictureJob> jobs = picturesOf(results);
  std::vector<PictureOutcome> outcomes(jobs.size());
  std::vector<std::optional<RenderedSurface>> rendered(jobs.size());
  if (!jobs.empty()) {
    gpu::RenderTarget target(*context, settings.size_px, settings.size_px);
    std::mutex target_mutex;
    tbb::parallel_for(
        size_t(0), jobs.size(),
        [&](size_t i) {
          outcomes[i] = renderSurface(jobs[i], settings, target, target_mutex, &rendered[i]);
        },
        tbb::simple_partitioner());
  }
  // One colour scale per asset: the largest error of its pictures (at least
  // kMinimumScaleMax), so its techniques' pictures compare colour for colour.
  std::map<std::string, double> asset_scale;
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (!rendered[i]) continue;
    double& scale = asset_scale[outcomes[i].entry.asset];
    scale = std::max({scale, kMinimumScaleMax, rendered[i]->surface.error_max});
  }
  tbb::parallel_for(
      size_t(0), jobs.size(),
      [&](size_t i) {
        if (!rendered[i]) return;
        composePicture(std::move(*rendered[i]), settings, asset_scale[outcomes[i].entry.asset],
                       &outcomes[i]);
        rendered[i].reset();
      },
      tbb::simple_partitioner());
  for (PictureOutcome& outcome : outcomes) {
    if (outcome.entry.status == "ok") {
      write(outcome.entry.error_png, outcome.error_png);
      write(outcome.entry.wireframe_png, outcome.wireframe_png);
      if (!outcome.entry.crack_png.empty()) write(outcome.entry.crack_png, outcome.crack_png);
      index.png_bytes +=
          outcome.error_png.size() + outcome.wireframe_png.size() + outcome.crack_png.size();
    }
    index.pictures.push_back(std::move(outcome.entry));
  }
  write(kPicturesIndexPath, picturesIndexJson(index));
  index.wall_s = secondsSince(start);
  return index;
}

}  // namespace tb::pictures
