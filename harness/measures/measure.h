// The measure interface. A measure turns one technique × variant × asset into a
// MeasureResult of the results model; it registers itself like a technique.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/gpu/context.h"
#include "core/mesh/mesh.h"
#include "core/mesh/registry.h"
#include "core/view/camera_path_views.h"
#include "core/view/view.h"
#include "harness/measures/displaced_input.h"
#include "harness/results/results_model.h"
#include "techniques/technique.h"

namespace tb::measures {

// What a measure is and what it emits, declared once: reports and compare read this
// (through the MeasureDeclaration each run writes to results.json), never the measure's id.
// A measure's declaration, written with designated initialisers:
// MeasureInfo{.id = "memory", .title = ..., .metrics = table.specs(), .headline = {...}}.
struct MeasureInfo {
  std::string id = {};           // "memory"
  std::string title = {};        // "Memory footprint against plain triangle meshes"
  std::string description = {};  // one line: what is measured, in which units
  // Every metric a row may emit, in emission order (a MetricTable's specs()).
  std::vector<results::MetricSpec> metrics = {};
  // Names from `metrics` that a summary shows first, most important first; each has a
  // direction (a headline ranks techniques), so never a Direction::kNone context figure.
  std::vector<std::string> headline = {};
  // Notes true of every record (what is measured and how, a few sentences linking
  // docs/derivations/); a note about one record goes in its MeasureResult::notes.
  std::vector<std::string> notes = {};
  // The rows a summary aggregates (MeasureDeclaration::summary_scope); empty: every ok row.
  results::RowScope summary_scope = {};
  // The charts report.html draws of this measure's rows (MeasureDeclaration::plots).
  std::vector<results::PlotSpec> plots = {};
  // Rows made to show a failure (MeasureDeclaration::control_rows): never recommended.
  std::vector<results::RowScope> control_rows = {};
  // The side-by-side tables and bar charts opening its report sections.
  std::vector<results::ComparisonSpec> comparisons = {};
  // The figures the decision, `advise`, the answers and the tables may read of its rows
  // (results::DecisionInput): harness/report finds them by role, never by name.
  std::vector<results::DecisionInput> decision_inputs = {};
  // The shader-db summary `compare` prints of its rows (MeasureDeclaration::shader_db).
  results::ShaderDbSpec shader_db = {};
};

// What a measure needs from a technique instance and the run. The suite runs a measure
// only where every need is met (harness/suite/measure_rule.h), so a measure that needs a
// surface always gets MeasureInput::patches non-null, and so on.
enum class MeasureNeed : uint8_t {
  kSurface,     // MeasureInput::patches (TechniqueInstance::surface())
  kSimulation,  // MeasureInput::simulation (TechniqueInstance::simulation())
  // Either capability: the measure applies to both families (memory, instructions) and reads
  // MeasureInput::patches or MeasureInput::simulation, whichever is non-null (a simulation
  // is freshly built for it, as for kSimulation).
  kSurfaceOrSimulation,
  // MeasureInput::view: the suite runs the measure once per view of each camera path and
  // adds the row keys "camera_path" and "view" (the view's index on the path) to its rows.
  kView,
  // MeasureInput::camera_path: the suite runs the measure once per camera path, with the
  // whole path, and adds the row key "camera_path" (the path's name) to its rows; the
  // measure keys its rows by frame itself. A measure declares kView or kCameraPath, not
  // both (kCameraPath wins).
  kCameraPath,
  // MeasureInput::gpu: the run's Vulkan device. Never a reason not to run: without a
  // device the measure reports its GPU parts skipped with gpu_unavailable, as it would.
  kGpu,
  // Optional simulation capabilities (techniques/simulation.h), declared beside kSimulation:
  // the technique's simulationCapabilities() promise them and MeasureInput::simulation
  // returns them non-null (Simulation::constraintSolver(), Simulation::waveField()).
  kConstraintSolver,  // convergence, stability
  kWaveField,         // wave_error
};

// Which grid of parameters a measure runs (`tessbench run --suite`): the default suite
// stays within the run-time budget (docs/ARCHITECTURE.md, section 3); the full suite is
// every level, path and policy a measure knows.
enum class SuiteMode : uint8_t { kDefault, kFull };

// "default" or "full": the --suite value and results.json's context.selection.suite.
inline const char* toString(SuiteMode mode) {
  return mode == SuiteMode::kFull ? "full" : "default";
}

// Which variants of a technique a measure runs on, on an asset it applies to.
enum class VariantPolicy : uint8_t {
  kDefaultOnly,   // the figures are the same for every variant (published_figures)
  kEveryVariant,  // the figures follow the variant (errors, cracks, instruction counts)
  // The figures follow the patch data alone (memory): the default variant, and each other
  // variant whose SurfacePatches::footprint() differs from the default's on the asset
  // (gregory_acc/quads_only: 3 quads per triangle; phong/edge: per-edge normals). Every
  // variant of a simulation (each keeps its own state).
  kWhenPatchDataDiffers,
  // The default variant in the default suite, every variant in --suite full (culling: the
  // figures follow the variant, but a frame costs a render and a device run per policy).
  kEveryVariantInFullSuite,
  // Every variant whose surface differs from the default's; in --suite full every variant
  // (error: a variant that only reorders the float evaluation has the default's figures).
  kEveryDistinctSurface,
};

// A measure's whole declaration of where it runs.
struct MeasureRequirements {
  std::vector<MeasureNeed> needs;
  VariantPolicy variants = VariantPolicy::kDefaultOnly;
  // Narrows the techniques further when the needs alone do not say it (published_figures needs
  // the technique's own probe shader); empty: every technique whose instances meet the needs.
  std::function<bool(const techniques::Technique&)> technique_filter;
  // The measure also runs on displaced surfaces (`run --displacement`, bundled maps): the
  // suite then hands it a DisplacedPatches and MeasureInput::displacement, and adds the row
  // keys `displacement` and `sampling`. Other measures never see a displaced surface.
  bool displaced_surfaces = false;
  // The figures follow the technique × variant, not the input (the ISA measure's compiled
  // shaders): the suite runs the measure on the technique's first supported input alone.
  bool first_input_only = false;
  bool has(MeasureNeed need) const {
    return std::find(needs.begin(), needs.end(), need) != needs.end();
  }
};
results::MeasureDeclaration declarationOf(const MeasureInfo& info);

struct MeasureInput {
  const techniques::Technique& technique;
  const techniques::VariantInfo& variant;
  const std::string& asset_name;  // the asset's name, or the scenario's for a simulation
  const mesh::Mesh& mesh;         // the asset as loaded (empty for a scenario)
  // The surface capability, built for this variant; non-null when the measure needs kSurface.
  const techniques::SurfacePatches* patches;
  // The run's Vulkan device, or null when none is usable; then gpu_unavailable says why
  // and GPU measures report themselves skipped with that reason.
  gpu::Context* gpu = nullptr;
  std::string gpu_unavailable;
  // The simulation capability, freshly built for this measure (at time 0); non-null when
  // the measure needs kSimulation. The measure may step it.
  techniques::Simulation* simulation = nullptr;
  // The camera view; non-null when the measure needs kView.
  const view::View* view = nullptr;
  // The whole camera path; non-null when the measure needs kCameraPath.
  const view::CameraPath* camera_path = nullptr;
  // The run's suite: a measure picks its default or full grid by it.
  SuiteMode suite = SuiteMode::kDefault;
  // Only the figures a decision reads (`advise`): a measure may leave out the context figures
  // that cost most and decide nothing (memory: the compressed baseline).
  bool decision_figures_only = false;
  // Non-null when `patches` is displaced by a map (measures with displaced_surfaces only).
  const DisplacementRun* displacement = nullptr;
};

// Whether a measure runs the compute path (core/gpu/compute_path.h) for this input beside the
// tessellator's: --suite full on every asset; the default suite on one quad and one triangle
// mesh with extraordinary vertices (kDefaultComputeAssets), to keep within its budget. Never
// on a displaced surface (the compute path does not displace yet).
inline constexpr const char* kDefaultComputeAssets[] = {"opensubdiv/catmark_xord_interior",
                                                        "opensubdiv/loop_xord_interior"};
bool runsComputePath(const MeasureInput& input);

// Precondition of a kCameraPath measure's run(): the path its needs promise (the suite always sets
// them; a caller outside the suite, a benchmark or a test, may not). Throws std::invalid_argument
// naming the missing input, which the suite turns into an error row, instead of a crash.
const view::CameraPath& requireCameraPath(const MeasureInput& input);

class Measure {
 public:
  virtual ~Measure() = default;
  virtual const MeasureInfo& info() const = 0;
  virtual MeasureRequirements requirements() const = 0;
  virtual results::MeasureResult run(const MeasureInput& input) const = 0;
  // kCameraPath measures: one result per path of `paths`, in order, each as run() gives it
  // with input.camera_path set to that path (the suite keys the rows by path). A measure
  // whose set-up does not depend on the path overrides it to build that set-up once.
  virtual std::vector<results::MeasureResult> runPaths(
      MeasureInput input, std::span<const view::CameraPath> paths) const {
    std::vector<results::MeasureResult> out;
    for (const view::CameraPath& path : paths) {
      input.camera_path = &path;
      out.push_back(run(input));
    }
    return out;
  }
  // kCameraPath measures: the bundled paths (name, frames; 0 = the file's own count) the
  // measure runs along in the default suite when the run names no --camera. Empty: the
  // suite's default path (orbit at 4 frames). --suite full always runs every bundled path.
  virtual std::vector<std::pair<std::string, uint32_t>> defaultSuitePaths() const { return {}; }
};

// add, find and all() (sorted by id): mesh::Registry.
class MeasureRegistry : public mesh::Registry<Measure> {
 public:
  static MeasureRegistry& instance();
};

#define TB_REGISTER_MEASURE_CONCAT2(a, b) a##b
#define TB_REGISTER_MEASURE_CONCAT(a, b) TB_REGISTER_MEASURE_CONCAT2(a, b)
#define TB_REGISTER_MEASURE(Class)                                               \
  static const bool TB_REGISTER_MEASURE_CONCAT(tb_measure_registered_, __LINE__) \
      [[maybe_unused]] =                                                         \
          ::tb::measures::MeasureRegistry::instance().add(std::make_unique<Class>())

}  // namespace tb::measures
