// Oracle: serial evaluation. Bfr's irregular patches are built lazily into the
// factory's cache; a fresh surface evaluated from many threads at once fills that
// cache concurrently and must give bit-identical results to a serial run (Bfr is
// deterministic). TBB runs the parallel loop with more threads than cores, so the
// threads do interleave even on a two-core machine.
#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "reference/embree_subdivision.h"
#include "reference/limit_surface.h"
#include "reference/triangle_distance_field.h"
#include "tests/reference/reference_test_support.h"

namespace tb::ref {
namespace {

using testing::clusteredFacePoints;
using testing::loadShape;

constexpr int kThreads = 8;

struct Sample {
  size_t face;
  mesh::Vec2d uv;
};

std::vector<Sample> samplesOf(const mesh::Mesh& mesh, osd::Scheme scheme) {
  std::vector<Sample> samples;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    for (const mesh::Vec2d& uv : clusteredFacePoints(scheme, int(mesh.faceSize(f)), 4))
      samples.push_back({f, uv});
  }
  return samples;
}

template <class Body>
void runParallel(size_t count, Body body) {
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, kThreads);
  tbb::task_arena arena(kThreads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i != r.end(); ++i) body(i);
                      });
  });
}

bool samePoint(const LimitPoint& a, const LimitPoint& b) {
  return a.position == b.position && a.du == b.du && a.dv == b.dv && a.normal == b.normal;
}

TEST(ThreadSafety, ParallelLimitEvaluationEqualsSerial) {
  for (const auto& [name, scheme] :
       {std::pair{"catmark_pawn.obj", osd::Scheme::kCatmullClark},
        std::pair{"catmark_xord_interior.obj", osd::Scheme::kCatmullClark},
        std::pair{"loop_xord_interior.obj", osd::Scheme::kLoop}}) {
    const mesh::Mesh mesh = loadShape(name);
    const std::vector<Sample> samples = samplesOf(mesh, scheme);
    std::vector<LimitPoint> serial(samples.size()), parallel(samples.size());
    {
      const LimitSurface surface(mesh, scheme);
      for (size_t i = 0; i < samples.size(); ++i) {
        serial[i] = surface.evaluate(samples[i].face, samples[i].uv.x, samples[i].uv.y);
      }
    }
    const LimitSurface fresh(mesh, scheme);  // empty cache: the threads race to fill it
    runParallel(samples.size(), [&](size_t i) {
      parallel[i] = fresh.evaluate(samples[i].face, samples[i].uv.x, samples[i].uv.y);
    });
    size_t differing = 0;
    for (size_t i = 0; i < samples.size(); ++i) differing += !samePoint(serial[i], parallel[i]);
    EXPECT_EQ(differing, 0u) << name << ", " << samples.size() << " samples";
  }
}

TEST(ThreadSafety, ParallelEmbreeAndDistanceQueriesEqualSerial) {
  const mesh::Mesh mesh = loadShape("catmark_pawn.obj");
  const std::vector<Sample> samples = samplesOf(mesh, osd::Scheme::kCatmullClark);
  const EmbreeSubdivision embree(mesh);
  const std::vector<Triangle> triangles = fanTriangles(mesh);
  const TriangleDistanceField field(mesh.positions, triangles);
  std::vector<LimitPoint> serial(samples.size()), parallel(samples.size());
  std::vector<double> serial_d(samples.size()), parallel_d(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    serial[i] = embree.evaluate(samples[i].face, samples[i].uv.x, samples[i].uv.y);
    serial_d[i] = field.closest(serial[i].position).distance;
  }
  runParallel(samples.size(), [&](size_t i) {
    parallel[i] = embree.evaluate(samples[i].face, samples[i].uv.x, samples[i].uv.y);
    parallel_d[i] = field.closest(parallel[i].position).distance;
  });
  size_t differing = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    differing += !samePoint(serial[i], parallel[i]) || serial_d[i] != parallel_d[i];
  }
  EXPECT_EQ(differing, 0u);
}

}  // namespace
}  // namespace tb::ref
