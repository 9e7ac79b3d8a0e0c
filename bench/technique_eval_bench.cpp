// CPU evaluation throughput in double, one thread: every registered surface technique
// point by point (evaluate) and batched (evaluateBatch: position, du, dv), beside
// OpenSubdiv's evaluation paths on the same points of the same asset (a lattice of
// kSegments segments per patch edge), and the core's measured FMA peak.
//
// Rows (counters: points_per_second; batched rows also fma_per_point and
// fma_peak_fraction = points_per_second x fma_per_point / fma_peak):
//   eval/<technique>/<asset>                  evaluate() per point (position + normal)
//   eval_batch/<technique>/<asset>            evaluateBatch() per patch, one pattern per domain
//   opensubdiv/<setup>/<asset>                bench/opensubdiv_eval.h, quad-only Catmull-Clark
//                                             assets; max_deviation: of the positions from
//                                             bfr_surface's, per bounding-box diagonal
//   fma_peak                                  fma_per_second of bench/fma_peak.h
// After the run, the batched rows' ratios to the OpenSubdiv rows go to stderr (the same
// points only for techniques whose patch p is face p in the face's (u, v): acc, and
// gregory_acc on meshes of quads; the triangle techniques fan-triangulate).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "bench/fma_peak.h"
#include "bench/opensubdiv_eval.h"
#include "bench/technique_bench_support.h"
#include "techniques/common/basis_table.h"
#include "techniques/registry.h"

