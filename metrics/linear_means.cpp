#include "metrics/linear_means.h"

#include <algorithm>
#include <functional>

namespace holebench {

double linear_mean(const std::array<double, 3>& v) {
  return (v[0] + v[1] + v[2]) / 3.0;
}

double linear_square_mean(const std::array<double, 3>& v) {
  return (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[0] * v[1] + v[1] * v[2] + v[2] * v[0]) / 6.0;
}

double positive_part_mean(std::array<double, 3> v, int power) {
  std::sort(v.begin(), v.end(), std::greater<>());
  if (v[2] >= 0.0)
    return power == 1 ? linear_mean(v) : linear_square_mean(v);
  if (v[0] <= 0.0)
    return 0.0;
  if (v[1] <= 0.0) {
    const double share = v[0] * v[0] / ((v[0] - v[1]) * (v[0] - v[2]));
    return share * (power == 1 ? v[0] / 3.0 : v[0] * v[0] / 6.0);
  }
  const double negative = positive_part_mean({-v[2], -v[1], -v[0]}, power);
  return std::max(0.0, power == 1 ? linear_mean(v) + negative : linear_square_mean(v) - negative);
}

double absolute_mean(const std::array<double, 3>& v) {
  return positive_part_mean(v, 1) + positive_part_mean({-v[0], -v[1], -v[2]}, 1);
}

}  // namespace holebench
