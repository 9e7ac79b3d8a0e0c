// Oracle: the same run on one worker thread. Records run in parallel groups and the
// heavy measures parallelise inside (error sampling, closest-point queries, chunked
// compression, crack pairing); none of it may change a byte of the results.
#include <gtest/gtest.h>

#include <string>

#include "harness/results/results_json.h"
#include "harness/suite/suite.h"
#include "techniques/registry.h"
#include "tests/test_support.h"

namespace tb {
namespace {

std::string runWithThreads(int threads, suite::SuiteTimings* timings) {
  suite::SuiteSelection selection;
  // A quad mesh, on which every technique runs (acc and osd_adaptive take quads only; phong
  // and pn_triangles its fan triangles) and every measure on some technique, and a
  // quad-and-triangle mesh (gregory_acc's mixed domains). Under a sanitizer the quad mesh
  // alone: the same code, every technique and measure, in about 0.7 of the time.
  selection.assets = {suite::resolveAsset("catmark_cube")};
  if (!::tb::testing::kUnderSanitizer) {
    selection.assets.push_back(suite::resolveAsset("catmark_pyramid"));
  }
  selection.threads = threads;
  results::Results results;
  suite::runSuite(selection, nullptr, &results, timings);
  return results::serializeResults(results);
}

TEST(ThreadInvariance, ResultsAreByteIdenticalOnOneAndTwoThreads) {
  suite::SuiteTimings one_thread, two_threads;
  const std::string serial = runWithThreads(1, &one_thread);
  const std::string parallel = runWithThreads(2, &two_threads);
  EXPECT_EQ(one_thread.threads, 1);
  EXPECT_EQ(two_threads.threads, 2);
  EXPECT_GT(one_thread.measures.size(), 40u);  // a real workload, not a trivial one
  EXPECT_EQ(serial.size(), parallel.size());
  EXPECT_TRUE(serial == parallel) << "the results depend on the thread count";
}

TEST(ThreadInvariance, TimingsCoverEveryMeasureOfEveryRecord) {
  // A third whole run: under a sanitizer the one above runs the same suite code.
  if (::tb::testing::kUnderSanitizer)
    GTEST_SKIP() << "the suite's code runs above under a sanitizer";
  suite::SuiteSelection selection;
  selection.assets = {suite::resolveAsset("loop_icosahedron")};
  selection.threads = 2;
  results::Results results;
  suite::SuiteTimings timings;
  suite::runSuite(selection, nullptr, &results, &timings);
  size_t measured = 0;
  for (const results::Record& record : results.records) measured += record.measures.size();
  EXPECT_EQ(timings.measures.size(), measured);
  double sum = 0;
  for (const suite::MeasureTiming& t : timings.measures) sum += t.seconds;
  EXPECT_GT(timings.wall_seconds, 0);
  EXPECT_GT(sum, 0);
}

}  // namespace
}  // namespace tb
