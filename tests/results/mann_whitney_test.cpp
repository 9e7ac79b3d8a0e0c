// The Mann–Whitney U test against scipy.stats.mannwhitneyu(x, y, alternative="two-sided")
// with its defaults (method "auto", use_continuity True): SciPy 1.10.1 (Debian
// python3-scipy 1.10.1-2), the function Google Benchmark's compare.py calls. The reference
// p-values below were printed by that SciPy for these exact samples; tolerance 1e-12
// relative. tests/results/mann_whitney_scipy_check.py repeats the check against the SciPy
// installed at test time (ctest MannWhitney.MatchesInstalledScipy).
#include "harness/results/mann_whitney.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tb {
namespace {

struct ScipyCase {
  const char* name;
  std::vector<double> x, y;
  double u1, p;  // scipy's statistic (U of x) and p-value
  bool exact;    // the method scipy's "auto" chose
};

std::vector<double> affine(int n, double scale, double offset) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(i * scale + offset);
  return v;
}

std::vector<double> modular(int n, long multiplier, long modulus, double offset) {
  std::vector<double> v;
  for (long i = 0; i < n; ++i) v.push_back(double((i * multiplier) % modulus) / 10.0 + offset);
  return v;
}

std::vector<ScipyCase> scipyCases() {
  return {
      {"exact 3v3 disjoint", {1, 2, 3}, {4, 5, 6}, 0, 0.1, true},
      {"exact 5v5 disjoint",
       {1.0, 1.1, 1.2, 1.3, 1.4},
       {2.0, 2.1, 2.2, 2.3, 2.4},
       0,
       0.007936507936507936,
       true},
      {"exact 5v5 interleaved",
       {1.0, 1.2, 1.4, 1.6, 1.8},
       {1.1, 1.3, 1.5, 1.7, 1.9},
       10,
       0.6904761904761905,
       true},
      {"exact 4v6",
       {0.31, 0.27, 0.45, 0.12},
       {0.5, 0.61, 0.22, 0.9, 0.77, 0.43},
       4,
       0.11428571428571428,
       true},
      {"exact 2v2", {1, 2}, {3, 4}, 0, 0.3333333333333333, true},
      {"exact 8v20, one side small",
       {3.1, 2.7, 4.5, 1.2, 5.0, 6.1, 2.2, 0.9},
       affine(20, 0.37, 0.05),
       74,
       0.7841504711069929,
       true},
      {"asymptotic 9v9 no ties", affine(9, 1.3, 0), affine(9, 1.1, 2.05), 32, 0.47992869214595724,
       false},
      {"asymptotic 5v5 ties", {1, 2, 2, 3, 4}, {2, 3, 3, 5, 6}, 6, 0.19882894401644247, false},
      {"asymptotic 12v10 ties",
       {1, 1, 2, 3, 5, 8, 13, 21, 34, 55, 89, 144},
       {2, 3, 3, 4, 5, 6, 7, 8, 9, 10},
       74.5,
       0.35484901147682846,
       false},
      {"asymptotic 30v30 shifted", modular(30, 7919, 101, 0), modular(30, 104729, 103, 1.5), 333,
       0.08497370673578393, false},
  };
}

TEST(MannWhitney, MatchesScipyOnExactAndAsymptoticCases) {
  for (const ScipyCase& c : scipyCases()) {
    const results::MannWhitneyResult r = results::mannWhitneyU(c.x, c.y);
    EXPECT_DOUBLE_EQ(r.u1, c.u1) << c.name;
    EXPECT_NEAR(r.p_value, c.p, 1e-12 * c.p) << c.name;
    EXPECT_EQ(r.exact, c.exact) << c.name;
  }
}

// The exact null distribution, against counts summed by hand: for 2 against 2 the six
// placements give U = 0, 1, 2, 2, 3, 4, so P(U ≥ 2) = 4/6 and P(U ≥ 4) = 1/6. It is
// symmetric in the sample sizes and in U ↔ n1 n2 − U.
TEST(MannWhitney, ExactDistributionAgainstEnumeration) {
  EXPECT_DOUBLE_EQ(results::mannWhitneyExactSf(2, 2, 2), 4.0 / 6);
  EXPECT_DOUBLE_EQ(results::mannWhitneyExactSf(4, 2, 2), 1.0 / 6);
  EXPECT_DOUBLE_EQ(results::mannWhitneyExactSf(0, 3, 5), 1.0);
  EXPECT_DOUBLE_EQ(results::mannWhitneyExactSf(16, 3, 5), 0.0);
  EXPECT_DOUBLE_EQ(results::mannWhitneyExactSf(15, 3, 5), 1.0 / 56);  // C(8, 3) placements
  for (size_t u = 0; u <= 24; ++u) {
    EXPECT_NEAR(results::mannWhitneyExactSf(u, 4, 6), results::mannWhitneyExactSf(u, 6, 4), 1e-15)
        << u;
    // P(U ≥ u) = P(U ≤ 24 − u) = 1 − P(U ≥ 25 − u)
    EXPECT_NEAR(results::mannWhitneyExactSf(u, 4, 6), 1 - results::mannWhitneyExactSf(25 - u, 4, 6),
                1e-14)
        << u;
  }
}

// The test is symmetric in its samples, and every value equal is no evidence: p = 1.
TEST(MannWhitney, SymmetricAndAllEqualIsOne) {
  for (const ScipyCase& c : scipyCases()) {
    EXPECT_NEAR(results::mannWhitneyU(c.y, c.x).p_value, c.p, 1e-12 * c.p) << c.name;
  }
  EXPECT_EQ(results::mannWhitneyU({1, 1, 1}, {1, 1, 1, 1}).p_value, 1.0);
  EXPECT_EQ(results::mannWhitneyU({2}, {2}).p_value, 1.0);
}

}  // namespace
}  // namespace tb
