// The "memory" measure: measureMemory at levels 8, 16, 32, 64, with meshoptimizer's
// compressed plain mesh as a second baseline.
#include <meshoptimizer.h>

#include <optional>
#include <string>
#include <vector>

#include "core/gpu/patch_program_desc.h"
#include "harness/measures/measure.h"
#include "harness/measures/memory/memory.h"
#include "harness/measures/metric_table.h"

namespace tb::measures {
namespace {

// One row: the level's figures, the patch count, and the compressed baseline.
struct MemoryRowFigures {
  MemoryFigures memory;
  uint64_t patches = 0;
  // The compressed plain mesh; none on displaced surfaces (the baseline is the undisplaced
  // record's, and building it again per sampling would double the measure's cost).
  std::optional<CompressedSize> compressed;
  std::optional<uint64_t> map_file_bytes = {};  // displaced surfaces: the EXR on disk
  // The compute path's transient output (rows with path = compute); none on the tessellator
  // path's rows, which hold none (0).
  std::optional<TransientFigures> transient = {};
};

// The compute path's figures (core/gpu/compute_path.h), after the table's own.
std::vector<MetricField<MemoryRowFigures>> transientFields() {
  using D = results::Direction;
  using R = MemoryRowFigures;
  return {
      // transient_vertex_bytes: bytes; 0 on the tessellator path (best: its points stream
      //   from the TES to the rasteriser), unbounded (worst); the compute path's vertex buffer
      {"transient_vertex_bytes", results::Unit::kBytes, D::kLowerIsBetter,
       [](const R& r) { return r.transient ? double(r.transient->vertex_bytes) : 0.0; }},
      // transient_index_bytes: bytes; 0 on the tessellator path (best), unbounded (worst)
      {"transient_index_bytes", results::Unit::kBytes, D::kLowerIsBetter,
       [](const R& r) { return r.transient ? double(r.transient->index_bytes) : 0.0; }},
      // transient_over_plain: ratio; 0 on the tessellator path (best), about 1.5 to 2.5 on the
      //   compute path (its unwelded 40-byte records against the plain mesh's welded 32-byte
      //   vertices; worst: unbounded)
      {"transient_over_plain", results::Unit::kRatio, D::kLowerIsBetter,
       [](const R& r) {
         return r.transient ? double(r.transient->bytes()) / double(r.memory.plain_bytes) : 0.0;
       }},
  };
}

// The plain and compressed meshes are the baselines (context); the technique's own bytes
// are better lower; plain_over_* and compressed_over_technique above 1 mean the technique
// is the smaller, so higher is better.
const MetricTable<MemoryRowFigures>& memoryTable() {
  using D = results::Direction;
  using R = MemoryRowFigures;
  auto field = [](auto MemoryFigures::*member) {
    return [member](const R& r) { return double(r.memory.*member); };
  };
  auto footprint = [](uint64_t techniques::DataFootprint::*member) {
    return [member](const R& r) { return double(r.memory.technique.*member); };
  };
  static const MetricTable<R> kTable{
      {
          // plain_vertices: count; context: the welded plain mesh's vertices at the level
          {"plain_vertices", results::Unit::kCount, D::kNone,
           field(&MemoryFigures::plain_vertices)},
          // plain_triangles: count; context
          {"plain_triangles", results::Unit::kCount, D::kNone,
           field(&MemoryFigures::plain_triangles)},
          // plain_bytes: bytes; context: the plain mesh (32 B vertices, 32-bit indices)
          {"plain_bytes", results::Unit::kBytes, D::kNone, field(&MemoryFigures::plain_bytes)},
          // control_mesh_bytes: bytes; 0 (best), unbounded (worst)
          {"control_mesh_bytes", results::Unit::kBytes, D::kLowerIsBetter,
           footprint(&techniques::DataFootprint::control_mesh_bytes)},
          // patch_data_bytes: bytes; 0 (best), unbounded (worst)
          {"patch_data_bytes", results::Unit::kBytes, D::kLowerIsBetter,
           footprint(&techniques::DataFootprint::patch_data_bytes)},
          // stencil_bytes: bytes; 0 (best), unbounded (worst)
          {"stencil_bytes", results::Unit::kBytes, D::kLowerIsBetter,
           footprint(&techniques::DataFootprint::stencil_bytes)},
          // topology_combinations: count; 1 (best) when every patch shares one weight table, 0
          // without
          //   classes, up to patches (worst)
          {"topology_combinations", results::Unit::kCount, D::kLowerIsBetter,
           footprint(&techniques::DataFootprint::topology_combinations)},
          // patches: count; context
          {"patches", results::Unit::kCount, D::kNone, &R::patches},
          // displacement_bytes: bytes; 0 (best), unbounded (worst); a 16-bit scalar map sized for
          // the
          //   level
          {"displacement_bytes", results::Unit::kBytes, D::kLowerIsBetter,
           field(&MemoryFigures::displacement_bytes)},
          // technique_with_displacement_bytes: bytes; 0 (best), unbounded (worst)
          {"technique_with_displacement_bytes", results::Unit::kBytes, D::kLowerIsBetter,
           field(&MemoryFigures::technique_with_displacement_bytes)},
          // plain_over_technique: ratio; above 1 the technique is smaller (better, unbounded),
          // towards
          //   0 (worst)
          {"plain_over_technique", results::Unit::kRatio, D::kHigherIsBetter,
           field(&MemoryFigures::plain_over_technique)},
          // vector_displacement_bytes: bytes; 0 (best), unbounded (worst); 3 x 16 bits per texel
          {"vector_displacement_bytes", results::Unit::kBytes, D::kLowerIsBetter,
           field(&MemoryFigures::vector_displacement_bytes)},
          // technique_with_vector_displacement_bytes: bytes; 0 (best), unbounded (worst)
          {"technique_with_vector_displacement_bytes", results::Unit::kBytes, D::kLowerIsBetter,
           field(&MemoryFigures::technique_with_vector_displacement_bytes)},
          // plain_over_technique_vector: ratio; above 1 the technique is smaller (better,
          // unbounded),
          //   towards 0 (worst)
          {"plain_over_technique_vector", results::Unit::kRatio, D::kHigherIsBetter,
           field(&MemoryFigures::plain_over_technique_vector)},
          // compressed_vertex_bytes: bytes; context: the meshoptimizer-compressed plain mesh's
          // vertices
          {"compressed_vertex_bytes", results::Unit::kBytes, D::kNone,
           [](const R& r) -> std::optional<double> {
             if (!r.compressed) return std::nullopt;
             return double(r.compressed->vertex_bytes);
           }},
          // compressed_index_bytes: bytes; context
          {"compressed_index_bytes", results::Unit::kBytes, D::kNone,
           [](const R& r) -> std::optional<double> {
             if (!r.compressed) return std::nullopt;
             return double(r.compressed->index_bytes);
           }},
          // compressed_bytes: bytes; context
          {"compressed_bytes", results::Unit::kBytes, D::kNone,
           [](const R& r) -> std::optional<double> {
             if (!r.compressed) return std::nullopt;
             return double(r.compressed->bytes());
           }},
          // compressed_over_technique: ratio; above 1 the technique is smaller (better, unbounded),
          //   towards 0 (worst)
          {"compressed_over_technique", results::Unit::kRatio, D::kHigherIsBetter,
           [](const R& r) -> std::optional<double> {
             if (!r.compressed) return std::nullopt;
             return double(r.compressed->bytes()) /
                    double(r.memory.technique_with_displacement_bytes);
           }},
          // Displaced surfaces only: the map as a file (OpenEXR, ZIP), beside its GPU bytes.
          // map_file_bytes: bytes; 0 (best), unbounded (worst); the map as an OpenEXR file
          {"map_file_bytes", results::Unit::kBytes, D::kLowerIsBetter,
           [](const R& r) -> std::optional<double> {
             if (!r.map_file_bytes) return std::nullopt;
             return double(*r.map_file_bytes);
           }},
      },
      transientFields()};
  return kTable;
}

// Simulations: the bytes they keep resident (Simulation::footprint) against the alternative
// a user would pick for the same scenario (wave particles: a height-field grid solver at the
// output's resolution). alternative_over_simulation above 1: the simulation is the smaller.
const MetricTable<techniques::SimulationFootprint>& simulationTable() {
  using D = results::Direction;
  using F = techniques::SimulationFootprint;
  static const MetricTable<F> kTable{
      // state_bytes: bytes; 0 (best), unbounded (worst)
      {"state_bytes", results::Unit::kBytes, D::kLowerIsBetter, &F::state_bytes},
      // auxiliary_bytes: bytes; 0 (best), unbounded (worst)
      {"auxiliary_bytes", results::Unit::kBytes, D::kLowerIsBetter, &F::auxiliary_bytes},
      // simulation_bytes: bytes; 0 (best), unbounded (worst)
      {"simulation_bytes", results::Unit::kBytes, D::kLowerIsBetter,
       [](const F& f) { return double(f.total()); }},
      // alternative_bytes: bytes; context: the alternative a user would pick
      {"alternative_bytes", results::Unit::kBytes, D::kNone,
       [](const F& f) -> std::optional<double> {
         if (f.alternative_bytes == 0) return std::nullopt;
         return double(f.alternative_bytes);
       }},
      // alternative_over_simulation: ratio; above 1 the simulation is smaller (better, unbounded),
      //   towards 0 (worst)
      {"alternative_over_simulation", results::Unit::kRatio, D::kHigherIsBetter,
       [](const F& f) -> std::optional<double> {
         if (f.alternative_bytes == 0 || f.total() == 0) return std::nullopt;
         return double(f.alternative_bytes) / double(f.total());
       }},
  };
  return kTable;
}

std::vector<results::MetricSpec> memorySpecs() {
  std::vector<results::MetricSpec> specs = memoryTable().specs();
  for (const results::MetricSpec& spec : simulationTable().specs()) specs.push_back(spec);
  return specs;
}

// The highest level whose compressed baseline the default suite builds: levels 32 and 64 were
// nine tenths of the measure's time (the plain mesh of level 64 has 16 times level 16's
// points); --suite full builds every level's.
constexpr uint32_t kDefaultSuiteCompressedLevel = 16;

class MemoryMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        .id = "memory",
        .title = "Memory footprint against plain triangle meshes",
        .description =
            "bytes of the technique's data (plus a 16-bit displacement map) against the equivalent "
            "welded triangle mesh at uniform levels 8, 16, 32, 64",
        .metrics = memorySpecs(),
        .headline = {"plain_over_technique", "technique_with_displacement_bytes"},
        .notes =
            {"plain mesh: welded vertices of float3 position, float3 normal, float2 uv (32 B) and "
             "32-bit indices, with the tessellator's point and triangle counts",
             "displacement map: 16-bit, one texel per tessellated point of each patch; vector "
             "displacement: 3 x 16 bits per texel",
             "compressed: the plain mesh actually built (technique evaluated in float at the CPU "
             "tessellator's points, welded like plain_vertices, uv interpolated from the patch "
             "corners), vertex-cache and vertex-fetch optimised, then meshopt_encodeIndexBuffer + "
             "meshopt_encodeVertexBuffer on the raw 32-byte float vertices (meshoptimizer " +
                 std::to_string(MESHOPTIMIZER_VERSION / 1000) + "." +
                 std::to_string(MESHOPTIMIZER_VERSION % 1000 / 10) + "), per chunk of " +
                 std::to_string(kCompressChunkPatches) +
                 " patches in patch order (the whole mesh below that; points on an edge between "
                 "chunks stored in each), sizes summed; an asset of more than " +
                 std::to_string(kCompressSampleChunks) + " chunks (" +
                 std::to_string(kCompressSampleChunks * kCompressChunkPatches) +
                 " patches) is sampled: " + std::to_string(kCompressSampleChunks) +
                 " evenly spaced chunks built, their bytes scaled by patches (the record's note "
                 "says so; within 0.3 % of every chunk on the production assets); the default "
                 "suite builds it at levels 8 and 16, --suite full at every level",
             "NVIDIA's displacement subdivision surfaces talk's table (16/59/236/943 MB against "
             "1.9/7.5/30/118 MB at levels 8..64, x8) fits "
             "about 14-15 thousand quad patches, a plain mesh of about 16 B per tessellated vertex "
             "with no index cost (943e6 B / (16 B x 64^2) = 14.4k patches; 16e6 / (16 x 8^2) = "
             "15.6k) "
             "against one 16-bit texel per vertex and negligible control data: 16 B / 2 B = 8. "
             "Here "
             "the plain vertex is 32 B plus 2 triangles x 12 B of indices per point, so quad "
             "patches "
             "give about 56 / 2 = 28 at high levels; triangle patches more (about 42: the D3D11 "
             "triangle domain has ~3n^2/4 points at level n but the map (n+1)(n+2)/2 texels)",
             "displaced surfaces (rows with a displacement key): displacement_bytes and the "
             "vector_* "
             "figures are the real map's GPU-resident bytes (R16/R32 float for a scalar map, RGBA "
             "for "
             "a vector map, no mips) instead of the per-vertex assumption, patch_data_bytes "
             "includes "
             "the 33 words per patch of owners and corner directions the displaced TES reads, and "
             "map_file_bytes is the EXR on disk; no compressed_* baseline (the undisplaced record "
             "has "
             "it); summaries leave these rows out",
             "path = compute rows: the same level drawn through the compute path "
             "(core/gpu/compute_path.h), which writes every patch's points (unwelded, a 40-byte "
             "record: patch, coordinate, position, normal) and triangles (32-bit indices) to "
             "transient device buffers each frame; transient_* are those bytes, 0 on the "
             "tessellator path's rows (its points stream from the TES to the rasteriser)",
             "simulations (rows keyed by state = resident): Simulation::footprint, the state and "
             "auxiliary buffers the GPU keeps for the scenario, against the alternative the "
             "simulation names (its record's note says which)"},
        .summary_scope = {{"displacement", ""}},
        // One line per technique/variant: how the saving grows with the level (median over
        // the assets; levels double, so a log x spaces them evenly).
        .plots = {results::PlotSpec{
            .title = "Plain mesh over technique bytes against tessellation level",
            .kind = results::PlotKind::kLine,
            .x = "level",
            .y = "plain_over_technique",
            .series = "variant",
            .facet = "",
            .where = {{"displacement", ""}},
            .log_x = true}},
        .decision_inputs = {
            {.role = results::DecisionRole::kMemoryRatio,
             .label = "memory ratio",
             .column = "memory / plain mesh at level 16 (ratio)",
             .metrics = {"technique_with_displacement_bytes", "transient_vertex_bytes",
                         "transient_index_bytes"},
             .per = "plain_bytes",
             .where = {{"level", "16"}},
             .reduce = results::DecisionReduce::kLast,
             .rows_on_path = true},
            {.role = results::DecisionRole::kMemorySaving,
             .label = "the plain mesh's bytes over the technique's",
             .metrics = {"plain_over_technique"},
             .where = {{"level", "16"}}},
            {.role = results::DecisionRole::kAdviceMemory,
             .label = "memory",
             .column = "technique bytes with a 16-bit displacement map over the plain triangle "
                       "mesh's bytes, largest over the levels (ratio)",
             .metrics = {"plain_over_technique"}},
            {.role = results::DecisionRole::kPublishedMemory,
             .label = "bytes against the plain mesh",
             .metrics = {"patches", "plain_bytes", "technique_with_displacement_bytes",
                         "plain_over_technique"}}}};
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    MeasureRequirements requirements{
        {MeasureNeed::kSurfaceOrSimulation}, VariantPolicy::kWhenPatchDataDiffers, {}};
    requirements.displaced_surfaces = true;
    return requirements;
  }

  results::MeasureResult run(const MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    if (input.patches == nullptr && input.simulation != nullptr) {
      const techniques::SimulationFootprint footprint = input.simulation->footprint();
      results::MetricRow row;
      row.keys["state"] = "resident";
      row.metrics = simulationTable().metrics(footprint);
      result.rows.push_back(std::move(row));
      if (!footprint.alternative.empty()) {
        result.notes.push_back("alternative: " + footprint.alternative);
      }
      return result;
    }
    const std::string compute_skip =
        computeSkipReason(*input.patches, input.displacement != nullptr);
    for (uint32_t level : kMemoryLevels) {
      MemoryRowFigures figures{measureMemory(*input.patches, level), input.patches->patchCount(),
                               std::nullopt};
      if (input.displacement) {
        figures.map_file_bytes = input.displacement->input->file_bytes;
      } else if (!input.decision_figures_only &&
                 (input.suite == SuiteMode::kFull || level <= kDefaultSuiteCompressedLevel)) {
        figures.compressed = compressedSize(*input.patches, level);
        if (figures.compressed->sampled_chunks < figures.compressed->chunks &&
            level == kMemoryLevels.front()) {
          result.notes.push_back("compressed_* figures sampled: " +
                                 std::to_string(figures.compressed->sampled_chunks) + " of " +
                                 std::to_string(figures.compressed->chunks) + " chunks of " +
                                 std::to_string(kCompressChunkPatches) +
                                 " patches built and compressed, bytes scaled by patches");
        }
      }
      results::MetricRow row;
      row.keys["level"] = std::to_string(level);
      row.keys["path"] = "tessellator";
      row.metrics = memoryTable().metrics(figures);
      result.rows.push_back(std::move(row));
      result.rows.push_back(computeRow(*input.patches, compute_skip, figures));
    }
    return result;
  }

 private:
  // The same level on the compute path: the tessellator row's figures and the transient
  // buffers; skipped where the compute path cannot run the program.
  static results::MetricRow computeRow(const techniques::SurfacePatches& patches,
                                       const std::string& reason, MemoryRowFigures figures) {
    results::MetricRow row;
    row.keys["level"] = std::to_string(figures.memory.level);
    row.keys["path"] = "compute";
    if (!reason.empty()) {
      return results::unmeasuredRow(std::move(row.keys), results::MeasureStatus::kSkipped, reason);
    }
    figures.transient = computePathTransient(patches, figures.memory.level);
    row.metrics = memoryTable().metrics(figures);
    return row;
  }

  // Why the compute path cannot run the surface ("" when it can).
  static std::string computeSkipReason(const techniques::SurfacePatches& patches, bool displaced) {
    if (displaced) return "the compute path does not displace yet";
    const std::vector<gpu::GpuPatchProgram> programs = patches.gpuPrograms();
    if (programs.empty()) return "the technique has no GPU program";
    for (const gpu::GpuPatchProgram& program : programs) {
      if (program.compute_shader.empty())
        return program.evaluation_shader + " has no compute shader";
    }
    return "";
  }
};

TB_REGISTER_MEASURE(MemoryMeasure);

}  // namespace
}  // namespace tb::measures
