// Reads cases from stdin, one per line: the first sample, "|", the second (numbers separated
// by spaces), and prints per line U1, the two-sided p-value and 1/0 for the exact method,
// for tests/results/mann_whitney_scipy_check.py to hold against the installed SciPy.
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "harness/results/mann_whitney.h"

int main() {
  std::string line;
  while (std::getline(std::cin, line)) {
    std::vector<double> samples[2];
    int side = 0;
    std::istringstream words(line);
    for (std::string word; words >> word;) {
      if (word == "|") {
        side = 1;
      } else {
        samples[side].push_back(std::stod(word));
      }
    }
    if (samples[0].empty() || samples[1].empty()) return 2;
    const tb::results::MannWhitneyResult r = tb::results::mannWhitneyU(samples[0], samples[1]);
    std::printf("%.17g %.17g %d\n", r.u1, r.p_value, r.exact ? 1 : 0);
  }
  return 0;
}
