#include "harness/outputs/render/snapshot.h"

#include "core/geometry.h"
#include "harness/outputs/render/ray_view.h"
#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace holebench::render {

Rgb region_colour(int id) {
  if (id < 0)
    return {0.6f, 0.6f, 0.6f};
  // Golden-angle hues: neighbouring ids get clearly different colours.
  const float hue = std::fmod(0.12f + 0.618034f * static_cast<float>(id), 1.0f) * 6.0f;
  const float x = 1.0f - std::abs(std::fmod(hue, 2.0f) - 1.0f);
  Rgb c;
  switch (static_cast<int>(hue)) {
    case 0:
      c = {1, x, 0};
      break;
    case 1:
      c = {x, 1, 0};
      break;
    case 2:
      c = {0, 1, x};
      break;
    case 3:
      c = {0, x, 1};
      break;
    case 4:
      c = {x, 0, 1};
      break;
    default:
      c = {1, 0, x};
      break;
  }
  // Pastel: mix with white so that shading stays readable.
  return {0.35f + 0.55f * c.r, 0.35f + 0.55f * c.g, 0.35f + 0.55f * c.b};
}

Rgb patch_colour() {
  return {1.0f, 0.42f, 0.05f};
}

Camera frame_sphere(const Point& target, double radius, const Point& direction,
                    double field_of_view_degrees) {
  Camera camera;
  camera.target = target;
  camera.direction = direction / direction.norm();
  camera.field_of_view_degrees = field_of_view_degrees;
  camera.distance = 1.05 * radius / std::sin(0.5 * field_of_view_degrees * M_PI / 180.0);
  return camera;
}

TriangleSoup arrow_solid(const Point& from, const Point& to, double radius, int segments) {
  const Point axis = to - from;
  const double length = axis.norm();
  const Point r = axis / length;
  // Two unit vectors across the axis.
  Point u = OpenMesh::cross(r, std::abs(r[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0));
  u /= u.norm();
  const Point v = OpenMesh::cross(r, u);
  // The profile (position along the axis, radius) from the tail's pole to the tip's.
  const double head = 0.25 * length;
  const std::vector<std::pair<double, double>> profile = {
      {0.0, radius}, {length - head, radius}, {length - head, 2.5 * radius}};
  TriangleSoup soup;
  soup.points.push_back(from);  // 0: the tail's pole
  for (const auto& [along, width] : profile) {
    for (int j = 0; j < segments; ++j) {
      const double angle = 2.0 * M_PI * j / segments;
      soup.points.push_back(from + r * along + (u * std::cos(angle) + v * std::sin(angle)) * width);
    }
  }
  const int tip = static_cast<int>(soup.points.size());
  soup.points.push_back(to);
  const auto ring = [segments](int k, int j) { return 1 + k * segments + (j % segments); };
  const int rings = static_cast<int>(profile.size());
  for (int j = 0; j < segments; ++j) {
    soup.triangles.push_back({0, ring(0, j + 1), ring(0, j)});  // the tail's cap
    for (int k = 0; k + 1 < rings; ++k) {
      soup.triangles.push_back({ring(k, j), ring(k, j + 1), ring(k + 1, j + 1)});
      soup.triangles.push_back({ring(k, j), ring(k + 1, j + 1), ring(k + 1, j)});
    }
    soup.triangles.push_back({ring(rings - 1, j), ring(rings - 1, j + 1), tip});  // the cone
  }
  return soup;
}

std::optional<Projection> project(const Camera& camera, int width, int height, const Point& p) {
  const View view(camera, width, height);
  Projection out;
  if (!view.project(p, out.x, out.y, out.depth))
    return std::nullopt;
  return out;
}

Point eye_of(const Camera& camera) {
  return camera.target - camera.direction / camera.direction.norm() * camera.distance;
}

PrimaryRays primary_rays(const Camera& camera, const SnapshotOptions& options) {
  const View view(camera, options.width, options.height);
  const int n = std::max(1, options.samples_per_axis);
  PrimaryRays rays{view.eye, {}};
  rays.directions.reserve(static_cast<std::size_t>(options.width) * options.height * n * n);
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x)
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx)
          rays.directions.push_back(view.ray(x + (sx + 0.5) / n, y + (sy + 0.5) / n));
  return rays;
}

Image render_snapshot(const Mesh& mesh, const Camera& camera, const SnapshotOptions& options,
                      const Overlay& overlay) {
  return render_with_depth(mesh, camera, options, overlay).image;
}

Rendering render_with_depth(const Mesh& mesh, const Camera& camera, const SnapshotOptions& options,
                            const Overlay& overlay) {
  const embree::TriangleScene scene(mesh);
  return render_with_depth(mesh, scene, camera, options, overlay);
}

Rendering render_with_depth(const Mesh& mesh, const embree::TriangleScene& scene,
                            const Camera& camera, const SnapshotOptions& options,
                            const Overlay& overlay) {
  const SolidScene solids = solid_scene(overlay);
  Image image(options.width, options.height);
  const View view(camera, options.width, options.height);
  const int n = std::max(1, options.samples_per_axis);
  std::vector<double> depth(static_cast<std::size_t>(options.width) * options.height,
                            std::numeric_limits<double>::infinity());

  // One row at a time: its rays (n x n per pixel) traced as one coherent stream.
  const std::size_t per_pixel = static_cast<std::size_t>(n) * n;
  std::vector<Point> directions;
  std::vector<embree::RayHit> hits, solid_hits;
  for (int y = 0; y < options.height; ++y) {
    row_directions(view, y, 0, options.width, n, directions);
    scene.intersect_coherent(view.eye, directions, hits);
    if (solids.scene)
      solids.scene->intersect_coherent(view.eye, directions, solid_hits);
    for (int x = 0; x < options.width; ++x) {
      Rgb sum;
      auto& d = depth[static_cast<std::size_t>(y) * options.width + x];
      for (std::size_t k = per_pixel * x; k < per_pixel * (x + 1); ++k) {
        const Point unit = directions[k] / directions[k].norm();
        const embree::RayHit& hit = hits[k];
        const embree::RayHit solid_hit = solids.scene ? solid_hits[k] : embree::RayHit{};
        Rgb colour;
        if (solid_hit.hit && (!hit.hit || solid_hit.distance < hit.distance)) {
          d = std::min(d, solid_hit.distance);
          colour = shade_solid_hit(solids, solid_hit, unit);
        } else if (!hit.hit) {
          colour = background_colour(y, options.height);
        } else {
          d = std::min(d, hit.distance);  // t along the unit ray: the distance
          colour = shade_mesh_hit(mesh, hit, unit, view.eye, options);
        }
        sum.r += colour.r;
        sum.g += colour.g;
        sum.b += colour.b;
      }
      const float w = 1.0f / static_cast<float>(n * n);
      image.set(x, y, {sum.r * w, sum.g * w, sum.b * w});
    }
  }
  draw_overlay(image, view, depth, 0.01 * camera.distance, overlay);
  return {std::move(image), std::move(depth)};
}

}  // namespace holebench::render
