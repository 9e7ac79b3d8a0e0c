"""Holds tessbench's Mann-Whitney U test (harness/results/mann_whitney.cpp, through
mann_whitney_tool) against scipy.stats.mannwhitneyu(x, y, alternative="two-sided") with its
defaults, the call Google Benchmark's compare.py makes, on seeded random samples: sizes 2 to
40 on each side, with and without ties (values rounded to a grid), so both the exact and the
asymptotic method are exercised. Tolerance: 1e-9 relative on p (absolute below 1e-300)."""
import random
import subprocess
import sys

from scipy.stats import mannwhitneyu

tool = sys.argv[1]
rng = random.Random(20240611)
cases = []
for _ in range(400):
    n1, n2 = rng.randint(1, 40), rng.randint(2, 40)
    if rng.random() < 0.5:
        n1 = rng.randint(1, 8)  # the exact method unless ties
    shift = rng.choice([0.0, 0.3, 1.0, 3.0])
    grid = rng.choice([None, None, 0.5, 0.1])  # rounded: ties
    def draw(n, offset):
        values = [rng.gauss(offset, 1.0) for _ in range(n)]
        return [round(v / grid) * grid for v in values] if grid else values
    x, y = draw(n1, 0.0), draw(n2, shift)
    if len(set(x + y)) == 1:
        continue  # scipy's p is NaN there (zero variance); ours is 1 (tested in C++)
    cases.append((x, y))

text = "".join(" ".join(repr(v) for v in x) + " | " + " ".join(repr(v) for v in y) + "\n"
               for x, y in cases)
out = subprocess.run([tool], input=text, capture_output=True, text=True, check=True).stdout
failures = 0
exact_count = 0
for (x, y), line in zip(cases, out.splitlines(), strict=True):
    u1, p, exact = line.split()
    u1, p = float(u1), float(p)
    exact_count += exact == "1"
    ref = mannwhitneyu(x, y, alternative="two-sided")
    if abs(u1 - ref.statistic) > 1e-9 or abs(p - ref.pvalue) > 1e-9 * max(ref.pvalue, 1e-300):
        failures += 1
        print(f"MISMATCH n={len(x)},{len(y)}: ours U1={u1} p={p!r}, scipy U1={ref.statistic} "
              f"p={ref.pvalue!r}")
print(f"{len(cases)} cases ({exact_count} exact), {failures} mismatches against scipy "
      f"{__import__('scipy').__version__}")
sys.exit(1 if failures else 0)
