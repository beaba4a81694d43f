// Tests of core/statistics: the median and the interpolated quantile.
#include "core/statistics.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace holebench
