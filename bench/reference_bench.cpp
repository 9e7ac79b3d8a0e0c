// Throughput of the reference layer (docs/ARCHITECTURE.md §7): Bfr limit evaluations,
// Embree rtcInterpolate evaluations (both position + first derivatives) and exact
// closest-point queries, each as a rate.
#include <benchmark/benchmark.h>

#include <random>

#include "bench/bench_main.h"
#include "harness/suite/asset_catalog.h"
#include "reference/embree_subdivision.h"
#include "reference/face_domain.h"
#include "reference/limit_surface.h"
#include "reference/limit_tessellation.h"
#include "reference/triangle_distance_field.h"

namespace {

using tb::osd::Scheme;

constexpr int kGrid = 8;  // kGrid x kGrid points per (sub-)face

tb::mesh::Mesh pawn() { return tb::suite::loadAsset(tb::suite::resolveAsset("catmark_pawn")); }

// Face (u,v) of a uniform grid on every sub-face of `face_size`.
std::vector<tb::mesh::Vec2d> gridPoints(int face_size) {
  std::vector<tb::mesh::Vec2d> points;
  for (int k = 0; k < tb::ref::subFaceCount(Scheme::kCatmullClark, face_size); ++k) {
    for (int j = 0; j < kGrid; ++j) {
      for (int i = 0; i < kGrid; ++i) {
        points.push_back(tb::ref::subFaceToFaceUv(Scheme::kCatmullClark, face_size, k,
                                                  {(i + 0.5) / kGrid, (j + 0.5) / kGrid}));
      }
    }
  }
  return points;
}

// gridPoints of every face, computed before timing.
std::vector<std::vector<tb::mesh::Vec2d>> pointsPerFace(const tb::mesh::Mesh& mesh) {
  std::vector<std::vector<tb::mesh::Vec2d>> points(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) points[f] = gridPoints(int(mesh.faceSize(f)));
  return points;
}

// Runs evaluate_face(f, grid points of f) over every face per iteration; it returns
// how many points it evaluated. Reports evaluations (position + dP/du + dP/dv) per second.
template <class EvaluateFace>
void timeFaces(benchmark::State& state, const tb::mesh::Mesh& mesh, EvaluateFace evaluate_face) {
  const std::vector<std::vector<tb::mesh::Vec2d>> points = pointsPerFace(mesh);
  int64_t evaluations = 0;
  for (auto _ : state) {
    for (size_t f = 0; f < mesh.faceCount(); ++f) evaluations += evaluate_face(f, points[f]);
  }
  state.counters["evaluations_per_second"] =
      benchmark::Counter(double(evaluations), benchmark::Counter::kIsRate);
}

// Prepares each face once per pass (LimitSurface::face) and evaluates its grid: the
// way the error measure walks a mesh.
void BM_BfrLimitEvaluate(benchmark::State& state) {
  const tb::mesh::Mesh mesh = pawn();
  const tb::ref::LimitSurface surface(mesh, Scheme::kCatmullClark);
  timeFaces(state, mesh, [&](size_t f, const std::vector<tb::mesh::Vec2d>& points) {
    const tb::ref::LimitFace face = surface.face(f);
    for (const tb::mesh::Vec2d& uv : points) benchmark::DoNotOptimize(face.evaluate(uv.x, uv.y));
    return int64_t(points.size());
  });
}
BENCHMARK(BM_BfrLimitEvaluate)->Unit(benchmark::kMillisecond);

// One-off points: every evaluation prepares its face again.
void BM_BfrLimitEvaluateSinglePoints(benchmark::State& state) {
  const tb::mesh::Mesh mesh = pawn();
  const tb::ref::LimitSurface surface(mesh, Scheme::kCatmullClark);
  timeFaces(state, mesh, [&](size_t f, const std::vector<tb::mesh::Vec2d>& points) {
    const tb::mesh::Vec2d uv = points[kGrid + 3];
    benchmark::DoNotOptimize(surface.evaluate(f, uv.x, uv.y));
    return int64_t(1);
  });
}
BENCHMARK(BM_BfrLimitEvaluateSinglePoints)->Unit(benchmark::kMillisecond);

void BM_EmbreeInterpolate(benchmark::State& state) {
  const tb::mesh::Mesh mesh = pawn();
  const tb::ref::EmbreeSubdivision embree(mesh);
  timeFaces(state, mesh, [&](size_t f, const std::vector<tb::mesh::Vec2d>& points) {
    for (const tb::mesh::Vec2d& uv : points)
      benchmark::DoNotOptimize(embree.evaluate(f, uv.x, uv.y));
    return int64_t(points.size());
  });
}
BENCHMARK(BM_EmbreeInterpolate)->Unit(benchmark::kMillisecond);

// Exact closest points on the pawn's limit tessellated at rate 3 (~10.6k triangles),
// for queries scattered within 1% of the diagonal around the surface.
void BM_ClosestPoint(benchmark::State& state) {
  const tb::ref::LimitSurface surface(pawn(), Scheme::kCatmullClark);
  const tb::ref::LimitTessellation tessellation = tb::ref::tessellateLimit(surface, 3);
  const tb::ref::TriangleDistanceField field(tessellation.view());
  const double spread = 0.01 * tb::ref::boundingBoxDiagonal(tessellation.positions);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<size_t> pick(0, tessellation.positions.size() - 1);
  std::uniform_real_distribution<double> offset(-spread, spread);
  std::vector<tb::mesh::Vec3d> queries(4096);
  for (tb::mesh::Vec3d& q : queries) {
    q = tessellation.positions[pick(rng)] + tb::mesh::Vec3d{offset(rng), offset(rng), offset(rng)};
  }
  int64_t count = 0;
  for (auto _ : state) {
    for (const tb::mesh::Vec3d& q : queries) benchmark::DoNotOptimize(field.closest(q));
    count += int64_t(queries.size());
  }
  state.counters["triangles"] = double(field.triangleCount());
  state.counters["queries_per_second"] =
      benchmark::Counter(double(count), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ClosestPoint)->Unit(benchmark::kMillisecond);

}  // namespace

TB_BENCHMARK_MAIN()
