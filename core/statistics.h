// Order statistics of a list of numbers: the median (a job's repeated method times) and
// quantiles (the report's summary tables), in one place.
#pragma once

#include <vector>

namespace holebench {

/// The median of `values` (the mean of the two middle ones for an even count); 0 if empty.
double median_of(std::vector<double> values);

/// The p-quantile (p in [0, 1]) of `sorted` (ascending, not empty), linearly interpolated
/// between the two nearest ranks.
double quantile(const std::vector<double>& sorted, double p);

}  // namespace holebench
