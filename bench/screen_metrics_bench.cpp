// Cost of the screen-space figures (harness/lod/screen_metrics.h) per call, the figure
// a factor-policy sweep multiplies by its ~30 calls per record: tessellationError, frame
// and pop on a pawn at 1920 x 1080 filling about half the screen height. acc runs on the
// pawn with its crease tags removed (acc refuses creases); pn_triangles on tri_pawn.
//
// Levels: uniform 4, 8, 16 (one shared pattern: the cache is warm after the first call), and
// "adaptive" (level argument 0): each patch's outer levels from its corners' projected edge
// lengths / 8 px, fractional_odd, so nearly every patch has its own levels (the cache helps
// little). The `cold` cases build a fresh ScreenMetrics (empty cache) every iteration; the
// sweep cycles through 30 adaptive level sets, as a policy's parameter sweep does. Wall clock; the
// second argument is the worker thread count (0: TBB's default).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_main.h"
#include "core/mesh/obj_loader.h"
#include "core/view/camera.h"
#include "harness/lod/screen_metrics.h"
#include "harness/suite/asset_catalog.h"
#include "harness/suite/camera_path.h"
#include "reference/limit_surface.h"
#include "techniques/registry.h"

namespace {

constexpr double kFovYRad = 60 * std::numbers::pi / 180;

struct Subject {
  tb::mesh::Mesh mesh;
  tb::techniques::BuiltSurface patches;
  tb::view::View view;
};

// The sphere around the mesh's bounding box spans half the screen height.
tb::view::View halfScreenView(const tb::mesh::Mesh& mesh) {
  const tb::mesh::Aabb box = tb::mesh::boundsOf(mesh);
  const tb::mesh::Vec3d centre = 0.5 * (box.min + box.max);
  const double radius = 0.5 * length(box.max - box.min);
  const double distance = 2 * radius / std::tan(kFovYRad / 2);
  const tb::mesh::Vec3d eye = centre + distance * normalize(tb::mesh::Vec3d{0.6, 0.5, 0.8});
  tb::view::View view;
  const double near_plane = distance - 1.5 * radius, far_plane = distance + 1.5 * radius;
  view.view_projection = tb::view::perspective(kFovYRad, 1920.0 / 1080, near_plane, far_plane) *
                         tb::view::lookAt(eye, centre, {0, 1, 0});
  view.viewport_width_px = 1920;
  view.viewport_height_px = 1080;
  view.eye = {eye.x, eye.y, eye.z};
  view.projection_y_scale = 1 / std::tan(kFovYRad / 2);
  view.near_plane = near_plane;
  view.target_pixels_per_edge = 8;
  return view;
}

const Subject& subject(const std::string& technique) {
  static std::optional<Subject> acc, pn;
  std::optional<Subject>& s = technique == "acc" ? acc : pn;
  if (!s) {
    tb::mesh::Mesh mesh = tb::mesh::loadObjFile(
        tb::suite::resolveAsset(technique == "acc" ? "catmark_pawn" : "tri_pawn").path);
    mesh.tags.creases.clear();
    mesh.tags.corners.clear();
    const tb::techniques::Technique* t =
        tb::techniques::TechniqueRegistry::instance().find(technique);
    tb::techniques::BuiltSurface patches = tb::techniques::buildSurface(*t, mesh, t->variants()[0]);
    const tb::view::View view = halfScreenView(mesh);
    s.emplace(Subject{std::move(mesh), std::move(patches), view});
  }
  return *s;
}

// Outer level of each patch edge: its corners' distance on screen / target, in [1, 64];
// inner levels the largest outer level.
std::vector<tb::tess::Levels> adaptiveLevels(const Subject& s, double target_px = 8) {
  std::vector<tb::tess::Levels> levels;
  for (size_t p = 0; p < s.patches->patchCount(); ++p) {
    const auto corners = s.patches->patchCorners(p);
    const int n = s.patches->patchDomain(p) == tb::techniques::PatchDomain::kQuad ? 4 : 3;
    tb::tess::Levels l;
    float largest = 1;
    for (int k = 0; k < n; ++k) {
      const tb::mesh::Vec3d a = s.mesh.positions[corners[k]],
                            b = s.mesh.positions[corners[(k + 1) % n]];
      const tb::view::ProjectedPoint pa = tb::view::projectToPixels(s.view, a.x, a.y, a.z);
      const tb::view::ProjectedPoint pb = tb::view::projectToPixels(s.view, b.x, b.y, b.z);
      const double px = std::hypot(pa.x_px - pb.x_px, pa.y_px - pb.y_px);
      l.outer[k] = float(std::clamp(px / target_px, 1.0, 64.0));
      largest = std::max(largest, l.outer[k]);
    }
    l.inner = {largest, largest};
    levels.push_back(l);
  }
  return levels;
}

std::vector<tb::tess::Levels> levelsFor(const Subject& s, int level) {
  if (level == 0) return adaptiveLevels(s);
  const float f = float(level);
  return std::vector<tb::tess::Levels>(s.patches->patchCount(), {{f, f, f, f}, {f, f}});
}

tb::tess::Spacing spacingFor(int level) {
  return level == 0 ? tb::tess::Spacing::kFractionalOdd : tb::tess::Spacing::kInteger;
}

// Limits TBB to `count` worker threads while alive; 0 leaves TBB's default.
class Threads {
 public:
  explicit Threads(int count) {
    if (count > 0) control_.emplace(tbb::global_control::max_allowed_parallelism, size_t(count));
  }

