#include "harness/suite/suite.h"

#include <algorithm>
#include <cstdio>
#include <optional>

#include "core/mesh/obj_loader.h"
#include "techniques/registry.h"

namespace tb {
namespace {

std::string describeFaceKinds(const Mesh& mesh) {
  if (mesh.allFacesOfSize(3)) return "triangles";
  if (mesh.allFacesOfSize(4)) return "quads";
  return "mixed (max " + std::to_string(mesh.maxFaceSize()) + " vertices)";
}

struct LoadedAsset {
  AssetRef ref;
  Mesh mesh;
};

void formatParameters(const VariantInfo& variant, std::map<std::string, std::string>* out) {
  for (const auto& [key, value] : variant.parameters) {
    // Shortest text that round-trips, so the JSON stays byte-stable.
    char text[32];
    double parsed = 0;
    for (int precision = 1; precision <= 17; ++precision) {
      std::snprintf(text, sizeof(text), "%.*g", precision, value);
      std::sscanf(text, "%lf", &parsed);
      if (parsed == value) break;
    }
    (*out)[key] = text;
  }
}

}  // namespace

void runSuite(const SuiteSelection& selection, const ProgressFn& progress, Results* results) {
  std::vector<const Technique*> techniques = selection.techniques;
  if (techniques.empty()) techniques = TechniqueRegistry::instance().all();
  std::vector<const Measure*> measures = selection.measures;
  if (measures.empty()) measures = MeasureRegistry::instance().all();
  for (const Measure* measure : measures) {
    results->measures.push_back(declarationOf(measure->info()));
  }
  std::sort(results->measures.begin(), results->measures.end(),
            [](const MeasureDeclaration& a, const MeasureDeclaration& b) {
              return a.measure < b.measure;
            });
  std::vector<AssetRef> refs = selection.assets;
  if (refs.empty()) refs = bundledAssets();

  // One Vulkan device for the whole run (GPU measures share it); its absence is a reason
  // each GPU measure reports, never an abort.
  std::unique_ptr<gpu::Context> gpu_context;
  std::string gpu_unavailable;
  {
    gpu::ContextOptions options;
    options.device_name = selection.device_name;
    auto created = gpu::Context::create(options);
    if (created) {
      gpu_context = std::move(created.value());
    } else {
      gpu_unavailable = created.error();
    }
  }

  std::vector<LoadedAsset> assets;
  for (const AssetRef& ref : refs) {
    Mesh mesh = loadObjFile(ref.path);
    results->assets.push_back({ref.name, ref.path, mesh.faceCount(), mesh.positions.size(),
                               describeFaceKinds(mesh), mesh.normals_computed});
    assets.push_back({ref, std::move(mesh)});
  }

  size_t total = 0;
  for (const Technique* technique : techniques) total += technique->variants().size() * assets.size();
  size_t done = 0;
  for (const Technique* technique : techniques) {
    const std::vector<VariantInfo> variants = technique->variants();
    // The default variant's patch data per asset, for dependsOnPatchData measures.
    std::vector<std::optional<DataFootprint>> default_footprint(assets.size());
    for (size_t v = 0; v < variants.size(); ++v) {
      const VariantInfo& variant = variants[v];
      const bool is_default = v == 0;
      for (size_t a = 0; a < assets.size(); ++a) {
        const LoadedAsset& asset = assets[a];
        if (progress) {
          progress(done, total, technique->info().id + "/" + variant.name + " " + asset.ref.name);
        }
        ++done;
        // Measures that may apply: every one on the default variant; on the others the
        // variant-dependent ones, and those following the patch data once known.
        bool any_applies = false;
        for (const Measure* measure : measures) {
          any_applies |= measure->appliesTo(*technique) &&
                         (is_default || measure->dependsOnVariant() ||
                          (measure->dependsOnPatchData() && default_footprint[a]));
        }
        if (!any_applies) continue;
        if (std::string reason = technique->checkSupport(asset.mesh); !reason.empty()) {
          if (is_default) results->skipped.push_back({technique->info().id, asset.ref.name, reason});
          continue;
        }
        std::unique_ptr<SurfacePatches> patches;
        if (technique->info().family == TechniqueFamily::kSurface) {
          try {
            patches = technique->buildPatches(asset.mesh, variant);
          } catch (const UnsupportedInput& unsupported) {
            if (is_default) {
              results->skipped.push_back({technique->info().id, asset.ref.name, unsupported.what()});
            }
            continue;
          }
        }
        if (patches && is_default) default_footprint[a] = patches->footprint();
        const bool own_patch_data = is_default || (patches && default_footprint[a] &&
                                                   patches->footprint() != *default_footprint[a]);
        std::vector<const Measure*> applicable;
        for (const Measure* measure : measures) {
          if (measure->appliesTo(*technique) &&
              (is_default || measure->dependsOnVariant() ||
               (measure->dependsOnPatchData() && own_patch_data))) {
            applicable.push_back(measure);
          }
        }
        if (applicable.empty()) continue;
        Record record;
        record.technique = technique->info().id;
        record.variant = variant.name;
        record.asset = asset.ref.name;
        formatParameters(variant, &record.parameters);
        if (patches) record.warnings = patches->warnings();
        const MeasureInput input{*technique,     variant,           asset.ref.name,
                                 asset.mesh,     patches.get(),     gpu_context.get(),
                                 gpu_unavailable};
        for (const Measure* measure : applicable) record.measures.push_back(measure->run(input));
        results->records.push_back(std::move(record));
      }
    }
  }
  if (progress) progress(total, total, "done");
}

}  // namespace tb
