#include "harness/cli/progress_estimate.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace tb::cli {

ProgressEstimate::ProgressEstimate(std::function<double()> now)
    : now_(std::move(now)), start_(now_()) {}

double ProgressEstimate::steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double ProgressEstimate::remainingSeconds(size_t done, size_t total) const {
  constexpr double kMinimumElapsedSeconds = 1.0;
  constexpr size_t kStepsPerEstimateFraction = 20;  // the estimate waits for 1/20 of the steps
  const double elapsed = now_() - start_;
  // `done` counts steps started; the one just started has not run yet.
  const size_t finished = done > 0 ? done - 1 : 0;
  // The first steps carry the run's fixed costs (device set-up, shader compilation) and a
  // technique's default variant costs several times its others, so an estimate from a handful
  // of steps ran 4.8x long on the default run (21 min for 4.4). Waiting for 5 % of the steps,
  // with the groups spread over the run (suite.cpp planGroups), the first estimate read 1.4x
  // the time left, and later ones 0.45x to 1.1x.
  const size_t enough =
      std::max<size_t>(1, (total + kStepsPerEstimateFraction - 1) / kStepsPerEstimateFraction);
  if (finished < enough || elapsed < kMinimumElapsedSeconds || total < done) return -1;
  return elapsed / static_cast<double>(finished) * static_cast<double>(total - finished);
}

std::string ProgressEstimate::remainingText(size_t done, size_t total) const {
  if (done >= total && total > 0) return "last step";
  const double seconds = remainingSeconds(done, total);
  if (seconds < 0) return "estimating…";
  return fmt::format("~{} left", formatDuration(seconds));
}

std::string formatDuration(double seconds) {
  const long whole = static_cast<long>(std::ceil(std::max(0.0, seconds)));
  if (whole >= 3600) return fmt::format("{}h{:02}m", whole / 3600, (whole % 3600) / 60);
  if (whole >= 60) return fmt::format("{}m{:02}s", whole / 60, whole % 60);
  return fmt::format("{}s", whole);
}

}  // namespace tb::cli