 private:
  std::optional<tbb::global_control> control_;
};

// range(0): the uniform level, 0 for adaptive; range(1): worker threads, 0 for the default.
void BM_TessellationError(benchmark::State& state, const std::string& technique, bool cold) {
  const Threads threads(int(state.range(1)));
  const Subject& s = subject(technique);
  const std::vector<tb::tess::Levels> levels = levelsFor(s, int(state.range(0)));
  const tb::tess::Spacing spacing = spacingFor(int(state.range(0)));
  std::optional<tb::lod::ScreenMetrics> metrics(std::in_place, *s.patches, nullptr);
  uint64_t triangles = 0;
  tb::lod::ScreenErrorFigures figures;
  for (auto _ : state) {
    if (cold) metrics.emplace(*s.patches, nullptr);
    figures = metrics->tessellationError(spacing, levels, s.view, &triangles);
  }
  state.counters["patches"] = double(s.patches->patchCount());
  state.counters["triangles"] = double(triangles);
  state.counters["samples"] = double(figures.samples);
  state.counters["max_px"] = figures.max_px;
}

// A parameter sweep as a factor-policy measure runs it: one ScreenMetrics, 30 calls with
// adaptive levels for targets of 4, 5, ..., 33 px per edge; the time is per call.
void BM_TessellationErrorSweep(benchmark::State& state, const std::string& technique) {
  const Threads threads(int(state.range(1)));
  const Subject& s = subject(technique);
  std::vector<std::vector<tb::tess::Levels>> sweep;
  for (int target_px = 4; target_px < 34; ++target_px)
    sweep.push_back(adaptiveLevels(s, target_px));
  tb::lod::ScreenMetrics metrics(*s.patches, nullptr);
  size_t call = 0;
  uint64_t triangles = 0, total = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(metrics.tessellationError(
        tb::tess::Spacing::kFractionalOdd, sweep[call++ % sweep.size()], s.view, &triangles));
    total += triangles;
  }
  state.counters["triangles_per_call"] = double(total) / double(call);
}

void BM_Frame(benchmark::State& state, const std::string& technique) {
  const Threads threads(int(state.range(1)));
  const Subject& s = subject(technique);
  const std::vector<tb::tess::Levels> levels = levelsFor(s, int(state.range(0)));
  const tb::ref::LimitSurface limit(s.patches->controlMesh(), technique == "acc"
                                                                  ? tb::osd::Scheme::kCatmullClark
                                                                  : tb::osd::Scheme::kLoop);
  tb::lod::ScreenMetrics metrics(*s.patches, &limit);
  tb::lod::FrameScreenFigures figures;
  for (auto _ : state) figures = metrics.frame(spacingFor(int(state.range(0))), levels, s.view);
  state.counters["triangles"] = double(figures.triangles);
  state.counters["edges"] = double(figures.edges.edges);
  state.counters["median_px"] = figures.edges.median_px;
}

void BM_Pop(benchmark::State& state, const std::string& technique) {
  const Threads threads(int(state.range(1)));
  const Subject& s = subject(technique);
  const std::vector<tb::tess::Levels> before = adaptiveLevels(s);
  std::vector<tb::tess::Levels> after = before;
  for (tb::tess::Levels& l : after) {
    for (float& level : l.outer) level = std::min(64.0f, level * 1.1f);
    for (float& level : l.inner) level = std::min(64.0f, level * 1.1f);
  }
  tb::lod::ScreenMetrics metrics(*s.patches, nullptr);
  tb::lod::ScreenErrorFigures figures;
  for (auto _ : state) {
    figures = metrics.pop(tb::tess::Spacing::kFractionalOdd, before, after, s.view);
  }
  state.counters["max_px"] = figures.max_px;
}

void levelArgs(benchmark::internal::Benchmark* b) {
  for (int threads : {1, 0}) {
    for (int level : {4, 8, 16, 0}) b->Args({level, threads});
  }
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK_CAPTURE(BM_TessellationError, acc_pawn, std::string("acc"), false)->Apply(levelArgs);
BENCHMARK_CAPTURE(BM_TessellationError, acc_pawn_cold, std::string("acc"), true)->Apply(levelArgs);
BENCHMARK_CAPTURE(BM_TessellationError, pn_tri_pawn, std::string("pn_triangles"), false)
    ->Apply(levelArgs);
BENCHMARK_CAPTURE(BM_TessellationError, pn_tri_pawn_cold, std::string("pn_triangles"), true)
    ->Apply(levelArgs);
BENCHMARK_CAPTURE(BM_TessellationErrorSweep, acc_pawn, std::string("acc"))
    ->Args({0, 1})
    ->Args({0, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_TessellationErrorSweep, pn_tri_pawn, std::string("pn_triangles"))
    ->Args({0, 1})
    ->Args({0, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Frame, acc_pawn, std::string("acc"))->Apply(levelArgs);
BENCHMARK_CAPTURE(BM_Frame, pn_tri_pawn, std::string("pn_triangles"))->Apply(levelArgs);
BENCHMARK_CAPTURE(BM_Pop, acc_pawn, std::string("acc"))
    ->Args({0, 1})
    ->Args({0, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Pop, pn_tri_pawn, std::string("pn_triangles"))
    ->Args({0, 1})
    ->Args({0, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

TB_BENCHMARK_MAIN()
