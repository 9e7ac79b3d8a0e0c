#include "harness/cli/progress_estimate.h"

#include <fmt/format.h>

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
  const double elapsed = now_() - start_;
  // `done` counts steps started; the one just started has not run yet.
  const size_t finished = done > 0 ? done - 1 : 0;
  if (finished == 0 || elapsed < kMinimumElapsedSeconds || total < done) return -1;
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
