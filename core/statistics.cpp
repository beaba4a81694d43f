#include "core/statistics.h"

#include <algorithm>
#include <cmath>

namespace holebench {

double median_of(std::vector<double> values) {
  if (values.empty())
    return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double quantile(const std::vector<double>& sorted, double p) {
  const double position = p * static_cast<double>(sorted.size() - 1);
  const auto lower = static_cast<std::size_t>(std::floor(position));
  const std::size_t upper = std::min(lower + 1, sorted.size() - 1);
  const double t = position - static_cast<double>(lower);
  return sorted[lower] + t * (sorted[upper] - sorted[lower]);
}

}  // namespace holebench
