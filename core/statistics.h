// Statistics of lists of numbers, in one place: order statistics (the median of a job's
// repeated method times, the quantiles of the report's summary tables) and the paired
// comparison of two methods on the same jobs (win/tie/loss counts with the metrics' error
// bounds, and the Wilcoxon signed-rank test) that the report's leaderboard shows.
#pragma once

#include <cstddef>
#include <vector>

namespace holebench {

/// The median of `values` (the mean of the two middle ones for an even count); 0 if empty.
double median_of(std::vector<double> values);

/// The p-quantile (p in [0, 1]) of `sorted` (ascending, not empty), linearly interpolated
/// between the two nearest ranks.
double quantile(const std::vector<double>& sorted, double p);

struct SignedRankOptions {
  /// Up to this many non-zero differences the p-value comes from the exact distribution of
  /// the statistic (all 2^n sign patterns, midranks for tied magnitudes); above it from the
  /// normal approximation.
  std::size_t max_exact_n = 25;
};

/// The Wilcoxon signed-rank test of the hypothesis that paired differences are symmetric
/// about 0.
struct SignedRankTest {
  std::size_t n = 0;      ///< non-zero differences (the ones ranked)
  std::size_t zeros = 0;  ///< differences equal to 0, dropped before ranking (Wilcoxon's rule)
  double w_plus = 0.0;    ///< sum of the ranks of the positive differences
  double w_minus = 0.0;   ///< sum of the ranks of the negative differences
  double z = 0.0;         ///< (w_plus - n(n+1)/4) / sd, tie-corrected sd; 0 when n == 0
  double p_value = 1.0;   ///< two-sided; 1 when n == 0
  bool exact = false;     ///< p from the exact distribution (n <= max_exact_n)
};

/// Ranks |d| of the non-zero differences (midranks for ties), sums them by sign and gives a
/// two-sided p-value: exact for n <= options.max_exact_n (the conditional distribution given
/// the tied ranks, so ties are exact too), otherwise the normal approximation without
/// continuity correction and with the variance n(n+1)(2n+1)/24 - sum(t^3 - t)/48 over groups
/// of t tied magnitudes. The same numbers as scipy.stats.wilcoxon(d, zero_method="wilcox",
/// correction=False) with method="exact" (no ties) or "approx". Deterministic.
SignedRankTest wilcoxon_signed_rank(const std::vector<double>& differences,
                                    const SignedRankOptions& options = {});

/// A value with a guaranteed interval: lower <= true value <= upper, value in between (a
/// metric with its error bound; lower == value == upper for an exact one).
struct BoundedValue {
  double lower = 0.0;
  double value = 0.0;
  double upper = 0.0;
};

/// Two methods on the same jobs: how often the first one is better (lower is better).
struct PairedComparison {
  std::size_t wins = 0;    ///< the first interval lies wholly below the second
  std::size_t ties = 0;    ///< the intervals overlap: the order of the true values is unknown
  std::size_t losses = 0;  ///< the first interval lies wholly above the second
  /// On the differences first - second of the values, a tie counting as a difference of 0.
  SignedRankTest test;
};

/// Compares first[i] with second[i] for every i (the two lists are paired job by job; the
/// shorter length is used). Lower is better.
PairedComparison compare_paired(const std::vector<BoundedValue>& first,
                                const std::vector<BoundedValue>& second,
                                const SignedRankOptions& options = {});

}  // namespace holebench
