#include "harness/render/snapshot.h"

#include "core/geometry.h"
#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <cmath>

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

Image render_snapshot(const Mesh& mesh, const Camera& camera, const SnapshotOptions& options) {
  const embree::TriangleScene scene(mesh);
  Image image(options.width, options.height);
  const Point forward = camera.direction / camera.direction.norm();
  // A right/up frame; "up" is +z unless the camera looks along z.
  Point up_hint = std::abs(forward[2]) < 0.95 ? Point(0, 0, 1) : Point(0, 1, 0);
  Point right = OpenMesh::cross(forward, up_hint);
  right /= right.norm();
  const Point up = OpenMesh::cross(right, forward);
  const Point eye = camera.target - forward * camera.distance;
  const double half_height = std::tan(0.5 * camera.field_of_view_degrees * M_PI / 180.0);
  const double half_width = half_height * options.width / options.height;
  const int n = std::max(1, options.samples_per_axis);

  for (int y = 0; y < options.height; ++y) {
    for (int x = 0; x < options.width; ++x) {
      Rgb sum;
      for (int sy = 0; sy < n; ++sy) {
        for (int sx = 0; sx < n; ++sx) {
          const double u = ((x + (sx + 0.5) / n) / options.width * 2.0 - 1.0) * half_width;
          const double v = (1.0 - (y + (sy + 0.5) / n) / options.height * 2.0) * half_height;
          const Point direction = forward + right * u + up * v;
          const auto hit = scene.intersect(eye, direction);
          Rgb colour;
          if (!hit.hit) {
            // A soft vertical gradient as background.
            const float t = static_cast<float>(0.5 + 0.5 * v / half_height);
            colour = {0.93f - 0.12f * t, 0.94f - 0.10f * t, 0.96f - 0.05f * t};
          } else {
            const FaceHandle f = mesh.face_handle(hit.face);
            const double facing = -OpenMesh::dot(hit.normal, direction / direction.norm());
            const float light = static_cast<float>(0.25 + 0.75 * std::abs(facing));
            Rgb base = is_new(mesh, f) ? patch_colour() : region_colour(region(mesh, f));
            if (facing < 0.0)
              base = {0.35f, 0.08f, 0.12f};  // the inside, seen through a hole
            colour = {base.r * light, base.g * light, base.b * light};
          }
          sum.r += colour.r;
          sum.g += colour.g;
          sum.b += colour.b;
        }
      }
      const float w = 1.0f / static_cast<float>(n * n);
      image.set(x, y, {sum.r * w, sum.g * w, sum.b * w});
    }
  }
  return image;
}

}  // namespace holebench::render