namespace {

constexpr int kSegments = 16;  // 17 x 17 points per quad patch, 153 per triangle patch
constexpr int kOsdLevel = 10;  // the reference's Bfr ApproxLevel (reference/limit_surface.h)

// catmark_pawn (creased: the triangle techniques), loop_icosahedron (triangles),
// catmark_xord_interior (smooth quads with extraordinary vertices: every quad technique,
// ACC included) and catmark_pyramid (quads and triangles in one mesh).
const char* const kAssets[] = {"catmark_pawn", "loop_icosahedron", "catmark_xord_interior",
                               "catmark_pyramid"};

void evaluatePerPoint(benchmark::State& state, const tb::techniques::Technique* technique,
                      const std::string& asset) {
  const tb::techniques::BuiltSurface patches =
      tb::bench::defaultVariantPatches(state, *technique, asset);
  if (!patches) return;
  const std::vector<tb::techniques::DomainCoord> lattice[2] = {
      tb::techniques::latticeCoords(tb::techniques::PatchDomain::kTriangle, kSegments),
      tb::techniques::latticeCoords(tb::techniques::PatchDomain::kQuad, kSegments)};
  int64_t points = 0;
  for (auto _ : state) {
    for (size_t p = 0; p < patches->patchCount(); ++p) {
      for (const tb::techniques::DomainCoord& coord : lattice[int(patches->patchDomain(p))]) {
        benchmark::DoNotOptimize(patches->evaluate(p, coord));
      }
      points += int64_t(lattice[int(patches->patchDomain(p))].size());
    }
  }
  state.counters["points_per_second"] =
      benchmark::Counter(double(points), benchmark::Counter::kIsRate);
}

void evaluateBatched(benchmark::State& state, const tb::techniques::Technique* technique,
                     const std::string& asset) {
  const tb::techniques::BuiltSurface patches =
      tb::bench::defaultVariantPatches(state, *technique, asset);
  if (!patches) return;
  std::unique_ptr<tb::techniques::BatchPattern> patterns[2];  // by PatchDomain
  double fmas_per_pass = 0, points_per_pass = 0;
  for (size_t p = 0; p < patches->patchCount(); ++p) {
    const tb::techniques::PatchDomain domain = patches->patchDomain(p);
    auto& pattern = patterns[int(domain)];
    if (!pattern) {
      pattern = patches->makeBatchPattern(domain, tb::techniques::latticeCoords(domain, kSegments),
                                          tb::techniques::BatchOutput::kPositionAndDerivatives);
    }
    fmas_per_pass += pattern->multiplyAddsPerPoint() * double(pattern->pointCount());
    points_per_pass += double(pattern->pointCount());
  }
  tb::techniques::BatchPoints out;
  int64_t points = 0;
  const double start_s = tb::bench::threadCpuSeconds();
  for (auto _ : state) {
    for (size_t p = 0; p < patches->patchCount(); ++p) {
      patches->evaluateBatch(p, *patterns[int(patches->patchDomain(p))], out);
      benchmark::DoNotOptimize(out.position[0].data());
      points += int64_t(out.count);
    }
    benchmark::ClobberMemory();
  }
  const double cpu_s = tb::bench::threadCpuSeconds() - start_s;
  state.counters["points_per_second"] =
      benchmark::Counter(double(points), benchmark::Counter::kIsRate);
  if (fmas_per_pass > 0) {
    const double fma_per_point = fmas_per_pass / points_per_pass;
    state.counters["fma_per_point"] = fma_per_point;
    // Best 1 (every cycle a full-width FMA on every pipe); a kernel that hid no latency
    // and streamed its weights from memory would sit near 0.1.
    state.counters["fma_peak_fraction"] =
        double(points) * fma_per_point / cpu_s / tb::bench::fmaPeakPerSecond();
    state.SetLabel(toString(tb::techniques::fastestBatchKernel()));
  } else {
    state.SetLabel("per-point default");
  }
}

std::vector<tb::mesh::Vec2d> quadLattice() {
  std::vector<tb::mesh::Vec2d> uv;
  for (const tb::techniques::DomainCoord& d :
       tb::techniques::latticeCoords(tb::techniques::PatchDomain::kQuad, kSegments)) {
    uv.push_back({d[0], d[1]});
  }
  return uv;
}

double diagonal(const tb::mesh::Mesh& mesh) {
  tb::mesh::Vec3d lo = mesh.positions[0], hi = lo;
  for (const tb::mesh::Vec3d& p : mesh.positions) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  return length(hi - lo);
}

using OsdFactory = std::unique_ptr<tb::bench::OsdEvaluation> (*)(
    const tb::mesh::Mesh&, const std::vector<tb::mesh::Vec2d>&);

struct OsdSetup {
  const char* name;
  OsdFactory make;
};

const OsdSetup kOsdSetups[] = {
    {"bfr_surface",
     [](const tb::mesh::Mesh& m, const std::vector<tb::mesh::Vec2d>& uv) {
       return tb::bench::makeBfrSurfaces(m, uv, kOsdLevel);
     }},
    {"bfr_surface_default_levels",  // OpenSubdiv's defaults: ApproxLevelSmooth 2, sharp 6
     [](const tb::mesh::Mesh& m, const std::vector<tb::mesh::Vec2d>& uv) {
       return tb::bench::makeBfrSurfaces(m, uv, 2);
     }},
    {"far_patch_map",
     [](const tb::mesh::Mesh& m, const std::vector<tb::mesh::Vec2d>& uv) {
       return tb::bench::makePatchMap(m, uv, kOsdLevel);
     }},
    {"far_limit_stencils",
     [](const tb::mesh::Mesh& m, const std::vector<tb::mesh::Vec2d>& uv) {
       return tb::bench::makeLimitStencils(m, uv, kOsdLevel);
     }},
};

void evaluateOpenSubdiv(benchmark::State& state, const OsdSetup& setup, const std::string& asset) {
  const tb::mesh::Mesh mesh = tb::suite::loadAsset(tb::suite::resolveAsset(asset));
  const std::vector<tb::mesh::Vec2d> uv = quadLattice();
  std::unique_ptr<tb::bench::OsdEvaluation> evaluation, reference;
  try {
    evaluation = setup.make(mesh, uv);
    reference = kOsdSetups[0].make(mesh, uv);
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
    return;
  }
  reference->evaluateAll();
  int64_t points = 0;
  for (auto _ : state) {
    points += evaluation->evaluateAll();
    benchmark::ClobberMemory();
  }
  double deviation = 0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    for (size_t i = 0; i < uv.size(); ++i) {
      deviation =
          std::max(deviation, length(evaluation->position(f, i) - reference->position(f, i)));
    }
  }
  state.counters["points_per_second"] =
      benchmark::Counter(double(points), benchmark::Counter::kIsRate);
  state.counters["max_deviation"] = deviation / diagonal(mesh);
  if (evaluation->multiplyAddsPerPoint() > 0) {
    state.counters["fma_per_point"] = evaluation->multiplyAddsPerPoint();
  }
}

