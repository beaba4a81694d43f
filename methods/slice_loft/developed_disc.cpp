#include "methods/slice_loft/developed_disc.h"

#include "core/polygon.h"

#include <algorithm>
#include <cmath>

namespace holebench::slice_loft {

DevelopedDisc develop_onto_disc(const std::vector<Point>& loop) {
  DevelopedDisc disc;
  const std::size_t n = loop.size();
  double length = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    length += (loop[(i + 1) % n] - loop[i]).norm();
  if (n == 0 || length <= 0.0)
    return disc;
  disc.radius = length / (2.0 * M_PI);
  double walked = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * M_PI * walked / length;
    disc.points.push_back({disc.radius * std::cos(angle), disc.radius * std::sin(angle)});
    walked += (loop[(i + 1) % n] - loop[i]).norm();
  }
  const double disc_area = M_PI * disc.radius * disc.radius;
  const double area = 0.5 * newell_normal(loop).norm();  // the loop's vector area
  disc.spacing_scale = area > 0.0 ? std::clamp(std::sqrt(disc_area / area), 1.0, 5.0) : 5.0;
  return disc;
}

std::vector<double> mean_value_coordinates(const std::vector<std::array<double, 2>>& polygon,
                                           std::array<double, 2> x) {
  const std::size_t n = polygon.size();
  std::vector<double> weights(n, 0.0);
  std::vector<double> radius(n), angle(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = polygon[i][0] - x[0], dy = polygon[i][1] - x[1];
    radius[i] = std::hypot(dx, dy);
    if (radius[i] < 1e-300) {  // x is a vertex
      weights[i] = 1.0;
      return weights;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {  // the angle at x from vertex i to vertex i + 1
    const std::size_t j = (i + 1) % n;
    const double ax = polygon[i][0] - x[0], ay = polygon[i][1] - x[1];
    const double bx = polygon[j][0] - x[0], by = polygon[j][1] - x[1];
    angle[i] = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t before = (i + n - 1) % n;
    weights[i] = (std::tan(0.5 * angle[before]) + std::tan(0.5 * angle[i])) / radius[i];
    sum += weights[i];
  }
  for (double& w : weights)
    w /= sum;
  return weights;
}

}  // namespace holebench::slice_loft
