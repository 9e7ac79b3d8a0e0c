#include <gtest/gtest.h>

#include "harness/cli/progress_estimate.h"

namespace tb::cli {
namespace {

TEST(ProgressEstimate, ExtrapolatesFromFinishedSteps) {
  double now = 100;
  ProgressEstimate estimate([&] { return now; });
  EXPECT_EQ(estimate.remainingText(1, 10), "estimating…") << "nothing finished yet";
  now = 110;
  // Step 3 started: 2 finished in 10 s, 8 to go (the one started included) at 5 s each.
  EXPECT_DOUBLE_EQ(estimate.remainingSeconds(3, 10), 40);
  EXPECT_EQ(estimate.remainingText(3, 10), "~40s left");
  now = 100.5;
  EXPECT_LT(estimate.remainingSeconds(3, 10), 0) << "under a second: no estimate";
  now = 400;
  EXPECT_EQ(estimate.remainingText(4, 10), "~11m40s left");  // 300 s / 3 × 7
  EXPECT_EQ(estimate.remainingText(10, 10), "last step");
}

// The default run's 572 steps: its first steps (device set-up, shader compilation, the
// techniques' default variants) made the first estimate 4.8x too long; none is shown before
// 29 steps (5 %) have finished.
TEST(ProgressEstimate, WaitsForOneTwentiethOfTheSteps) {
  double now = 0;
  ProgressEstimate estimate([&] { return now; });
  now = 10;
  EXPECT_LT(estimate.remainingSeconds(29, 572), 0) << "28 finished: too few to go by";
  EXPECT_DOUBLE_EQ(estimate.remainingSeconds(30, 572), 10.0 / 29 * 543);
}

TEST(ProgressEstimate, FormatsDurations) {
  EXPECT_EQ(formatDuration(0), "0s");
  EXPECT_EQ(formatDuration(41.2), "42s");
  EXPECT_EQ(formatDuration(185), "3m05s");
  EXPECT_EQ(formatDuration(3720), "1h02m");
}

}  // namespace
}  // namespace tb::cli
