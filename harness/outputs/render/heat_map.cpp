#include "harness/outputs/render/heat_map.h"

#include "core/geometry.h"
#include "harness/outputs/render/bitmap_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace holebench::render {
namespace {

/// 1, 2 or 5 times a power of ten, at least `value`.
double nice_ceiling(double value) {
  const double power = std::pow(10.0, std::floor(std::log10(value)));
  for (double step : {1.0, 2.0, 5.0, 10.0}) {
    if (step * power >= value * (1.0 - 1e-12))
      return step * power;
  }
  return 10.0 * power;
}

/// The largest distance from a vertex of the hole's removed faces to their centroid.
double hole_radius(const Mesh& complete, const HoleTruth& hole) {
  std::set<int> vertices;
  for (int index : hole.removed_faces) {
    for (auto v : complete.fv_range(complete.face_handle(index)))
      vertices.insert(v.idx());
  }
  if (vertices.empty())
    return 0.0;
  Point centroid(0, 0, 0);
  for (int v : vertices)
    centroid += complete.point(complete.vertex_handle(v));
  centroid /= static_cast<double>(vertices.size());
  double radius = 0.0;
  for (int v : vertices)
    radius = std::max(radius, (complete.point(complete.vertex_handle(v)) - centroid).norm());
  return radius;
}

}  // namespace

HeatScale case_heat_scale(const Case& c) {
  const double diagonal = bounding_box(c.complete).diagonal();
  double radius = 0.0;
  for (const auto& hole : c.holes)
    radius = std::max(radius, hole_radius(c.complete, hole));
  HeatScale scale;
  if (diagonal > 0.0 && radius > 0.0)
    scale.max_rel_diag = nice_ceiling(0.5 * radius / diagonal);
  return scale;
}

const std::vector<Rgb>& heat_stops() {
  static const std::vector<Rgb> stops = {
      {0.10f, 0.25f, 0.85f},  // blue: on the complete model
      {0.05f, 0.70f, 0.85f},  // cyan
      {0.30f, 0.80f, 0.25f},  // green
      {0.98f, 0.78f, 0.08f},  // yellow
      {0.85f, 0.08f, 0.06f},  // red: at the scale's maximum or beyond
  };
  return stops;
}

Rgb heat_colour(double distance_rel_diag, const HeatScale& scale) {
  const auto& stops = heat_stops();
  const double t = std::clamp(distance_rel_diag / scale.max_rel_diag, 0.0, 1.0);
  if (t >= 1.0)
    return stops.back();
  const double position = t * static_cast<double>(stops.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(position), stops.size() - 2);
  const float f = static_cast<float>(position - static_cast<double>(i));
  const Rgb& a = stops[i];
  const Rgb& b = stops[i + 1];
  return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f};
}

std::string heat_label(double value_rel_diag) {
  return value_rel_diag == 0.0 ? std::string("0") : fmt::format("{:.2g}", value_rel_diag);
}

Image colour_bar(const HeatScale& scale, int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      image.set(x, y, {1, 1, 1});
  }
  const TextOptions text;
  const int glyph_height = 7 * text.scale;
  const int top = glyph_height / 2 + 2;
  const int bottom = height - glyph_height / 2 - 3;
  const int bar_width = std::min(16, width / 4);
  for (int y = top; y <= bottom; ++y) {
    const double t = 1.0 - static_cast<double>(y - top) / std::max(1, bottom - top);
    const Rgb colour = heat_colour(t * scale.max_rel_diag, scale);
    for (int x = 2; x < 2 + bar_width; ++x)
      image.set(x, y, colour);
  }
  const int label_x = 2 + bar_width + 4;
  draw_text(image, label_x, top - glyph_height / 2, heat_label(scale.max_rel_diag), text);
  draw_text(image, label_x, (top + bottom) / 2 - glyph_height / 2,
            heat_label(0.5 * scale.max_rel_diag), text);
  draw_text(image, label_x, bottom - glyph_height / 2, "0", text);
  return image;
}

}  // namespace holebench::render
