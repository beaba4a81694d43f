#include "core/polygon_2d.h"

#include <algorithm>
#include <cmath>

namespace holebench {

bool inside_polygon_2d(const std::vector<Point2d>& polygon, Point2d p) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point2d a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

double distance_to_polygon_2d(const std::vector<Point2d>& polygon, Point2d p) {
  double best = 1e300;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const double dx = polygon[i].x - polygon[j].x, dy = polygon[i].y - polygon[j].y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - polygon[j].x) * dx + (p.y - polygon[j].y) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    best = std::min(best, std::hypot(polygon[j].x + t * dx - p.x, polygon[j].y + t * dy - p.y));
  }
  return best;
}

double signed_area_2d(const std::vector<Point2d>& polygon) {
  double area = 0.0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    area += polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y;
  return 0.5 * area;
}

}  // namespace holebench
