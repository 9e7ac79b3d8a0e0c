// The measure interface. A measure turns one technique × variant × asset into a
// MeasureResult of the results model; it registers itself like a technique.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/gpu/context.h"
#include "core/mesh/mesh.h"
#include "harness/results/results_model.h"
#include "techniques/technique.h"

namespace tb {

// What a measure is and what it emits, declared once: reports and compare read this
// (through the MeasureDeclaration each run writes to results.json), never the measure's id.
struct MeasureInfo {
  std::string id;           // "memory"
  std::string title;        // "Memory footprint against plain triangle meshes"
  std::string description;  // one line: what is measured, in which units
  // Every metric a row may emit, in emission order (a MetricTable's specs()).
  std::vector<MetricSpec> metrics;
  // Names from `metrics` that a summary shows first, most important first; each has a
  // direction (a headline ranks techniques), so never a Direction::kNone context figure.
  std::vector<std::string> headline;
  // Notes true of every record (definitions, method), shown once under the measure;
  // a note about one record goes in its MeasureResult::notes.
  std::vector<std::string> notes;
};

MeasureDeclaration declarationOf(const MeasureInfo& info);

struct MeasureInput {
  const Technique& technique;
  const VariantInfo& variant;
  const std::string& asset_name;
  const Mesh& mesh;                 // the asset as loaded
  const SurfacePatches* patches;    // built for this variant; null for simulation techniques
  // The run's Vulkan device, or null when none is usable; then gpu_unavailable says why
  // and GPU measures report themselves skipped with that reason.
  gpu::Context* gpu = nullptr;
  std::string gpu_unavailable;
};

class Measure {
 public:
  virtual ~Measure() = default;
  virtual const MeasureInfo& info() const = 0;
  virtual bool appliesTo(const Technique& technique) const = 0;
  // False when every variant gives the same figures (e.g. memory for phong's α):
  // the suite then measures the default variant only.
  virtual bool dependsOnVariant() const = 0;
  // True when the figures follow the patch data alone (memory): the suite then also
  // measures each other variant whose SurfacePatches::footprint() differs from the
  // default variant's on the asset (gregory_acc/quads_only: 3 quads per triangle).
  virtual bool dependsOnPatchData() const { return false; }
  virtual MeasureResult run(const MeasureInput& input) const = 0;
};

class MeasureRegistry {
 public:
  static MeasureRegistry& instance();
  bool add(std::unique_ptr<Measure> measure);
  const Measure* find(std::string_view id) const;
  std::vector<const Measure*> all() const;  // sorted by id

 private:
  std::vector<std::unique_ptr<Measure>> measures_;
};

#define TB_REGISTER_MEASURE_CONCAT2(a, b) a##b
#define TB_REGISTER_MEASURE_CONCAT(a, b) TB_REGISTER_MEASURE_CONCAT2(a, b)
#define TB_REGISTER_MEASURE(Class)                                                        \
  static const bool TB_REGISTER_MEASURE_CONCAT(tb_measure_registered_, __LINE__) [[maybe_unused]] = \
      ::tb::MeasureRegistry::instance().add(std::make_unique<Class>())

}  // namespace tb
