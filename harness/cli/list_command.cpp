#include "harness/cli/list_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/gpu/context.h"
#include "harness/cli/usage_error.h"
#include "harness/measures/measure.h"
#include "harness/results/results_json.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/scenario_file.h"
#include "techniques/registry.h"

namespace tb::cli {

namespace {

// The Vulkan devices, default first, each with its identity (the string results.json, timings
// and benchmark JSON name it by) and whether it can run the GPU measures.
void listDevices(bool json, nlohmann::ordered_json* items) {
  std::string reason;
  const std::vector<gpu::DeviceInfo> devices = gpu::listDevices(&reason);
  if (devices.empty() && !json) fmt::print("no Vulkan device: {}\n", reason);
  for (size_t i = 0; i < devices.size(); ++i) {
    const gpu::DeviceInfo& d = devices[i];
    const std::string missing = gpu::firstMissingFeature(d.features, gpu::tessCaptureFeatures());
    items->push_back({{"name", d.device_name},
                      {"type", d.device_type},
                      {"driver", d.driver_name + " " + d.driver_info},
                      {"vulkan", d.api_version},
                      {"identity", gpu::describeDevice(d)},
                      {"default", i == 0},
                      {"gpu_measures", missing.empty() ? "yes" : "no: lacks " + missing}});
    if (!json) {
      fmt::print("{:<40} {:<15} {} {}, Vulkan {}{}{}\n", d.device_name, d.device_type,
                 d.driver_name, d.driver_info, d.api_version, i == 0 ? " (default)" : "",
                 missing.empty() ? "" : "; cannot run the GPU measures: lacks " + missing);
    }
  }
}

}  // namespace

CLI::App* addListCommand(CLI::App& app, ListArgs& args) {
  CLI::App* list =
      app.add_subcommand("list", "list techniques, assets, scenarios, measures or devices");
  list->add_option("what", args.what,
                   "techniques | assets | scenarios | measures | devices (the Vulkan devices, "
                   "default first: what `run --device` names)")
      ->required()
      ->check(CLI::IsMember({"techniques", "assets", "scenarios", "measures", "devices"}));
  list->add_flag("--json", args.json, "print JSON");
  return list;
}

int runList(const ListArgs& args) {
  nlohmann::ordered_json items = nlohmann::ordered_json::array();
  if (args.what == "techniques") {
    for (const techniques::Technique* t : techniques::TechniqueRegistry::instance().all()) {
      const techniques::TechniqueInfo& info = t->info();
      nlohmann::ordered_json variants = nlohmann::ordered_json::array();
      nlohmann::ordered_json controls = nlohmann::ordered_json::array();
      for (const techniques::VariantInfo& v : t->variants()) {
        variants.push_back(v.name);
        if (!v.control.empty()) controls.push_back({{"variant", v.name}, {"shows", v.control}});
      }
      items.push_back({{"id", info.id},
                       {"family", toString(info.family)},
                       {"title", info.title},
                       {"citation", info.citation},
                       {"input", info.input},
                       {"variants", variants},
                       {"controls", controls}});
      if (!args.json)
        fmt::print("{:<16} {:<10} {} — {}\n", info.id, toString(info.family), info.title,
                   info.citation);
    }
  } else if (args.what == "assets") {
    // The production assets too: bundled shapes refined at load (their path says so).
    for (const suite::AssetRef& asset : suite::suiteAssets(true)) {
      items.push_back({{"name", asset.name}, {"path", asset.path}, {"refine", asset.refine}});
      if (!args.json) {
        fmt::print("{:<40} {}\n", asset.name, asset.refine == 0 ? asset.path : asset.label);
      }
    }
  } else if (args.what == "scenarios") {
    for (const techniques::Scenario& scenario : suite::bundledScenarios()) {
      items.push_back({{"name", scenario.name},
                       {"technique", scenario.technique},
                       {"path", scenario.path},
                       {"time_step_s", scenario.time_step_s},
                       {"duration_s", scenario.duration_s}});
      if (!args.json)
        fmt::print("{:<28} {:<16} {}\n", scenario.name, scenario.technique, scenario.path);
    }
  } else if (args.what == "measures") {
    for (const measures::Measure* m : measures::MeasureRegistry::instance().all()) {
      const measures::MeasureInfo& info = m->info();
      // The declaration: id, title, description, headline, fixed notes, metrics (unit, direction).
      nlohmann::ordered_json item = results::toJson(measures::declarationOf(info));
      item.erase("measure");
      items.push_back({{"id", info.id}});
      items.back().update(item);
      if (!args.json) fmt::print("{:<16} {} — {}\n", info.id, info.title, info.description);
    }
  } else if (args.what == "devices") {
    listDevices(args.json, &items);
  } else {
    throw UsageError("list", args.what,
                     "expected techniques, assets, scenarios, measures or devices");
  }
  if (args.json) fmt::print("{}\n", items.dump(2));
  return 0;
}

namespace {

SubcommandRun addList(CLI::App& app) {
  auto args = std::make_shared<ListArgs>();
  addListCommand(app, *args);
  return [args](const Invocation&) { return runList(*args); };
}

}  // namespace

const Subcommand kListSubcommand{"list", addList};

}  // namespace tb::cli
