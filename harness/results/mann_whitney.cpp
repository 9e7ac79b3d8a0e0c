#include "harness/results/mann_whitney.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace tb::results {
namespace {

// Mid-ranks (1-based) of the pooled sample x ++ y, and Σ (t³ − t) over its groups of t tied
// values (the tie term of the variance of U).
struct PooledRanks {
  std::vector<double> ranks;  // in pooled order: x first, then y
  double tie_term = 0;
  bool ties = false;
};

PooledRanks rankPooled(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> pooled(x);
  pooled.insert(pooled.end(), y.begin(), y.end());
  std::vector<size_t> order(pooled.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return pooled[a] < pooled[b]; });
  PooledRanks result;
  result.ranks.resize(pooled.size());
  for (size_t first = 0; first < order.size();) {
    size_t last = first + 1;
    while (last < order.size() && pooled[order[last]] == pooled[order[first]]) ++last;
    const double mid_rank = 0.5 * double(first + 1 + last);  // mean of ranks first+1 .. last
    for (size_t k = first; k < last; ++k) result.ranks[order[k]] = mid_rank;
    const double t = double(last - first);
    if (t > 1) {
      result.ties = true;
      result.tie_term += t * t * t - t;
    }
    first = last;
  }
  return result;
}

}  // namespace

double mannWhitneyExactSf(size_t u, size_t n1, size_t n2) {
  // Without ties, the placements of the first sample with U1 = u are in one-to-one
  // correspondence with the partitions of u into at most n1 parts, none above n2 (the
  // coefficients of the Gaussian binomial [n1 + n2, n1]_q). counts[i][s] holds the
  // partitions of s into at most i parts, none above j, raised one j at a time:
  // p(i, j, s) = p(i, j − 1, s) + p(i − 1, j, s − j), all sums of positive terms.
  if (n1 > n2) std::swap(n1, n2);
  const size_t max_u = n1 * n2;
  if (u == 0) return 1;
  if (u > max_u) return 0;
  std::vector<std::vector<double>> counts(n1 + 1, std::vector<double>(max_u + 1, 0.0));
  for (auto& row : counts) row[0] = 1;
  for (size_t j = 1; j <= n2; ++j) {
    for (size_t i = 1; i <= n1; ++i) {
      std::vector<double>& row = counts[i];
      const std::vector<double>& fewer = counts[i - 1];
      const size_t top = i * j;  // largest sum with i parts of at most j
      for (size_t s = top; s >= j; --s) row[s] += fewer[s - j];
    }
  }
  const std::vector<double>& all = counts[n1];
  double total = 0, tail = 0;
  for (size_t s = 0; s <= max_u; ++s) {
    total += all[s];
    if (s >= u) tail += all[s];
  }
  return tail / total;
}

MannWhitneyResult mannWhitneyU(const std::vector<double>& x, const std::vector<double>& y) {
  assert(!x.empty() && !y.empty());
  const double n1 = double(x.size()), n2 = double(y.size());
  const PooledRanks ranked = rankPooled(x, y);
  const double r1 = std::accumulate(ranked.ranks.begin(), ranked.ranks.begin() + x.size(), 0.0);
  MannWhitneyResult result;
  result.u1 = r1 - n1 * (n1 + 1) / 2;
  const double u = std::max(result.u1, n1 * n2 - result.u1);  // the larger of U1 and U2
  result.exact = (x.size() <= 8 || y.size() <= 8) && !ranked.ties;
  if (result.exact) {
    result.p_value = 2 * mannWhitneyExactSf(size_t(std::lround(u)), x.size(), y.size());
  } else {
    const double n = n1 + n2;
    const double variance = n1 * n2 / 12 * ((n + 1) - ranked.tie_term / (n * (n - 1)));
    if (!(variance > 0)) return result;  // every value equal: p = 1
    const double z = (u - n1 * n2 / 2 - 0.5) / std::sqrt(variance);
    result.p_value = std::erfc(z / std::sqrt(2.0));  // 2 × the normal survival function at z
  }
  result.p_value = std::clamp(result.p_value, 0.0, 1.0);
  return result;
}

}  // namespace tb::results
