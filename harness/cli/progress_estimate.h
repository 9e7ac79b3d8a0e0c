// The time a run has left, estimated from the steps done so far: elapsed / done × (total −
// done). Steps (technique × variant × asset groups) differ in cost, so early estimates
// swing; an estimate is shown only once 5 % of the steps (at least one) have finished and a
// second has passed.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace tb::cli {

class ProgressEstimate {
 public:
  // `now` returns seconds on a steady clock; the default reads std::chrono::steady_clock.
  explicit ProgressEstimate(std::function<double()> now = steadySeconds);

  // Seconds left after `done` of `total` steps; negative while there is nothing to go by.
  double remainingSeconds(size_t done, size_t total) const;
  // "~1m20s left", "~12s left", "estimating…", or "done".
  std::string remainingText(size_t done, size_t total) const;

  static double steadySeconds();

 private:
  std::function<double()> now_;
  double start_;
};

// "1h02m", "3m05s", "42s": whole seconds, rounded up.
std::string formatDuration(double seconds);

}  // namespace tb::cli
