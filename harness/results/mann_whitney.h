// The two-sided Mann–Whitney U test (Wilcoxon rank-sum), the test Google Benchmark's
// compare.py runs on repeated timings (scipy.stats.mannwhitneyu with its defaults). Used by
// `tessbench compare` on timings.json samples (compare.h); the deterministic figures are
// compared by thresholds instead.
#pragma once

#include <cstddef>
#include <vector>

namespace tb::results {

struct MannWhitneyResult {
  // U of the first sample: R1 − n1 (n1 + 1) / 2 with R1 the sum of its (mid-)ranks in the
  // pooled sample; 0 when every first value lies below every second, n1 n2 when above.
  double u1 = 0;
  // Two-sided p-value in [0, 1]: small when the two samples come from shifted
  // distributions. 1 when every value is equal (no evidence of a difference).
  double p_value = 1;
  bool exact = false;  // the exact distribution of U was used (else the normal approximation)
};

// Chooses the method as scipy.stats.mannwhitneyu(method="auto") does (scipy 1.10): the exact
// null distribution of U when either sample has at most 8 values and the pooled sample has no
// ties; otherwise the normal approximation with the tie correction of its variance and a
// continuity correction of 0.5. Two-sided: p = min(1, 2 P(U ≥ max(U1, U2))). Both samples
// must be non-empty (asserted); NaNs are not allowed.
MannWhitneyResult mannWhitneyU(const std::vector<double>& x, const std::vector<double>& y);

// P(U ≥ u) under the null hypothesis for samples of n1 and n2 values without ties: the
// number of ways to place n1 values among n1 + n2 with U ≥ u, over C(n1 + n2, n1).
double mannWhitneyExactSf(size_t u, size_t n1, size_t n2);

}  // namespace tb::results
