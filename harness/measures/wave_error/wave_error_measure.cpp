// The "wave_error" measure: wave particles against the linear wave equation, per scenario
// and variant: height-field error and wavefront coverage over time (rows keyed by time),
// arrival time at the scenario's probes (rows keyed by probe).
#include <cstdio>
#include <string>

#include "harness/measures/measure.h"
#include "harness/measures/metric_table.h"
#include "harness/measures/wave_error/wave_error.h"

namespace tb::measures {
namespace {

// Sample times per run: the default suite's few, the full suite's finer time axis.
constexpr uint32_t kDefaultSamples = 4;
constexpr uint32_t kFullSamples = 12;

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.4g", value);
  return text;
}

const MetricTable<WaveTimeFigures>& timeTable() {
  using D = results::Direction;
  using R = WaveTimeFigures;
  static const MetricTable<R> kTable{
      // 0 when the particles' height field equals the reference; grows with the model's
      // departures from the wave equation (no 1/sqrt(R) spreading, no wake).
      // rms_error: ratio of the largest source amplitude; 0 when the field equals the reference
      //   (best), unbounded (worst)
      {"rms_error", results::Unit::kRatio, D::kLowerIsBetter, &R::rms_error},
      // max_error: ratio of the largest source amplitude; 0 (best), unbounded (worst)
      {"max_error", results::Unit::kRatio, D::kLowerIsBetter, &R::max_error},
      // coverage: ratio; 1 when the ideal ring is whole (best), 0 when no particle is left on it
      //   (worst)
      {"coverage", results::Unit::kRatio, D::kHigherIsBetter,
       [](const R& r) { return r.coverage; }},
      // front_radius: world units (m); context: c t for the first source, coverage's distance axis
      {"front_radius", results::Unit::kWorld, D::kNone, &R::front_radius_m},
      // particles: count; context: particles alive at this time
      {"particles", results::Unit::kCount, D::kNone, &R::particles},
  };
  return kTable;
}

const MetricTable<WaveProbeFigures>& probeTable() {
  using D = results::Direction;
  using R = WaveProbeFigures;
  static const MetricTable<R> kTable{
      // |particles - reference| arrival.
      // arrival_error_s: seconds; 0 (best), unbounded (worst); acceptance <= arrival_tolerance_s
      {"arrival_error_s", results::Unit::kSeconds, D::kLowerIsBetter,
       [](const R& r) -> std::optional<double> {
         if (auto e = r.arrivalError()) return std::abs(*e);
         return std::nullopt;
       }},
      // arrival_delay_s: seconds, signed; context: positive when the particles arrive late
      {"arrival_delay_s", results::Unit::kSeconds, D::kNone,
       [](const R& r) { return r.arrivalError(); }},
      // reference_arrival_s: seconds; context: the reference's arrival at the probe
      {"reference_arrival_s", results::Unit::kSeconds, D::kNone,
       [](const R& r) { return r.reference_arrival_s; }},
      // particle_arrival_s: seconds; context: the particles' arrival at the probe
      {"particle_arrival_s", results::Unit::kSeconds, D::kNone,
       [](const R& r) { return r.particle_arrival_s; }},
      // probe_distance: world units (m); context: distance to the nearest source
      {"probe_distance", results::Unit::kWorld, D::kNone, &R::distance_m},
  };
  return kTable;
}

std::vector<results::MetricSpec> allSpecs() {
  std::vector<results::MetricSpec> specs = timeTable().specs();
  for (const results::MetricSpec& spec : probeTable().specs()) specs.push_back(spec);
  // arrival_tolerance_s: seconds; context: one time step + particle radius / wave speed.
  specs.push_back({"arrival_tolerance_s", results::Unit::kSeconds, results::Direction::kNone});
  // arrival_within_tolerance: flag; 1 when |arrival_error_s| <= the tolerance (best), 0 (worst).
  specs.push_back(
      {"arrival_within_tolerance", results::Unit::kFlag, results::Direction::kHigherIsBetter});
  return specs;
}

class WaveErrorMeasure final : public Measure {
 public:
  const MeasureInfo& info() const override {
    static const MeasureInfo kInfo{
        .id = "wave_error",
        .title = "Wave particles against the linear wave equation",
        .description =
            "height-field RMS and max difference over the source amplitude, wavefront coverage "
            "(ratio) over time, and arrival time error (s) at probes, against a finite-difference "
            "wave-equation reference",
        .metrics = allSpecs(),
        .headline = {"arrival_error_s", "coverage", "rms_error"},
        .notes =
            {"reference: u_tt + 2k u_t = c^2 laplacian(u), 5-point Laplacian and leapfrog on the "
             "scenario's reference_spacing_m grid, c dt / h <= 0.5, Neumann walls at the domain "
             "border and at nodes within half a spacing of a wall; each source an initial "
             "displacement of the particle shape (Yuksel, House and Keyser, Wave Particles, "
             "SIGGRAPH 2007) at zero velocity",
             "height field: particles splatted as points (bilinear) on the height_field_spacing_m "
             "grid, filtered with the particle shape; rows keyed by time compare it with the "
             "reference at the same nodes",
             "arrival: the first time |height| exceeds 10% of the peak |height| the reference "
             "reaches at the probe, for both; the particles' height at a probe is their exact sum",
             "coverage: points every r/4 on each source's ideal ring (radius c (t - t_source)), "
             "inside the domain and in sight of the source, covered within r/2 of a particle; "
             "measured once t > 2r/c"},
        .summary_scope = {},
        .plots = {results::PlotSpec{.title = "Wavefront coverage against distance travelled",
                                    .kind = results::PlotKind::kLine,
                                    .x = "front_radius",
                                    .y = "coverage",
                                    .series = "variant",
                                    .facet = "",
                                    .where = {},
                                    .log_x = false}},
        .decision_inputs = {{.role = results::DecisionRole::kSimulationFigure,
                             .label = "per scenario",
                             .metrics = {"arrival_error_s", "coverage", "rms_error"}}}};
    return kInfo;
  }
  MeasureRequirements requirements() const override {
    return {{MeasureNeed::kSimulation, MeasureNeed::kWaveField}, VariantPolicy::kEveryVariant, {}};
  }
  results::MeasureResult run(const MeasureInput& input) const override {
    results::MeasureResult result;
    result.measure = info().id;
    techniques::Simulation* simulation = input.simulation;
    if (simulation == nullptr || simulation->waveField() == nullptr) {
      result.status = results::MeasureStatus::kSkipped;
      result.reason = "not a wave-particle simulation";
      return result;
    }
    const WaveErrorFigures figures = measureWaveError(
        *simulation, input.suite == SuiteMode::kFull ? kFullSamples : kDefaultSamples);
    for (const WaveTimeFigures& time : figures.times) {
      results::MetricRow row;
      row.keys["time"] = shortNumber(time.time_s);
      row.metrics = timeTable().metrics(time);
      result.rows.push_back(std::move(row));
    }
    for (size_t p = 0; p < figures.probes.size(); ++p) {
      const WaveProbeFigures& probe = figures.probes[p];
      std::map<std::string, std::string> keys{
          {"probe", "(" + shortNumber(probe.x_m) + ", " + shortNumber(probe.y_m) + ")"}};
      if (!probe.reference_arrival_s) {
        result.rows.push_back(results::unmeasuredRow(keys, results::MeasureStatus::kSkipped,
                                                     "the reference never reaches the probe"));
        continue;
      }
      results::MetricRow row;
      row.keys = keys;
      row.metrics = probeTable().metrics(probe);
      row.metrics.push_back({"arrival_tolerance_s", figures.arrival_tolerance_s,
                             std::string(toString(results::Unit::kSeconds))});
      const std::optional<double> error = probe.arrivalError();
      row.metrics.push_back({"arrival_within_tolerance",
                             error && std::abs(*error) <= figures.arrival_tolerance_s ? 1.0 : 0.0,
                             std::string(toString(results::Unit::kFlag))});
      result.rows.push_back(std::move(row));
    }
    return result;
  }
};

TB_REGISTER_MEASURE(WaveErrorMeasure);

}  // namespace
}  // namespace tb::measures
