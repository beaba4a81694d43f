// Tests of core/statistics: the median, the interpolated quantile, the Wilcoxon signed-rank
// test and the paired win/tie/loss comparison with error bounds. Expected p-values are worked
// out by hand below, or are scipy 1.10's (Debian python3-scipy), as noted at each.
#include "core/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

namespace holebench {
namespace {

TEST(Statistics, MedianOfOddAndEvenCounts) {
  EXPECT_EQ(median_of({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(median_of({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_EQ(median_of({7.0}), 7.0);
  EXPECT_EQ(median_of({}), 0.0);
}

TEST(Statistics, QuantileInterpolatesBetweenRanks) {
  const std::vector<double> sorted{1.0, 2.0, 4.0, 8.0};
  EXPECT_EQ(quantile(sorted, 0.0), 1.0);
  EXPECT_EQ(quantile(sorted, 1.0), 8.0);
  EXPECT_DOUBLE_EQ(quantile(sorted, 0.5), 3.0);  // between ranks 1 and 2
  EXPECT_DOUBLE_EQ(quantile(sorted, 0.25), 1.75);
  EXPECT_EQ(quantile({5.0}, 0.9), 5.0);
}

// Five positive differences: W+ = 1+2+3+4+5 = 15, W- = 0. Of the 2^5 = 32 sign patterns only
// "all positive" reaches 15 (and only "all negative" 0), so p = 2 * 1/32 = 0.0625.
TEST(Statistics, SignedRankExactAllPositive) {
  const auto test = wilcoxon_signed_rank({0.5, 1.0, 2.0, 3.0, 4.0});
  EXPECT_EQ(test.n, 5u);
  EXPECT_EQ(test.w_plus, 15.0);
  EXPECT_EQ(test.w_minus, 0.0);
  EXPECT_TRUE(test.exact);
  EXPECT_DOUBLE_EQ(test.p_value, 0.0625);
}

// Zeros are dropped: {0, 0, -1, 2, 3} ranks 1, 2, 3 with signs -, +, +: W+ = 5, W- = 1. The
// eight sign patterns of ranks {1, 2, 3} give W+ = 0, 1, 2, 3, 3, 4, 5, 6: P(W+ >= 5) = 2/8,
// so p = 2 * 0.25 = 0.5.
TEST(Statistics, SignedRankDropsZeros) {
  const auto test = wilcoxon_signed_rank({0.0, 0.0, -1.0, 2.0, 3.0});
  EXPECT_EQ(test.zeros, 2u);
  EXPECT_EQ(test.n, 3u);
  EXPECT_EQ(test.w_plus, 5.0);
  EXPECT_EQ(test.w_minus, 1.0);
  EXPECT_DOUBLE_EQ(test.p_value, 0.5);
}

// Tied magnitudes share their midrank: {1, 1, -1, 2}: |d| = 1 three times at ranks 1..3
// (midrank 2), |d| = 2 rank 4; W+ = 2 + 2 + 4 = 8, W- = 2. Exactly, over 16 sign patterns:
// W+ = 2k + 4e for k of the three 2s and e in {0, 1}; W+ >= 8 needs e = 1 and k >= 2:
// C(3,2) + C(3,3) = 4 patterns, so p = 2 * 4/16 = 0.5.
TEST(Statistics, SignedRankExactWithTiedMagnitudes) {
  const auto test = wilcoxon_signed_rank({1.0, 1.0, -1.0, 2.0});
  EXPECT_EQ(test.w_plus, 8.0);
  EXPECT_EQ(test.w_minus, 2.0);
  EXPECT_TRUE(test.exact);
  EXPECT_DOUBLE_EQ(test.p_value, 0.5);
}

// Mixed signs, no ties, n = 12: scipy.stats.wilcoxon(d, method="exact") gives statistic
// min(W+, W-) = 12 and p = 0.0341796875 (= 70/2048).
TEST(Statistics, SignedRankExactMatchesScipy) {
  const auto test =
      wilcoxon_signed_rank({1.5, -0.25, 3.0, 4.5, -2.0, 6.0, 7.25, -8.0, 9.0, 10.0, 11.5, 12.0});
  EXPECT_EQ(test.w_minus, 12.0);  // ranks of -0.25, -2, -8: 1 + 3 + 8
  EXPECT_TRUE(test.exact);
  EXPECT_NEAR(test.p_value, 0.0341796875, 1e-12);
}

// n = 30 > 25: the normal approximation. 1..30 all positive: W+ = 465, mean 232.5, variance
// 30*31*61/24 = 2363.75, z = 4.7822; scipy.stats.wilcoxon(d, method="approx",
// correction=False): p = 1.7343976283205784e-06.
TEST(Statistics, SignedRankNormalApproximation) {
  std::vector<double> d;
  for (int i = 1; i <= 30; ++i)
    d.push_back(i);
  const auto test = wilcoxon_signed_rank(d);
  EXPECT_FALSE(test.exact);
  EXPECT_EQ(test.w_plus, 465.0);
  EXPECT_NEAR(test.z, 232.5 / std::sqrt(2363.75), 1e-12);
  EXPECT_NEAR(test.p_value, 1.7343976283205784e-06, 1e-15);
}

// Ties and zeros with the normal approximation: d_i = ((7i mod 11) - 3) / 2 for i = 0..39
// (4 zeros, 25 positive, 11 negative, many tied magnitudes). scipy.stats.wilcoxon(d,
// zero_method="wilcox", correction=False, method="approx"): statistic 117.5 (= W-), p =
// 0.0006822921373787613.
TEST(Statistics, SignedRankNormalApproximationWithTiesAndZeros) {
  std::vector<double> d;
  for (int i = 0; i < 40; ++i)
    d.push_back(((i * 7) % 11 - 3) * 0.5);
  const auto test = wilcoxon_signed_rank(d);
  EXPECT_EQ(test.zeros, 4u);
  EXPECT_EQ(test.n, 36u);
  EXPECT_EQ(test.w_minus, 117.5);
  EXPECT_EQ(test.w_plus + test.w_minus, 36.0 * 37.0 / 2.0);  // ranks 1..n in all
  EXPECT_NEAR(test.p_value, 0.0006822921373787613, 1e-12);
}

TEST(Statistics, SignedRankOfNothingIsNotSignificant) {
  const auto test = wilcoxon_signed_rank({0.0, 0.0});
  EXPECT_EQ(test.n, 0u);
  EXPECT_EQ(test.p_value, 1.0);
}

// Intervals {lower, value, upper}: disjoint ones are ordered (lower is better), overlapping ones
// tie. Pairs: [1,2] vs [3,4] win; [5,6] vs [1,2] loss; [1,3] vs [2,4] tie (overlap);
// [1,1] vs [1,1] tie. The test sees differences -2, +4, 0, 0: W+ = 2, W- = 1 (n = 2).
TEST(Statistics, PairedComparisonCountsOverlapsAsTies) {
  const std::vector<BoundedValue> a{{1, 1, 2}, {5, 5, 6}, {1, 1, 3}, {1, 1, 1}};
  const std::vector<BoundedValue> b{{3, 3, 4}, {1, 1, 2}, {2, 2, 4}, {1, 1, 1}};
  const auto result = compare_paired(a, b);
  EXPECT_EQ(result.wins, 1u);
  EXPECT_EQ(result.losses, 1u);
  EXPECT_EQ(result.ties, 2u);
  EXPECT_EQ(result.test.zeros, 2u);
  EXPECT_EQ(result.test.n, 2u);
  EXPECT_EQ(result.test.w_plus, 2.0);
  EXPECT_EQ(result.test.w_minus, 1.0);
  // Swapping the sides swaps wins and losses and keeps the two-sided p-value.
  const auto swapped = compare_paired(b, a);
  EXPECT_EQ(swapped.wins, result.losses);
  EXPECT_EQ(swapped.losses, result.wins);
  EXPECT_EQ(swapped.test.p_value, result.test.p_value);
}

}  // namespace
}  // namespace holebench
