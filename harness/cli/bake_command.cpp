#include "harness/cli/bake_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>

#include "core/mesh/obj_loader.h"
#include "harness/bake/analytic_target.h"
#include "harness/bake/bake_sidecar.h"
#include "harness/bake/baker.h"
#include "harness/cli/usage_error.h"
#include "harness/measures/error/error.h"
#include "harness/suite/asset_catalog.h"
#include "techniques/registry.h"

namespace tb::cli {
namespace {

const techniques::Technique& techniqueNamed(const std::string& id) {
  const techniques::Technique* technique = techniques::TechniqueRegistry::instance().find(id);
  if (technique != nullptr && technique->info().family == techniques::TechniqueFamily::kSurface) {
    return *technique;
  }
  std::string known;
  for (const techniques::Technique* t : techniques::TechniqueRegistry::instance().all()) {
    if (t->info().family != techniques::TechniqueFamily::kSurface) continue;
    known += (known.empty() ? "" : ", ") + t->info().id;
  }
  throw UsageError("--technique", id, "unknown surface technique (known: " + known + ")");
}

techniques::VariantInfo variantNamed(const techniques::Technique& technique,
                                     const std::string& name) {
  const std::vector<techniques::VariantInfo> variants = technique.variants();
  if (name.empty() && !variants.empty()) return variants.front();
  std::string known;
  for (const techniques::VariantInfo& variant : variants) {
    if (variant.name == name) return variant;
    known += (known.empty() ? "" : ", ") + variant.name;
  }
  throw UsageError("--variant", name,
                   "unknown variant of " + technique.info().id + " (known: " + known + ")");
}

void refuseExisting(const std::string& option, const std::string& path) {
  if (std::filesystem::exists(path)) {
    throw UsageError(option, path, "the file exists already (never overwritten)");
  }
}

// Every check that needs no computation, so bad input fails before any work.
bake::BakeSettings checkedSettings(const BakeArgs& args) {
  if (args.analytic == !args.target.empty()) {
    throw UsageError("--target/--analytic", "",
                     "give exactly one of --target MESH.obj or --analytic");
  }
  if (!args.write_target.empty() && !args.analytic) {
    throw UsageError("--write-target", args.write_target, "needs --analytic");
  }
  if (args.layout == "uv") {
    throw UsageError("--layout", "uv", "the uv layout is not built yet (use tiles)");
  }
  refuseExisting("--out", args.out);
  refuseExisting("--out", bake::sidecarPath(args.out));
  if (!args.write_target.empty()) refuseExisting("--write-target", args.write_target);
  bake::BakeSettings settings;
  settings.kind = args.kind == "vector" ? displacement::DisplacementKind::kVector
                                        : displacement::DisplacementKind::kScalar;
  settings.resolution = args.resolution;
  settings.layout = displacement::DisplacementLayout::kTiles;
  settings.pixel_type = args.pixel_type == "float" ? displacement::DisplacementPixelType::kFloat
                                                   : displacement::DisplacementPixelType::kHalf;
  return settings;
}

}  // namespace

CLI::App* addBakeCommand(CLI::App& app, BakeArgs& args) {
  CLI::App* bake = app.add_subcommand(
      "bake",
      "bake a displacement map (OpenEXR + FILE.exr.json sidecar) for a technique's surface "
      "against a detailed target mesh or the analytic oracle target (a displaced limit surface)");
  bake->add_option("--technique", args.technique, "surface technique id")->required();
  bake->add_option("--variant", args.variant, "variant name (default: the technique's first)");
  bake->add_option("--asset", args.asset, "bundled asset name or OBJ path")->required();
  bake->add_option("--out", args.out, "the map, FILE.exr (must not exist yet)")->required();
  bake->add_option("--target", args.target, "the detailed target mesh (OBJ)");
  bake->add_flag("--analytic", args.analytic,
                 "the analytic target: the asset's limit surface displaced along its normal by "
                 "a sum of sines of the limit position");
  bake->add_option(
          "--pixel-type", args.pixel_type,
          "half (16-bit, what a game ships) | float (32-bit) texels in the EXR and on the GPU")
      ->check(CLI::IsMember({"half", "float"}))
      ->capture_default_str();
  bake->add_option("--kind", args.kind,
                   "scalar (distance along the normal, rays both ways) | vector (closest point "
                   "minus surface point)")
      ->check(CLI::IsMember({"scalar", "vector"}))
      ->capture_default_str();
  bake->add_option("--resolution", args.resolution,
                   "texels per patch side, both edges included (2 to 1024)")
      ->check(CLI::Range(1u, bake::kMaxBakeResolution))
      ->capture_default_str();
  bake->add_option("--layout", args.layout, "tiles (per-patch atlas) | uv (not built yet)")
      ->check(CLI::IsMember({"tiles", "uv"}))
      ->capture_default_str();
  bake->add_option("--target-rate", args.target_rate,
                   "the analytic target's tessellation rate (segments per limit face edge)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  bake->add_option("--write-target", args.write_target,
                   "with --analytic: also write the analytic target mesh as OBJ (must not exist)");
  return bake;
}

int runBake(const BakeArgs& args) {
  const bake::BakeSettings settings = checkedSettings(args);
  const techniques::Technique& technique = techniqueNamed(args.technique);
  const techniques::VariantInfo variant = variantNamed(technique, args.variant);
  const suite::AssetRef asset = suite::resolveAsset(args.asset);
  mesh::Mesh mesh = suite::loadAsset(asset);
  mesh.source = asset.shownPath();
  if (std::string reason = technique.checkSupport(mesh); !reason.empty()) {
    throw techniques::UnsupportedInput(reason);
  }
  const techniques::BuiltSurface patches = techniques::buildSurface(technique, mesh, variant);
  const auto start = std::chrono::steady_clock::now();

  bake::BakeProvenance provenance{technique.info().id, variant.name, asset.name, ""};
  std::optional<ref::LimitTessellation> analytic;
  mesh::Mesh target_obj;
  std::vector<ref::Triangle> target_triangles;
  ref::TriangleMeshRef target;
  if (args.analytic) {
    const bake::AnalyticDisplacement h = bake::analyticDisplacementFor(patches->controlMesh());
    analytic = bake::analyticTargetMesh(
        patches->controlMesh(), lod::referenceScheme(patches->approximates()), args.target_rate, h);
    provenance.target =
        fmt::format("analytic: {}, limit tessellation rate {}", h.describe(), args.target_rate);
    target = analytic->view();
    provenance.target_rate = args.target_rate;
  } else {
    target_obj = mesh::loadObjFile(args.target);
    target_triangles = ref::fanTriangles(target_obj);
    target = {target_obj.positions, target_triangles};
    provenance.target = args.target;
    provenance.target_path = std::filesystem::absolute(args.target).lexically_normal().string();
  }
  const bake::BakeResult result =
      bake::bakeDisplacement(*patches, target, settings, provenance.target);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  bake::writeBake(args.out, result, bake::bakeSidecar(provenance, settings, result));
  if (analytic && !args.write_target.empty()) {
    bake::writeTriangleObj(args.write_target, *analytic, provenance.target);
  }
  fmt::print("{}: {} x {} {} map, {} texels baked, {} missed, {:.3f} s; sidecar {}\n", args.out,
             result.map.width, result.map.height, displacement::kindName(result.map.kind),
             result.texels_baked, result.rays_missed, seconds, bake::sidecarPath(args.out));
  return 0;
}

namespace {

SubcommandRun addBake(CLI::App& app) {
  auto args = std::make_shared<BakeArgs>();
  addBakeCommand(app, *args);
  return [args](const Invocation&) { return runBake(*args); };
}

}  // namespace

const Subcommand kBakeSubcommand{"bake", addBake};

}  // namespace tb::cli