void fmaPeak(benchmark::State& state) {
  int64_t fmas = 0;
  for (auto _ : state) fmas += tb::bench::runFmaPeakLoop(100'000);
  state.counters["fma_per_second"] = benchmark::Counter(double(fmas), benchmark::Counter::kIsRate);
  state.SetLabel(tb::bench::fmaPeakKernel());
}

bool quadOnlyCatmullClark(const std::string& asset) {
  if (asset.rfind("catmark_", 0) != 0) return false;
  const tb::mesh::Mesh mesh = tb::suite::loadAsset(tb::suite::resolveAsset(asset));
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (mesh.faceSize(f) != 4) return false;
  }
  return true;
}

// Registered from the technique registry in main (after every static registration has
// run), so new techniques are benchmarked without touching this file.
void registerBenchmarks() {
  benchmark::RegisterBenchmark("fma_peak", fmaPeak);
  for (const std::string asset : kAssets) {
    for (const tb::techniques::Technique* technique :
         tb::techniques::TechniqueRegistry::instance().all()) {
      if (technique->info().family != tb::techniques::TechniqueFamily::kSurface) continue;
      const std::string id = technique->info().id;
      benchmark::RegisterBenchmark(("eval/" + id + "/" + asset).c_str(),
                                   [technique, asset](benchmark::State& state) {
                                     evaluatePerPoint(state, technique, asset);
                                   });
      benchmark::RegisterBenchmark(("eval_batch/" + id + "/" + asset).c_str(),
                                   [technique, asset](benchmark::State& state) {
                                     evaluateBatched(state, technique, asset);
                                   });
    }
    if (!quadOnlyCatmullClark(asset)) continue;
    for (const OsdSetup& setup : kOsdSetups) {
      benchmark::RegisterBenchmark(
          (std::string("opensubdiv/") + setup.name + "/" + asset).c_str(),
          [&setup, asset](benchmark::State& state) { evaluateOpenSubdiv(state, setup, asset); });
    }
  }
}

// The display reporter, keeping each row's points_per_second for the ratios printed
// after the run.
class RateKeeper final : public benchmark::BenchmarkReporter {
 public:
  explicit RateKeeper(benchmark::BenchmarkReporter* display) : display_(display) {}
  bool ReportContext(const Context& context) override { return display_->ReportContext(context); }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      const auto rate = run.counters.find("points_per_second");
      if (run.error_occurred || rate == run.counters.end()) continue;
      rates_[run.benchmark_name()] = double(rate->second);
      const auto fraction = run.counters.find("fma_peak_fraction");
      if (fraction != run.counters.end()) fractions_[run.benchmark_name()] = fraction->second;
    }
    display_->ReportRuns(runs);
  }
  void Finalize() override { display_->Finalize(); }

  // Per asset with OpenSubdiv rows: each batched row against bfr_surface and the fastest.
  void printRatios() const {
    for (const std::string asset : kAssets) {
      const auto baseline = rates_.find("opensubdiv/bfr_surface/" + asset);
      if (baseline == rates_.end()) continue;
      std::string fastest_name;
      double fastest = 0;
      for (const auto& [name, rate] : rates_) {
        if (name.rfind("opensubdiv/", 0) == 0 && name.ends_with("/" + asset) && rate > fastest) {
          fastest = rate, fastest_name = name;
        }
      }
      std::fprintf(stderr, "\n%s: bfr_surface %.2f M points/s; fastest OpenSubdiv %s %.2f M/s\n",
                   asset.c_str(), baseline->second / 1e6, fastest_name.c_str(), fastest / 1e6);
      for (const auto& [name, rate] : rates_) {
        if (name.rfind("eval_batch/", 0) != 0 || !name.ends_with("/" + asset)) continue;
        const auto fraction = fractions_.find(name);
        std::fprintf(
            stderr, "  %-44s %8.2f M/s  x%6.1f bfr_surface  x%6.1f fastest  %s\n", name.c_str(),
            rate / 1e6, rate / baseline->second, rate / fastest,
            fraction == fractions_.end()
                ? "(per-point default)"
                : ("fma peak " + std::to_string(int(100 * fraction->second + 0.5)) + "%").c_str());
      }
    }
  }

 private:
  benchmark::BenchmarkReporter* display_;
  std::map<std::string, double> rates_, fractions_;
};

}  // namespace

int main(int argc, char** argv) {
  registerBenchmarks();
  tb::bench::addDeviceContext();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RateKeeper reporter(benchmark::CreateDefaultDisplayReporter());
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.printRatios();
  benchmark::Shutdown();
  return 0;
}
